// Shared by every fragment pass: the output every pass writes (o_ao), and the
// AO texture the passes hand each other. A sampling pass writes it, the blur
// reads and writes it, the upsample reads it: (ao, view z, g) with the sky
// marked by view z SKY_Z (common.glsl), texel (0,0) = grid texel (0,0), g the
// tangent plane's screen gradient of the grid's plane texel (grid.frag
// plane_texel; 0 where there is none), with which the upsample predicts the
// surface's depth at each viewport pixel, and the depth-aware blur at each
// tap. RGBA32F where the sampling pass reads the grid, else RG32F, where
// nothing may read g (it would read (0, 1)): every depth test runs on the
// grid (plan.cpp). The last pass before the output writes (ao, ao, ao, 1)
// instead.

uniform sampler2D u_ao_tex;
uniform bool u_pack_depth;  // this pass writes the AO texture: (ao, view z)

layout(location = 0) out vec4 o_ao;

// A weighted mean of AO values, held in [0,1]: a GPU's division need not be
// correctly rounded (NVIDIA's is not), and taps that are all 1 then give
// 1 + 1 ulp.
float weighted_mean(float sum, float weight) { return clamp(sum / weight, 0.0, 1.0); }

vec4 result(float ao, float z, vec2 g) { return u_pack_depth ? vec4(ao, z, g) : vec4(ao, ao, ao, 1.0); }
vec4 result(float ao, float z) { return result(ao, z, vec2(0.0)); }

// A tangent plane puts the surface where it is for a plane, so a test of a
// tap against it can be five times tighter than the blur's tolerance, which
// compares view z alone: tight enough that the floor of a groove narrower
// than a block does not take the AO of the ridges beside it (benchmark scene
// creases), and loose enough that a surface seen at a slant, whose view z
// changes faster than that tolerance from pixel to pixel, still averages.
const float kPlaneTolerance = SSAO_PLANE_TOLERANCE;

// The view z that the tangent plane (view z z, screen gradient g) of the
// texel picked at a viewport position puts under the position du viewport
// pixels away (as the march reads it, visibility.frag step_surface); z
// itself where that ray meets the plane behind the eye.
float plane_z(float z, vec2 g, vec2 du, bool ortho) {
    float gd = dot(g, du);
    float r = 1.0 + gd;
    return ortho ? z + gd : (r > 0.0 ? z / r : z);
}
