// Shared by every fragment pass: the host's depth, the grid a pass reads or
// writes, the sky test, view positions (through the inverse projection or
// from view z), and the depth step used for the format-aware bias.

// The texel of the host's texture `tex` (depth or normals) at viewport pixel
// vpx. Variant MULTISAMPLE: the host's textures are
// GL_TEXTURE_2D_MULTISAMPLE and every pixel reads sample u_sample_index
// (Pass::sample_index). Only the passes that read the host's textures (the
// grid pass, the upsample) have this variant.
#ifdef SSAO_MULTISAMPLE
uniform sampler2DMS u_depth_tex;
uniform int u_sample_index;
#define SSAO_INPUT_TEXEL(tex, vpx) texelFetch(tex, (vpx) + consts.viewport_origin, u_sample_index)
#else
uniform sampler2D u_depth_tex;
#define SSAO_INPUT_TEXEL(tex, vpx) texelFetch(tex, (vpx) + consts.viewport_origin, 0)
#endif

// Where viewport pixel (0,0) (or grid texel (0,0)) lands in the pass's render target.
uniform ivec2 u_target_origin;

// Viewport pixels per texel of the grid the pass reads or writes (plan.h
// Pass::scale): 1 = the viewport itself, 2 = half, 4 = quarter resolution.
uniform int u_scale;

// The host's depth at viewport pixel vpx.
float input_depth(ivec2 vpx) { return SSAO_INPUT_TEXEL(u_depth_tex, vpx).r; }

// Texel t of a single-sample texture the library made (the grid's textures,
// the AO texture, the noise tile), inv_size = 1 / its size (inv_size_of):
// sampled at the texel's centre at level 0, the same value as texelFetch,
// since the library's sampler (nearest, clamped to the edge, no compare) is
// bound on every unit (runner.cpp) and these textures have one level. On
// llvmpipe a sample costs less than a fetch, which checks bounds per lane:
// the march and the upsample take less time (docs/benchmark.md, "The
// library's textures sampled, not fetched"). The host's textures keep texelFetch
// (SSAO_INPUT_TEXEL): they may be multisampled.
vec4 owned_texel(sampler2D tex, ivec2 t, vec2 inv_size) { return textureLod(tex, (vec2(t) + 0.5) * inv_size, 0.0); }
vec2 inv_size_of(sampler2D tex) { return 1.0 / vec2(textureSize(tex, 0)); }
vec4 owned_texel(sampler2D tex, ivec2 t) { return owned_texel(tex, t, inv_size_of(tex)); }
#ifdef SSAO_MULTISAMPLE
// No plan reads the grid in a pass that reads multisampled host textures
// (u_depth_tex and u_normal_tex are then the host's), but every variant
// compiles (tests/unit/test_shader_variants.cpp): sample 0, as texelFetch.
vec2 inv_size_of(sampler2DMS tex) { return 1.0 / vec2(textureSize(tex)); }
vec4 owned_texel(sampler2DMS tex, ivec2 t, vec2 inv_size) { return texelFetch(tex, t, 0); }
vec4 owned_texel(sampler2DMS tex, ivec2 t) { return texelFetch(tex, t, 0); }
#endif

// Loops. A loop the compiler may keep as a loop (a count known only at run
// time, or a body too large to unroll) tests its condition at the end of the
// body (do { } while), where the count is at least 1: llvmpipe runs a SIMD
// batch's loop until no lane is left, checking at the end of the body, so a
// loop that tests at the top runs its body once more, every lane masked off,
// before it sees that all have left (docs/benchmark.md, "Loops that test
// at the end", measures what that cost).

// u_scale is 1, 2 or 4 (plugin/settings.h resolution_scale), so u_scale >> 1
// is its base-2 logarithm, and a shift by it divides by u_scale. No shader
// divides an integer by u_scale: llvmpipe has no SIMD integer division and
// divides lane by lane, which cost the upsample a sixth of its time.
int scale_log2() { return u_scale >> 1; }

