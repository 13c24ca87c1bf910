// Blur passes over the raw AO: the chapter's 4x4 box, or one direction of a
// separable gaussian, optionally depth-aware (depth_weight below: a tap off
// the surface at the centre gets no weight, so occlusion is not carried
// across silhouettes; sky taps never count). The view depth and the tangent
// plane come with the AO from the previous pass; the depth texture is not
// read.
//
// The depth-aware gaussian fits a line, not a constant: where the depth test
// leaves taps on one side only (a pixel on a crease line, beside a
// silhouette, at the border), a weighted mean of a sloping AO profile is the
// value some way into the surface, too light at a concave crease, where the
// AO is darkest at the centre. A weighted least-squares line through the taps,
// read at the centre, is exact for any linear profile and equals the weighted
// mean wherever the accepted taps are balanced around the centre. Its slope is
// damped (SSAO_BLUR_SLOPE_DAMPING is added to the taps' offset variance, in
// squared pass texels) so that two noisy taps on one side do not swing the
// result. The blurs that ignore depth (the box and the gaussian at full
// resolution) stay means.
//
// Variant BLUR_WEIGHTS (debug view SSAO_DEBUG_VIEW_BLUR_WEIGHTS) writes, in
// place of the blurred AO, the share of the pass's gaussian (box: uniform)
// weight that the depth test let through: sum(w * depth weight) / sum(w) over
// the taps the blur uses. Sky taps take no part in either sum (every blur
// skips them, depth test or not); beyond the border the gaussian skips taps
// and the box repeats the edge texel, in both sums alike. So a blur that
// ignores depth gives exactly 1. The vertical pass of a separable blur reads
// the horizontal pass's share at its centre and multiplies it in: the view is
// the product of both passes' shares at the pixel.

uniform ivec2 u_blur_dir;       // (1,0) or (0,1); unused by the box
uniform ivec2 u_pass_size;      // the grid blurred: the viewport, or the reduced grid below full resolution
uniform bool u_depth_aware;     // below full resolution: every kind weighs taps by depth similarity

const float kSlopeDamping = SSAO_BLUR_SLOPE_DAMPING;

// The depth weight of a tap at view z tap_z (its tangent plane's screen
// gradient g1), du viewport pixels from a centre at view z z0 whose tangent
// plane has the screen gradient g0: 1 on the centre's surface, falling
// linearly to 0 at the tolerance. With a plane (ao_texture.glsl) the tap is
// compared with the view z the plane puts under it, within kPlaneTolerance of
// the tolerance; without one (g0 = 0: a normal along the view axis, or none
// usable) with z0 itself, within the tolerance (consts.blur_depth_tolerance *
// |z0|).
//
// two_way (full resolution, both planes known): the tap's own plane is read
// under the centre as well and the two misses add up. Read one way only, a
// tap just across a crease lies within the tolerance of the centre's plane
// however sharply the surfaces turn there, and the tolerance (relative to the
// view depth) can span a whole small fold: the blur then averages the faces
// of folds and steps into a pattern of light and dark stripes along them. The
// sum of both misses is the planes' bend times the tap distance, wherever the
// crease lies between the two. Below full resolution taps lie a block apart,
// where a curved surface's second miss alone exceeds the tolerance and the
// blur loses its taps there (measured: LOW 0.08 dB lower with it).
float depth_weight(float tap_z, vec2 g1, vec2 du, float z0, vec2 g0, float tolerance, bool two_way) {
    bool ortho = consts.orthographic != 0;
    bool plane = any(notEqual(g0, vec2(0.0)));
    float expected = plane ? plane_z(z0, g0, du, ortho) : z0;
    float within = plane ? max(kPlaneTolerance * tolerance, 1e-30) : tolerance;
    float miss = abs(tap_z - expected);
    if (two_way && plane && any(notEqual(g1, vec2(0.0)))) miss += abs(plane_z(tap_z, g1, -du, ortho) - z0);
    return clamp(1.0 - miss / within, 0.0, 1.0);
}

// The weighted least-squares plane (a line, for one pass of the gaussian:
// its y moments 0) through the taps, read at the centre (offset 0), from
// the weighted means of the AO, of the offsets k, of k k (xx, xy, yy) and of
// k times the AO. The damping added to the offsets' variance keeps the system
// solvable when every tap lies on one line; where the taps are balanced
// around the centre the mean offset is 0 and the result is the mean.
float line_at_centre(float mean, vec2 k_mean, vec3 kk_mean, vec2 ka_mean) {
    float cxx = kk_mean.x - k_mean.x * k_mean.x + kSlopeDamping;
    float cxy = kk_mean.y - k_mean.x * k_mean.y;
    float cyy = kk_mean.z - k_mean.y * k_mean.y + kSlopeDamping;
    vec2 cka = ka_mean - k_mean * mean;
    vec2 slope = vec2(cyy * cka.x - cxy * cka.y, cxx * cka.y - cxy * cka.x) / (cxx * cyy - cxy * cxy);
    return clamp(mean - dot(k_mean, slope), 0.0, 1.0);
}

