// Shared by the passes that read the host's normals or the grid's (the two
// sampling passes, kernel.frag: the point kernel, and visibility.frag:
// ray-marched visibility; the grid pass; the normals view): the normal as a
// pass sees it, the tangent basis, the per-pixel rotation and step jitter, and
// the surface a sampling pass shades.

#ifdef SSAO_MULTISAMPLE
uniform sampler2DMS u_normal_tex;  // multisampled: sample u_sample_index (common.glsl)
#else
uniform sampler2D u_normal_tex;
#endif
uniform sampler2D u_noise_tex;

// The host's stored normal at viewport pixel vpx.
vec3 input_normal(ivec2 vpx) { return SSAO_INPUT_TEXEL(u_normal_tex, vpx).xyz; }

// The stored normal `stored` in view space, scaled so that its largest
// component is 1 (not yet unit length); false when it is zero, NaN or infinite.
bool decode_raw_normal(vec3 stored, out vec3 n) {
    n = stored;
    if (consts.normal_packing == SSAO_SHADER_PACKING_UNORM) n = n * 2.0 - 1.0;
    if (consts.normal_space == SSAO_SHADER_NORMAL_WORLD) n = mat3(consts.normal_to_view) * n;
    // Scale by the largest component first: a huge but finite normal (1e20)
    // would overflow dot(n, n) and a tiny one underflow it.
    float m = largest_abs(n);
    // max() need not propagate NaN (llvmpipe's does not), the sum does: a NaN
    // in any component fails the comparison.
    float sum = abs(n.x) + abs(n.y) + abs(n.z);
    if (!(m > 1e-30 && m < 3.0e38 && sum < 3.0e38)) return false;  // zero, NaN or infinite
    n /= m;
    return true;
}

// A usable normal made unit length and turned towards the camera: the part
// pointing away (back faces, interpolation at silhouettes) is removed,
// continuously, instead of flipping.
vec3 face_camera(vec3 n, vec3 to_eye) {
    n *= inversesqrt(dot(n, n));
    float away = dot(n, to_eye);
    if (away < 0.0) {
        n -= to_eye * (away * 1.01);
        n = normalize(n);
    }
    return n;
}

// A texel of the host's normal texture as the sampling passes see it: view
// space, unit length, facing the camera; a broken normal falls back to the
// direction towards the camera.
vec3 decode_normal(vec3 stored, vec3 to_eye) {
    vec3 n;
    return decode_raw_normal(stored, n) ? face_camera(n, to_eye) : to_eye;
}

// The normal of grid texel t before it is turned towards the camera; false
// when it is broken. From the grid (variant GRID_INPUT) the grid pass has
// decoded it already into its own texture (the picked pixel's unit normal,
// or zero for a broken one).
bool raw_normal(ivec2 t, out vec3 n) {
#ifdef SSAO_GRID_INPUT
    n = owned_texel(u_normal_tex, t).xyz;
    return dot(n, n) > 0.5;
#else
    return decode_raw_normal(input_normal(t), n);
#endif
}

// The normal of grid texel t as the sampling passes see it.
vec3 load_normal(ivec2 t, vec3 to_eye) {
    vec3 n;
    return raw_normal(t, n) ? face_camera(n, to_eye) : to_eye;
}

// Orthonormal basis around n (Duff et al. 2017): no degenerate case, unlike
// Gram-Schmidt against a random vector.
void basis(vec3 n, out vec3 b1, out vec3 b2) {
    float s = n.z >= 0.0 ? 1.0 : -1.0;
    float a = -1.0 / (s + n.z);
    float b = n.x * n.y * a;
    b1 = vec3(1.0 + s * n.x * n.x * a, s * b, -s * n.x);
    b2 = vec3(b, s + n.y * n.y * a, -n.y);
}

// Same integer arithmetic as plugin/kernel.cpp pixel_hash().
float pixel_hash(uvec2 p, uint seed) {
    uint v = p.x * 1973u + p.y * 9277u + seed * 26699u;
    v = v * 747796405u + 2891336453u;
    uint w = ((v >> ((v >> 28u) + 4u)) ^ v) * 277803737u;
    w = (w >> 22u) ^ w;
    return float(w >> 8) * (1.0 / 16777216.0);
}

// Interleaved gradient noise (Jimenez 2014) at grid texel p, in [0,1): no
// period on the screen, and each 3x3 neighbourhood spreads its values evenly.
float interleaved_gradient_noise(vec2 p) { return fract(52.9829189 * fract(dot(p, vec2(0.06711056, 0.00583715)))); }