// The grid: ceil(viewport / scale) texels, so an odd size's last block is
// partial and still has its texel.
ivec2 grid_size() { return (consts.viewport_size + u_scale - 1) >> scale_log2(); }

// How viewport pixels and grid texels map, with the uniforms read once: a
// loop that maps many points (the march) takes grid_map() before it, since
// on llvmpipe every uniform read in a loop body is a load per iteration.
struct GridMap {
    vec2 size;        // the viewport's, in pixels
    ivec2 last;       // its last pixel
    int scale;        // u_scale
    float inv_scale;  // 1 / u_scale, exact for a power of two
    int pick;         // grid_pixel's offset into the block, before the checkerboard's
    int checker;      // 1 below full resolution: the checkerboard's offset mask
    int swap;         // variant FRAME_NOISE: 1 in the frames whose checkerboard is swapped (grid_pixel)
};

GridMap grid_map() {
    GridMap g;
    g.size = vec2(consts.viewport_size);
    g.last = consts.viewport_size - 1;
    g.scale = u_scale;
    g.inv_scale = 1.0 / float(u_scale);
    g.checker = u_scale > 1 ? 1 : 0;
    g.pick = u_scale > 1 ? (u_scale >> 1) - 1 : 0;
#ifdef SSAO_FRAME_NOISE
    g.swap = consts.frame_pick_swap & g.checker;
#else
    g.swap = 0;
#endif
    return g;
}

// The viewport pixel grid texel t stands for: one real pixel of its block,
// near the block's centre, alternating between two positions in a
// checkerboard (half: offset (0,0) or (1,1) in the 2x2 block, by the parity
// of t.x + t.y; quarter: (1,1) or (2,2) in the 4x4 block) so that a
// one-pixel-wide feature is picked in every other block along it. Variant
// FRAME_NOISE: every other frame the two positions swap, so that a host
// averaging frames sees both corners of every block (docs/benchmark.md,
// "Where the grid loses"). Clamped into the viewport for the partial blocks
// of odd sizes. At full resolution: t itself.
ivec2 grid_pixel(GridMap g, ivec2 t) {
    return min(t * g.scale + g.pick + (((t.x + t.y) & g.checker) ^ g.swap), g.last);
}
ivec2 grid_pixel(ivec2 t) { return grid_pixel(grid_map(), t); }

// The host's depth at grid texel t (read only where the kernel pass reads
// the host's textures directly: full resolution, single sample, stored
// normals, no depth-aware blur; variant GRID_INPUT reads view z instead: texel_surface below).
float fetch_depth(ivec2 t) { return input_depth(t); }

// The grid pass stores view z (its plane texels' .r, grid.frag) and the AO
// pass hands the blur and the upsample its view z beside the AO
// (ao_texture.glsl), so a later pass fetches one texel and rebuilds nothing
// through the inverse projection. The sky (and a depth whose position is not finite) carries this
// marker instead.
const float SKY_Z = SSAO_SKY_Z;

bool finite3(vec3 v) { return all(lessThan(abs(v), vec3(3.0e38))) && !any(isnan(v)); }

// A power of two that brings a vector whose largest component is m (> 0)
// to about unit length when m is below 2^-20 or at least 2^21, else exactly 1:
// a scene at tiny (1e-11) or huge (1e20) view depths would underflow or
// overflow the squares that cross, dot, length and normalize take. Exact, so
// every other scene's vectors are untouched.
float unit_scale(float m) {
    int biased = (floatBitsToInt(m) >> 23) & 0xff;  // m's exponent + 127; 0 for 0 and denormals, 255 for inf
    if (biased == 0 || biased == 255 || (biased >= 107 && biased <= 147)) return 1.0;
    return intBitsToFloat((254 - min(biased, 253)) << 23);  // 2^(127 - biased), kept a normal float
}
float largest_abs(vec3 v) { return max(max(abs(v.x), abs(v.y)), abs(v.z)); }
vec3 near_unit(vec3 v) { return v * unit_scale(largest_abs(v)); }