void main() {
    ivec2 vpx = ivec2(gl_FragCoord.xy) - u_target_origin;
    ivec2 size = u_pass_size;
    int kind = consts.blur_kind;
    vec2 inv_size = inv_size_of(u_ao_tex);
    vec4 c = owned_texel(u_ao_tex, vpx, inv_size);
    float centre = c.r, z0 = c.g;
    vec2 g0 = c.ba;  // the centre's plane gradient, handed on to the upsample
    if (z0 == SKY_Z) { o_ao = result(1.0, SKY_Z); return; }  // the sky stays exactly 1
    // Floored: an orthographic camera whose near plane lies behind the eye
    // has surfaces at view z = 0, where 0/0 would be undefined.
    float tolerance = max(consts.blur_depth_tolerance * abs(z0), 1e-30);
    GridMap grid = grid_map();
    ivec2 u0 = grid_pixel(grid, vpx);  // tap offsets in viewport pixels: a grid texel spans several
    bool two_way = grid.scale == 1;    // depth_weight says why
    if (kind == SSAO_SHADER_BLUR_BOX) {
        // The chapter's blur: offsets -2..1 in x and y, clamped at the edges;
        // sky taps take no part in the average (the centre never is sky).
        // Depth-aware below full resolution: taps weighted as the
        // depth-aware gaussian weighs them (the centre always counts).
        float sum = 0.0, count = 0.0;
        vec2 sum_k = vec2(0.0), sum_ka = vec2(0.0);
        vec3 sum_kk = vec3(0.0);  // xx, xy, yy
#ifdef SSAO_BLUR_WEIGHTS
        float taps = 0.0;
#endif
        int y = -2;
        do {  // both loops test at the end (common.glsl, "Loops"); a continue goes to the test
            int x = -2;
            do {
                ivec2 t = clamp(vpx + ivec2(x, y), ivec2(0), size - 1);
                vec4 tap = owned_texel(u_ao_tex, t, inv_size);
                if (tap.g == SKY_Z) continue;
                vec2 du = vec2(grid_pixel(grid, t) - u0);
                float w = u_depth_aware ? depth_weight(tap.g, tap.ba, du, z0, g0, tolerance, two_way) : 1.0;
                sum += tap.r * w;
                count += w;
                vec2 k = vec2(x, y);
                sum_k += w * k;
                sum_kk += w * vec3(k.x * k.x, k.x * k.y, k.y * k.y);
                sum_ka += w * k * tap.r;
#ifdef SSAO_BLUR_WEIGHTS
                taps += 1.0;
#endif
            } while (++x < 2);
        } while (++y < 2);
#ifdef SSAO_BLUR_WEIGHTS
        o_ao = result(count / taps, z0, g0);
#else
        float mean = weighted_mean(sum, count);
        float ao = u_depth_aware ? line_at_centre(mean, sum_k / count, sum_kk / count, sum_ka / count) : mean;
        o_ao = result(ao, z0, g0);
#endif
        return;
    }
    bool aware = kind == SSAO_SHADER_BLUR_DEPTH_AWARE || u_depth_aware;
    float inv2s2 = 0.5 / (consts.blur_sigma * consts.blur_sigma);
    float sum = centre, weight = 1.0;
    float sum_k = 0.0, sum_kk = 0.0, sum_ka = 0.0;  // the line fit's moments (the centre's k is 0)
#ifdef SSAO_BLUR_WEIGHTS
    float gaussian = 1.0;  // the centre's weight, never rejected
#endif
    int k = -consts.blur_radius;
    do {  // tests at the end (common.glsl, "Loops"): a continue goes to the test
        if (k == 0) continue;
        ivec2 t = vpx + u_blur_dir * k;
        if (any(lessThan(t, ivec2(0))) || any(greaterThanEqual(t, size))) continue;  // no clamped repeats at borders
        float w = exp(-float(k * k) * inv2s2);
        vec4 tap = owned_texel(u_ao_tex, t, inv_size);
        if (tap.g == SKY_Z) continue;
#ifdef SSAO_BLUR_WEIGHTS
        gaussian += w;
#endif
        if (aware) w *= depth_weight(tap.g, tap.ba, vec2(grid_pixel(grid, t) - u0), z0, g0, tolerance, two_way);
        sum += tap.r * w;
        weight += w;
        float fk = float(k);
        sum_k += w * fk;
        sum_kk += w * fk * fk;
        sum_ka += w * fk * tap.r;
    } while (++k <= consts.blur_radius);
#ifdef SSAO_BLUR_WEIGHTS
    // Same taps summed in the same order: exactly 1 when nothing was rejected.
    float before = u_blur_dir.y != 0 ? centre : 1.0;  // the horizontal pass's share
    o_ao = result(weight / gaussian * before, z0, g0);
#else
    float mean = weighted_mean(sum, weight);
    float ao = aware ? line_at_centre(mean, vec2(sum_k, 0.0) / weight, vec3(sum_kk, 0.0, 0.0) / weight,
                                      vec2(sum_ka, 0.0) / weight)
                     : mean;
    o_ao = result(ao, z0, g0);
#endif
}