// The rotation GRADIENT_NOISE takes its angle from interleaved gradient
// noise on the grid and its step jitter from the same noise with x and y
// swapped: no period, and the texels of a 2x2 or 3x3 neighbourhood (what the
// upsample and the blur average) get angles and offsets spread evenly, where
// the 4x4 tile's 16 random angles may bunch. The swap keeps the two apart: a
// shifted copy of the noise would move with the angle, the same offset from
// it at every texel of a neighbourhood.
// Below full resolution a grid texel spans u_scale viewport pixels, so the
// 4x4 tile would repeat every 4 u_scale pixels: a stipple fixed on the
// screen that the upsample cannot hide. There NOISE_4X4 takes the gradient
// noise too; at full resolution it is the chapter's tile.
bool gradient_noise() {
    return consts.rotation == SSAO_SHADER_ROTATION_GRADIENT_NOISE ||
           (consts.rotation == SSAO_SHADER_ROTATION_NOISE && u_scale > 1);
}

vec2 fixed_rotation(ivec2 vpx) {
    if (gradient_noise()) {
        float a = interleaved_gradient_noise(vec2(vpx)) * 6.28318530718;
        return vec2(cos(a), sin(a));
    }
    if (consts.rotation == SSAO_SHADER_ROTATION_NOISE)
        return owned_texel(u_noise_tex, vpx & (SSAO_NOISE_SIZE - 1)).xy;  // tiles from the viewport's corner
    if (consts.rotation == SSAO_SHADER_ROTATION_HASH) {
        float a = pixel_hash(uvec2(vpx), uint(consts.seed)) * 6.28318530718;
        return vec2(cos(a), sin(a));
    }
    return vec2(1.0, 0.0);
}

// The per-pixel rotation (cos, sin). Variant FRAME_NOISE (inputs.frame_index
// != 0): the fixed pattern turned by the frame's R2 offset (consts.frame_rotation =
// cos, sin of 2 pi fract(n / g), plugin/kernel.cpp frame_noise_offsets), so
// each pixel's rotation walks a low-discrepancy sequence over the frames;
// without rotation (NONE) the whole kernel turns per frame.
vec2 rotation(ivec2 vpx) {
    vec2 r = fixed_rotation(vpx);
#ifdef SSAO_FRAME_NOISE
    vec2 f = consts.frame_rotation;
    r = vec2(r.x * f.x - r.y * f.y, r.x * f.y + r.y * f.x);
#endif
    return r;
}

// Per-pixel offset in (0,1) of the visibility method's steps along each
// direction; plugin/kernel.cpp step_jitter() computes the same at full
// resolution. The 4x4 noise gets an ordered (Bayer) pattern, so the 4x4 box
// blur averages 16 offsets; below full resolution see gradient_noise().
float fixed_step_jitter(ivec2 vpx) {
    if (gradient_noise()) return interleaved_gradient_noise(vec2(vpx.yx)) * 0.9999 + 0.00005;
    if (consts.rotation == SSAO_SHADER_ROTATION_NOISE) {
        const int bayer[16] = int[16](0, 8, 2, 10, 12, 4, 14, 6, 3, 11, 1, 9, 15, 7, 13, 5);
        ivec2 t = vpx & 3;
        return (float(bayer[t.y * 4 + t.x]) + 0.5) / 16.0;
    }
    if (consts.rotation == SSAO_SHADER_ROTATION_HASH)
        return pixel_hash(uvec2(vpx.yx), uint(consts.seed) ^ 0x5bd1e995u) * 0.9999 + 0.00005;
    return 0.5;
}

// The step jitter; variant FRAME_NOISE adds the frame's second R2 offset
// (consts.frame_step_offset = fract(n / g^2)) mod 1.
float step_jitter(ivec2 vpx) {
#ifdef SSAO_FRAME_NOISE
    return fract(fixed_step_jitter(vpx) + consts.frame_step_offset);
#else
    return fixed_step_jitter(vpx);
#endif
}

// Snap: the point on the ray through the fetched texel's centre (view position
// Q) that lies on the plane through s parallel to the surface at P (normal n).
// It is within half a texel of s on screen; comparing against s itself would
// make flat receding planes occlude themselves by up to half a texel times
// their depth slope (no depth bias covers that). Rays almost parallel to that
// plane keep s.
vec3 snap_to_texel_ray(vec3 s, vec3 n, vec3 Q, bool ortho) {
    float plane = dot(s, n);
    if (ortho) {
        if (abs(n.z) > 1e-3) return vec3(Q.xy, (plane - n.x * Q.x - n.y * Q.y) / n.z);
        return s;
    }
    vec3 Qs = near_unit(Q);  // at tiny or huge view depths length(Q) would underflow or overflow
    float qn = dot(Qs, n);
    return abs(qn) > 1e-3 * length(Qs) ? Qs * (plane / qn) : s;
}