// The far plane (cleared depth) in either convention: exact comparison, since
// a cleared buffer holds exactly the clear value.
bool is_sky(float d) { return d == consts.sky_depth; }

float ndc_z_of(float d) { return consts.ndc_per_depth == 2.0 ? d * 2.0 - 1.0 : d; }

vec2 ndc_xy_of(vec2 viewport_px) { return viewport_px / vec2(consts.viewport_size) * 2.0 - 1.0; }

// View-space position of the point at viewport pixel coordinates vp (a
// pixel's centre is +0.5) holding depth d, in xyz; w keeps the homogeneous w
// of the reconstruction for depth_step().
vec4 view_position_at(vec2 vp, float d) {
    vec4 v = consts.inv_proj * vec4(ndc_xy_of(vp), ndc_z_of(d), 1.0);
    return vec4(v.xyz / v.w, v.w);
}

// Of grid texel t (its picked pixel's centre) holding depth d.
vec4 view_position_w(ivec2 t, float d) { return view_position_at(vec2(grid_pixel(t)) + 0.5, d); }

// View position at viewport pixel coordinates px with view z z: two
// multiply-adds per coordinate (plugin/projection.h ViewFromZ; exact for
// every accepted projection: perspective, orthographic, off-centre, reverse-Z,
// infinite far).
vec3 view_position_from_z(vec2 px, float z) {
    vec2 xy = (mat2(consts.view_mul_z.xy, consts.view_mul_z.zw) * px + consts.view_add_z) * z +
              (mat2(consts.view_mul_1.xy, consts.view_mul_1.zw) * px + consts.view_add_1);
    return vec3(xy, z);
}

// depth_step below for a point at view z z, from z alone: clip w and clip z
// are affine in z (consts.clip_*), so d(view z)/d(ndc z) = w^2 / |det|
// (consts.inv_det). A float format's ulp is one of the stored depth
// d = clip z / w (the [-1,1] range: of d = (ndc + 1) / 2 and of ndc, as
// depth_step), floored at the smallest normal; times w^2 it needs no
// division: |d| w^2 = |clip z| w. The constants are read once
// (depth_steps()) where a loop takes many (GridMap says why).
struct DepthSteps {
    vec4 clip;        // clip_w_z, clip_w_1, clip_z_z, clip_z_1
    float unorm_k;    // inv_det ndc_per_depth unorm_depth_step: 0 for a float format
    float float_k;    // inv_det ndc_per_depth 2^-23: a float format's ulp per |d| w^2
    float normal_k;   // inv_det ndc_per_depth 2^-126: the floor, per w^2
    bool half_range;  // the [-1,1] clip range
};

DepthSteps depth_steps() {
    DepthSteps k;
    k.clip = vec4(consts.clip_w_z, consts.clip_w_1, consts.clip_z_z, consts.clip_z_1);
    float per_ndc = consts.inv_det * consts.ndc_per_depth;
    k.unorm_k = per_ndc * consts.unorm_depth_step;
    k.float_k = per_ndc * 1.1920929e-7;
    k.normal_k = per_ndc * 1.1754944e-38;
    k.half_range = consts.ndc_per_depth == 2.0;
    return k;
}

float depth_step_z(DepthSteps k, float z) {
    float w = k.clip.x * z + k.clip.y;
    // Past 1e18 (view depths of 1e18 and more) w w would overflow: the small
    // factor goes first there.
    float aw = abs(w);
    bool huge = aw > 1e18;
#ifdef SSAO_UNORM_DEPTH
    return huge ? aw * (aw * k.unorm_k) : w * w * k.unorm_k;
#else
    float cz = k.clip.z * z + k.clip.w;
    // |d| w and, for the [-1,1] range, |ndc| w / 2: the larger ulp wins.
    float dw = k.half_range ? max(abs(cz + w), abs(cz)) * 0.5 : abs(cz);
    return huge ? max(dw * (aw * k.float_k), aw * (aw * k.normal_k))
                : max(dw * abs(w) * k.float_k, w * w * k.normal_k);
#endif
}
float depth_step_z(float z) { return depth_step_z(depth_steps(), z); }

