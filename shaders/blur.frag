// Blur passes over the raw AO: the chapter's 4x4 box, or one direction of a
// separable gaussian, optionally depth-aware (depth_weight below: a tap off
// the surface at the centre gets no weight, so occlusion is not carried
// across silhouettes; sky taps never count). The view depth and the tangent
// plane come with the AO from the previous pass; the depth texture is not
// read.
//
// Variant BLUR_WEIGHTS (debug view SSAO_DEBUG_VIEW_BLUR_WEIGHTS) writes, in
// place of the blurred AO, the share of the pass's gaussian (box: uniform)
// weight that the depth test let through: sum(w * depth weight) / sum(w) over
// the taps the blur uses. Sky taps and taps beyond the border take no part in
// either sum (every blur skips them, depth test or not), so a blur that
// ignores depth gives exactly 1. The vertical pass of a separable blur reads
// the horizontal pass's share at its centre and multiplies it in: the view is
// the product of both passes' shares at the pixel.

uniform ivec2 u_blur_dir;       // (1,0) or (0,1); unused by the box
uniform ivec2 u_pass_size;      // the grid blurred: the viewport, or the reduced grid below full resolution
uniform bool u_depth_aware;     // below full resolution: every kind weighs taps by depth similarity

// The depth weight of a tap at view z tap_z, du viewport pixels from a centre
// at view z z0 whose tangent plane has the screen gradient g0: 1 on the
// centre's surface, falling linearly to 0 at the tolerance. With a plane
// (ao_texture.glsl) the tap is compared with the view z the plane puts under
// it, within kPlaneTolerance of the tolerance; without one (g0 = 0: a normal
// along the view axis, or none usable) with z0 itself, within the tolerance
// (consts.blur_depth_tolerance * |z0|).
float depth_weight(float tap_z, vec2 du, float z0, vec2 g0, float tolerance) {
    bool plane = any(notEqual(g0, vec2(0.0)));
    float expected = plane ? plane_z(z0, g0, du, consts.orthographic != 0) : z0;
    float within = plane ? max(kPlaneTolerance * tolerance, 1e-30) : tolerance;
    return clamp(1.0 - abs(tap_z - expected) / within, 0.0, 1.0);
}

void main() {
    ivec2 vpx = ivec2(gl_FragCoord.xy) - u_target_origin;
    ivec2 size = u_pass_size;
    int kind = consts.blur_kind;
    vec4 c = texelFetch(u_ao_tex, vpx, 0);
    float centre = c.r, z0 = c.g;
    vec2 g0 = c.ba;  // the centre's plane gradient, handed on to the upsample
    if (z0 == SKY_Z) { o_ao = result(1.0, SKY_Z); return; }  // the sky stays exactly 1
    // Floored: an orthographic camera whose near plane lies behind the eye
    // has surfaces at view z = 0, where 0/0 would be undefined.
    float tolerance = max(consts.blur_depth_tolerance * abs(z0), 1e-30);
    GridMap grid = grid_map();
    ivec2 u0 = grid_pixel(grid, vpx);  // tap offsets in viewport pixels: a grid texel spans several
    if (kind == SSAO_SHADER_BLUR_BOX) {
        // The chapter's blur: offsets -2..1 in x and y, clamped at the edges;
        // sky taps take no part in the average (the centre never is sky).
        // Depth-aware below full resolution: taps weighted as the
        // depth-aware gaussian weighs them (the centre always counts).
        float sum = 0.0, count = 0.0;
#ifdef SSAO_BLUR_WEIGHTS
        float taps = 0.0;
#endif
        for (int y = -2; y < 2; ++y)
            for (int x = -2; x < 2; ++x) {
                ivec2 t = clamp(vpx + ivec2(x, y), ivec2(0), size - 1);
                vec2 tap = texelFetch(u_ao_tex, t, 0).rg;
                if (tap.g == SKY_Z) continue;
                float w = u_depth_aware ? depth_weight(tap.g, vec2(grid_pixel(grid, t) - u0), z0, g0, tolerance) : 1.0;
                sum += tap.r * w;
                count += w;
#ifdef SSAO_BLUR_WEIGHTS
                taps += 1.0;
#endif
            }
#ifdef SSAO_BLUR_WEIGHTS
        o_ao = result(count / taps, z0, g0);
#else
        o_ao = result(sum / count, z0, g0);
#endif
        return;
    }
    bool aware = kind == SSAO_SHADER_BLUR_DEPTH_AWARE || u_depth_aware;
    float inv2s2 = 0.5 / (consts.blur_sigma * consts.blur_sigma);
    float sum = centre, weight = 1.0;
#ifdef SSAO_BLUR_WEIGHTS
    float gaussian = 1.0;  // the centre's weight, never rejected
#endif
    for (int k = -consts.blur_radius; k <= consts.blur_radius; ++k) {
        if (k == 0) continue;
        ivec2 t = vpx + u_blur_dir * k;
        if (any(lessThan(t, ivec2(0))) || any(greaterThanEqual(t, size))) continue;  // no clamped repeats at borders
        float w = exp(-float(k * k) * inv2s2);
        vec2 tap = texelFetch(u_ao_tex, t, 0).rg;
        if (tap.g == SKY_Z) continue;
#ifdef SSAO_BLUR_WEIGHTS
        gaussian += w;
#endif
        if (aware) w *= depth_weight(tap.g, vec2(grid_pixel(grid, t) - u0), z0, g0, tolerance);
        sum += tap.r * w;
        weight += w;
    }
#ifdef SSAO_BLUR_WEIGHTS
    // Same taps summed in the same order: exactly 1 when nothing was rejected.
    float before = u_blur_dir.y != 0 ? centre : 1.0;  // the horizontal pass's share
    o_ao = result(weight / gaussian * before, z0, g0);
#else
    o_ao = result(sum / weight, z0, g0);
#endif
}