// What both sampling passes know about the pixel they shade.
struct Surface {
    ivec2 vpx;    // grid texel (the viewport pixel at full resolution)
    vec3 P;       // view-space position
    vec3 n;       // unit normal facing the camera (load_normal)
    mat3 TBN;     // tangent frame around n, rotated per pixel
    float step;   // view-z change of one depth-format step at P
    bool ortho;
    float radius;        // sampling radius at P (view units): consts.radius, or from radius_pixels
    float radius_scale;  // radius / consts.radius: bias and thickness scale with it (1 without RADIUS_PIXELS)
};

#ifdef SSAO_RADIUS_PIXELS
// View-space size of one viewport pixel at view z z: how far the position
// moves per viewport pixel along x and along y at that view z (the columns of
// d(view xy)/d(px) = mul_z z + mul_1, common.glsl view_position_from_z); the
// geometric mean of the two. Pixels are the viewport's, also on a half or
// quarter resolution grid. From the projection's own coefficients, so
// orthographic (constant size) and off-centre frusta come out right.
float pixel_size_at(float z) {
    mat2 d = mat2(consts.view_mul_z.xy, consts.view_mul_z.zw) * z + mat2(consts.view_mul_1.xy, consts.view_mul_1.zw);
    // Scaled near unit length first (exactly): at tiny or huge view depths the lengths' squares would not fit.
    float k = unit_scale(max(largest_abs(vec3(d[0], 0.0)), largest_abs(vec3(d[1], 0.0))));
    return sqrt(length(d[0] * k) * length(d[1] * k)) / k;
}
#endif

#ifdef SSAO_FADE
// Distance fade (settings fade_start and fade_end, in consts): the
// weight of "no occlusion" at view-space P, linear in view depth -P.z (the
// distance along the view axis): 0 up to fade_start, 1 from fade_end on.
float fade_weight(vec3 P) {
    return clamp((-P.z - consts.fade_start) / (consts.fade_end - consts.fade_start), 0.0, 1.0);
}

// AO blended towards 1 by the fade weight; exactly `ao` before fade_start.
float apply_fade(float ao, vec3 P) {
    float f = fade_weight(P);
    return f > 0.0 ? mix(ao, 1.0, f) : ao;
}
#endif

// Fills `sf` for this fragment; false for sky and for depths whose position
// is not finite (they get AO 1).
bool load_surface(out Surface sf) {
    sf.vpx = ivec2(gl_FragCoord.xy) - u_target_origin;
    ivec2 px = sf.vpx;
    sf.ortho = consts.orthographic != 0;
    if (!texel_surface(px, sf.P, sf.step) || !finite3(sf.P)) return false;
    vec3 to_eye = sf.ortho ? vec3(0.0, 0.0, 1.0) : normalize(near_unit(-sf.P));
    sf.n = load_normal(px, to_eye);
    vec3 b1, b2;
    basis(sf.n, b1, b2);
    vec2 r = rotation(sf.vpx);
    vec3 T = r.x * b1 + r.y * b2;
    sf.TBN = mat3(T, cross(sf.n, T), sf.n);
    sf.radius = consts.radius;
    sf.radius_scale = 1.0;
#ifdef SSAO_RADIUS_PIXELS
    // consts.radius_pixels pixels at this depth, at most `radius`; a
    // degenerate size (NaN) keeps `radius`.
    float pixels = consts.radius_pixels * pixel_size_at(sf.P.z);
    sf.radius = pixels < consts.radius ? pixels : consts.radius;
    sf.radius_scale = sf.radius / consts.radius;
#endif
    return true;
}

// The grid texel whose block holds viewport pixel coordinates spf, or false
// (texel 0) when spf lies off the viewport.
bool pixel_to_texel(GridMap g, vec2 spf, out ivec2 texel) {
    texel = ivec2(0);
    // Tested for being inside, so that a NaN position (an overflowed step) is outside.
    if (!(all(greaterThanEqual(spf, vec2(0.0))) && all(lessThan(spf, g.size)))) return false;
    // spf / scale for a power-of-two scale is exact in float, so this is
    // ivec2(spf) / u_scale without an integer division per step.
    texel = ivec2(spf * g.inv_scale);
    return true;
}
bool pixel_to_texel(vec2 spf, out ivec2 texel) { return pixel_to_texel(grid_map(), spf, texel); }

// Where the point with clip coordinates c lands: the grid texel whose block
// holds it, or false when it is behind the eye or off the viewport.
bool clip_to_texel(vec4 c, out ivec2 texel) {
    texel = ivec2(0);
    if (!(c.w > 0.0)) return false;
    return pixel_to_texel((c.xy / c.w * 0.5 + 0.5) * vec2(consts.viewport_size), texel);
}

// The same for view-space point s.
bool project_to_texel(vec3 s, out ivec2 texel) { return clip_to_texel(consts.proj * vec4(s, 1.0), texel); }
