// Shared by every fragment pass: the output every pass writes (o_ao), and the
// AO texture the passes hand each other. A sampling pass writes it, the blur
// reads and writes it, the upsample reads it: (ao, view z, g) with the sky
// marked by view z SKY_Z (common.glsl), texel (0,0) = grid texel (0,0), g the
// tangent plane's screen gradient of the grid's plane texel (grid.frag
// plane_texel; 0 where there is none), with which the upsample predicts the
// surface's depth at each viewport pixel. RGBA32F below full resolution, RG32F
// at full resolution, where nothing reads g. The last pass before the output
// writes (ao, ao, ao, 1) instead.

uniform sampler2D u_ao_tex;
uniform bool u_pack_depth;  // this pass writes the AO texture: (ao, view z)

layout(location = 0) out vec4 o_ao;

vec4 result(float ao, float z, vec2 g) { return u_pack_depth ? vec4(ao, z, g) : vec4(ao, ao, ao, 1.0); }
vec4 result(float ao, float z) { return result(ao, z, vec2(0.0)); }
