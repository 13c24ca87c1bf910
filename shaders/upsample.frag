// The upsample (below full resolution): every viewport pixel takes the AO of
// the reduced grid's texels around it (the 3x3 blocks centred on its own),
// weighted by their distance on screen (a gaussian of half a block) and by
// depth similarity: a tap whose view z differs from the pixel's own (read
// from the full-resolution depth) by the blur's relative tolerance or more
// gets no weight, so AO is never carried across a silhouette. When no tap is
// within the tolerance (a feature thinner than a block), the tap nearest in
// depth is taken. Sky pixels are exactly 1.
//
// Variant UPSAMPLE_NEAREST (debug views RAW_AO and BLUR_WEIGHTS): a pixel
// takes the value of its own block's grid texel, no depth weights, so the
// view shows what the grid holds.

uniform sampler2D u_ao_tex;  // the grid's RG32F (ao, view z), sky = SKY_Z

out vec4 o_ao;

// The depth- and distance-weighted AO of the 3x3 grid texels around pixel p at view z z0.
float depth_weighted(ivec2 p, float z0) {
    // Floored as in the blur: an orthographic surface may sit at view z = 0.
    float tolerance = max(u_ao2.z * abs(z0), 1e-30);
    float sigma = 0.5 * float(u_scale);
    float inv2s2 = 0.5 / (sigma * sigma);
    ivec2 size = grid_size();
    ivec2 c = p / u_scale;
    float sum = 0.0, weight = 0.0;
    float nearest = 1.0, nearest_dz = 3.4e38;  // no surface tap at all: open
    for (int y = -1; y <= 1; ++y)
        for (int x = -1; x <= 1; ++x) {
            ivec2 t = c + ivec2(x, y);
            if (any(lessThan(t, ivec2(0))) || any(greaterThanEqual(t, size))) continue;
            vec2 tap = texelFetch(u_ao_tex, t, 0).rg;
            if (tap.g == SKY_Z) continue;
            float dz = abs(tap.g - z0);
            if (dz < nearest_dz) {
                nearest_dz = dz;
                nearest = tap.r;
            }
            vec2 off = vec2(grid_pixel(t) - p);
            float w = exp(-dot(off, off) * inv2s2) * clamp(1.0 - dz / tolerance, 0.0, 1.0);
            sum += tap.r * w;
            weight += w;
        }
    return weight > 0.0 ? sum / weight : nearest;
}

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy) - u_target_origin;
    float d = input_depth(p);
    vec3 P = view_position_at(vec2(p) + 0.5, d).xyz;
    if (is_sky(d) || !(all(lessThan(abs(P), vec3(3.0e38))) && !any(isnan(P)))) {
        o_ao = vec4(1.0);
        return;
    }
#ifdef SSAO_UPSAMPLE_NEAREST
    float ao = texelFetch(u_ao_tex, p / u_scale, 0).r;
#else
    float ao = depth_weighted(p, P.z);
#endif
    o_ao = vec4(ao, ao, ao, 1.0);
}