// The view z of viewport pixel p holding depth d: the inverse projection's z
// and w rows (the compiler drops x and y), one division. Valid for every
// projection, an oblique near plane's too (clip z with view x or y terms),
// with no branch: a branch on the projection's kind costs both its sides on a
// SIMD rasteriser (llvmpipe runs each side for the whole batch).
float view_z_of_depth(ivec2 p, float d) { return view_position_at(vec2(p) + 0.5, d).z; }

// A surface texel the sampling passes read: its view position and the view-z
// change of one depth-format step there. False for the sky (and a depth whose
// position is not finite, which the grid pass stores as sky). Variant
// GRID_INPUT (the visibility pass always; the kernel below full resolution,
// with the depth-aware blur, multisampled inputs or normals from depth): the view z of the grid
// pass's plane texel, the position by multiply-adds.
// Else the host's depth through the inverse projection.
#ifdef SSAO_GRID_INPUT
bool texel_surface(ivec2 t, out vec3 P, out float step) {
    float z = owned_texel(u_depth_tex, t).r;
    P = view_position_from_z(vec2(grid_pixel(t)) + 0.5, z);
    step = 0.0;
    if (z == SKY_Z) return false;
    step = depth_step_z(z);
    return true;
}
#endif

// The screen gradient of grid texel t's tangent plane (grid.frag
// plane_texel), which a sampling pass hands the depth-aware blur and the
// upsample beside its AO (ao_texture.glsl); 0 where the pass reads no grid.
#ifdef SSAO_GRID_INPUT
vec2 plane_gradient(ivec2 t) { return owned_texel(u_depth_tex, t).yz; }
#else
vec2 plane_gradient(ivec2 t) { return vec2(0.0); }
#endif

// View-space z change for one step of the depth format at depth d, from the
// point p = view_position_w(px, d): |dz/d(ndc)| * d(ndc)/d(depth) * step.
// Analytic: with v = inv_proj * ndc, z = v.z / v.w and
// dz/dndc = (inv_proj[2][2] - z * inv_proj[2][3]) / v.w (no difference of two
// nearly equal reconstructions, which would cancel to 0 in float).
float depth_step(vec4 p, float d) {
    float dz_dndc = (consts.inv_proj[2][2] - p.z * consts.inv_proj[2][3]) / p.w;
    // unorm formats: a fixed step; float: one ulp of d (2^-23 relative), floored
    // at the smallest normal so reverse-Z's tiny far values stay meaningful.
    float ulp = consts.unorm_depth_step > 0.0 ? consts.unorm_depth_step : max(abs(d) * 1.1920929e-7, 1.1754944e-38);
    // [-1,1] clip range: the rasteriser held NDC z = 2d - 1 in float before
    // storing d, and view_position goes back through it, so no float depth is
    // finer than one ulp of NDC z (reverse-Z without a [0,1] clip range keeps
    // standard-Z precision; docs/hard-cases.md, "Depth precision").
    if (consts.unorm_depth_step == 0.0 && consts.ndc_per_depth == 2.0)
        ulp = max(ulp, abs(d * 2.0 - 1.0) * 0.5 * 1.1920929e-7);
    return abs(dz_dndc) * consts.ndc_per_depth * ulp;
}

#ifndef SSAO_GRID_INPUT
bool texel_surface(ivec2 t, out vec3 P, out float step) {
    float d = fetch_depth(t);
    vec4 Pw = view_position_w(t, d);
    P = Pw.xyz;
    step = 0.0;
    if (is_sky(d)) return false;
    step = depth_step(Pw, d);
    return true;
}
#endif
