// Shared by the AO and blur passes: depth fetch, sky test, view-position
// reconstruction with the inverse projection, and the depth step used for the
// format-aware bias.

#ifdef SSAO_MULTISAMPLE
// (1.2) The host's depth is a GL_TEXTURE_2D_MULTISAMPLE: every pixel reads
// sample u_sample_index (Pass::sample_index). Only the passes that read the
// host's textures (the grid pass, the upsample) have this variant.
uniform sampler2DMS u_depth_tex;
uniform int u_sample_index;
#else
uniform sampler2D u_depth_tex;
#endif

// Where viewport pixel (0,0) (or grid texel (0,0)) lands in the pass's render target.
uniform ivec2 u_target_origin;

// Viewport pixels per texel of the grid the pass reads or writes (plan.h
// Pass::scale): 1 = the viewport itself, 2 = half, 4 = quarter resolution.
uniform int u_scale;

// The host's depth at viewport pixel vpx.
#ifdef SSAO_MULTISAMPLE
float input_depth(ivec2 vpx) { return texelFetch(u_depth_tex, vpx + u_viewport.xy, u_sample_index).r; }
#else
float input_depth(ivec2 vpx) { return texelFetch(u_depth_tex, vpx + u_viewport.xy, 0).r; }
#endif

// The grid: ceil(viewport / scale) texels, so an odd size's last block is
// partial and still has its texel.
ivec2 grid_size() { return (u_viewport.zw + u_scale - 1) / u_scale; }

// The viewport pixel grid texel t stands for: one real pixel of its block,
// near the block's centre, alternating between two positions in a
// checkerboard (half: offset (0,0) or (1,1) in the 2x2 block, by the parity
// of t.x + t.y; quarter: (1,1) or (2,2) in the 4x4 block) so that a
// one-pixel-wide feature is picked in every other block along it. Clamped
// into the viewport for the partial blocks of odd sizes.
ivec2 grid_pixel(ivec2 t) {
    if (u_scale == 1) return t;
    int o = u_scale / 2 - 1 + ((t.x + t.y) & 1);
    return min(t * u_scale + o, u_viewport.zw - 1);
}

// Depth of grid texel t: the host's depth texture, or (variant GRID_INPUT:
// below full resolution, multisampled inputs, normals from depth) the grid
// pass's texture, whose red channel is the picked pixel's depth copied bit
// for bit.
#ifdef SSAO_GRID_INPUT
float fetch_depth(ivec2 t) { return texelFetch(u_depth_tex, t, 0).r; }
#else
float fetch_depth(ivec2 t) { return input_depth(t); }
#endif

// The far plane (cleared depth) in either convention: exact comparison, since
// a cleared buffer holds exactly the clear value.
bool is_sky(float d) { return d == u_depth.x; }

float ndc_z_of(float d) { return u_ao2.w == 2.0 ? d * 2.0 - 1.0 : d; }

vec2 ndc_xy_of(vec2 viewport_px) { return viewport_px / vec2(u_viewport.zw) * 2.0 - 1.0; }

// View-space position of the point at viewport pixel coordinates vp (a
// pixel's centre is +0.5) holding depth d, in xyz; w keeps the homogeneous w
// of the reconstruction for depth_step().
vec4 view_position_at(vec2 vp, float d) {
    vec4 v = u_inv_proj * vec4(ndc_xy_of(vp), ndc_z_of(d), 1.0);
    return vec4(v.xyz / v.w, v.w);
}

// Of grid texel t (its picked pixel's centre) holding depth d.
vec4 view_position_w(ivec2 t, float d) { return view_position_at(vec2(grid_pixel(t)) + 0.5, d); }

// View-space z change for one step of the depth format at depth d, from the
// point p = view_position_w(px, d): |dz/d(ndc)| * d(ndc)/d(depth) * step.
// Analytic: with v = inv_proj * ndc, z = v.z / v.w and
// dz/dndc = (inv_proj[2][2] - z * inv_proj[2][3]) / v.w (no difference of two
// nearly equal reconstructions, which would cancel to 0 in float).
float depth_step(vec4 p, float d) {
    float dz_dndc = (u_inv_proj[2][2] - p.z * u_inv_proj[2][3]) / p.w;
    // unorm formats: a fixed step; float: one ulp of d (2^-23 relative), floored
    // at the smallest normal so reverse-Z's tiny far values stay meaningful.
    float ulp = u_depth.y > 0.0 ? u_depth.y : max(abs(d) * 1.1920929e-7, 1.1754944e-38);
    // [-1,1] clip range: the rasteriser held NDC z = 2d - 1 in float before
    // storing d, and view_position goes back through it, so no float depth is
    // finer than one ulp of NDC z (reverse-Z without a [0,1] clip range keeps
    // standard-Z precision; README "Depth precision").
    if (u_depth.y == 0.0 && u_ao2.w == 2.0) ulp = max(ulp, abs(d * 2.0 - 1.0) * 0.5 * 1.1920929e-7);
    return abs(dz_dndc) * u_ao2.w * ulp;
}

// The AO pass hands the blur its view z beside the AO (the intermediate
// targets are RG32F), so the blur fetches one texel per tap and rebuilds
// nothing. Sky carries this marker instead of a depth.
const float SKY_Z = 3.0e38;
