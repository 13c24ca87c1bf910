// The upsample (below full resolution): every viewport pixel takes the AO of
// the 2x2 reduced-grid texels around it (the two nearest along each axis),
// weighted by where their picked pixels lie (a tent two blocks wide, so the
// four taps also average the grid's noise; floored so a tap is never ignored
// on position alone) and by depth similarity: a tap whose tangent plane (the
// plane texel's gradient, handed on with the AO: ao_texture.glsl) puts the
// surface under the pixel at a view z that differs from the pixel's own (read
// from the full-resolution depth) by kPlaneTolerance of the blur's relative
// tolerance or more gets no weight, so AO is carried neither across a
// silhouette nor between surfaces at different depths. When no tap is within
// the tolerance (a feature thinner than a block), the tap nearest in depth is
// taken. Sky pixels are exactly 1.
//
// Variant UPSAMPLE_PLANE_FIT (a moving frame index, plan.cpp says why): a
// weighted least-squares plane through the taps (the same weights; offsets
// in grid texels, its slope damped as the blur's line is), read at the
// pixel, in place of their weighted mean.
//
// Variant UPSAMPLE_NEAREST (debug views RAW_AO and BLUR_WEIGHTS): a pixel
// takes the value of its own block's grid texel, no depth weights, so the
// view shows what the grid holds.

#ifdef SSAO_UPSAMPLE_PLANE_FIT
// The weighted moments of the taps a plane fit needs, offsets k from the pixel in grid texels.
struct Moments {
    vec2 k;    // sum w k
    vec3 kk;   // sum w (kx kx, kx ky, ky ky)
    vec2 ka;   // sum w k ao
};

void add_moments(inout Moments m, float w, vec2 k, float ao) {
    m.k += w * k;
    m.kk += w * vec3(k.x * k.x, k.x * k.y, k.y * k.y);
    m.ka += w * k * ao;
}

// The fitted plane's value at the pixel (offset 0): the weighted mean moved
// along the slope from the taps' weighted centre. SSAO_BLUR_SLOPE_DAMPING
// on the diagonal keeps the slope small where the taps span little (two
// taps left by the depth test, or taps on a line).
float plane_at_pixel(Moments m, float sum, float weight) {
    float mean = sum / weight;
    vec2 km = m.k / weight;
    float cxx = m.kk.x / weight - km.x * km.x + SSAO_BLUR_SLOPE_DAMPING;
    float cxy = m.kk.y / weight - km.x * km.y;
    float cyy = m.kk.z / weight - km.y * km.y + SSAO_BLUR_SLOPE_DAMPING;
    vec2 cka = m.ka / weight - km * mean;
    vec2 slope = vec2(cyy * cka.x - cxy * cka.y, cxx * cka.y - cxy * cka.x) / (cxx * cyy - cxy * cxy);
    return clamp(mean - dot(km, slope), 0.0, 1.0);
}
#endif

// The depth-weighted AO of the 2x2 grid texels around pixel p at view z z0:
// their weighted mean, or the plane through them (UPSAMPLE_PLANE_FIT).
float depth_weighted(ivec2 p, float z0) {
    // Floored as in the blur: an orthographic surface may sit at view z = 0.
    float inv_tolerance = 1.0 / max(kPlaneTolerance * consts.blur_depth_tolerance * abs(z0), 1e-30);
    GridMap g = grid_map();
    bool ortho = consts.orthographic != 0;
    vec2 u = vec2(p) + 0.5;
    ivec2 last = grid_size() - 1;
    vec2 inv_size = inv_size_of(u_ao_tex);
    // The blocks whose centres bracket p: p's own and its neighbour on the
    // side of p's half of the block (exact in float for a power-of-two
    // scale), clamped into the grid: at the border a texel may be taken
    // twice, which keeps the result a weighted mean of the texels there.
    ivec2 t0 = ivec2(floor((vec2(p) + float(g.scale - (g.scale >> 1))) * g.inv_scale)) - 1;
    float sum = 0.0, weight = 0.0;
#ifdef SSAO_UPSAMPLE_PLANE_FIT
    Moments m = Moments(vec2(0.0), vec3(0.0), vec2(0.0));
#endif
    float nearest = 1.0, nearest_dz = 3.4e38;
    for (int k = 0; k < 4; ++k) {
        ivec2 t = clamp(t0 + ivec2(k & 1, k >> 1), ivec2(0), last);
        vec4 tap = owned_texel(u_ao_tex, t, inv_size);
        vec2 u0 = vec2(grid_pixel(g, t)) + 0.5;
        float zp = plane_z(tap.g, tap.ba, u - u0, ortho);  // the tap's tangent plane's view z under p
        // A sky tap (view z SKY_Z, AO 1) is never within the tolerance, and
        // the nearest in depth only when every tap is sky: then 1, open.
        float dz = abs(zp - z0);
        bool closer = dz < nearest_dz;
        nearest_dz = closer ? dz : nearest_dz;
        nearest = closer ? tap.r : nearest;
        vec2 tent = max(1.0 - abs(u0 - u) * (0.5 * g.inv_scale), vec2(0.0625));
        float w = tent.x * tent.y * clamp(1.0 - dz * inv_tolerance, 0.0, 1.0);
        sum += tap.r * w;
        weight += w;
#ifdef SSAO_UPSAMPLE_PLANE_FIT
        add_moments(m, w, (u0 - u) * g.inv_scale, tap.r);
#endif
    }
    if (!(weight > 0.0)) return nearest;
#ifdef SSAO_UPSAMPLE_PLANE_FIT
    return plane_at_pixel(m, sum, weight);
#else
    return weighted_mean(sum, weight);
#endif
}

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy) - u_target_origin;
    float d = input_depth(p);
    float z = view_z_of_depth(p, d);
    if (is_sky(d) || !(abs(z) < 3.0e38)) {
        o_ao = vec4(1.0);
        return;
    }
#ifdef SSAO_UPSAMPLE_NEAREST
    float ao = owned_texel(u_ao_tex, p >> scale_log2()).r;
#else
    // Beyond the distance fade's end the AO is exactly 1, as the sampling
    // pass makes it on the grid: a tap whose plane continues a receding
    // surface from before the fade's end would otherwise reach past it.
    float ao = consts.fade_end > 0.0 && -z >= consts.fade_end ? 1.0 : depth_weighted(p, z);
#endif
    o_ao = vec4(ao, ao, ao, 1.0);
}
