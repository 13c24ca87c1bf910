// Shared by every fragment pass: the output every pass writes (o_ao), and the
// AO texture the passes hand each other. A sampling pass writes it, the blur
// reads and writes it, the upsample reads it: RG32F (ao, view z) with the sky
// marked by view z SKY_Z (common.glsl), texel (0,0) = grid texel (0,0). The
// last pass before the output writes (ao, ao, ao, 1) instead.

uniform sampler2D u_ao_tex;
uniform bool u_pack_depth;  // this pass writes the AO texture: (ao, view z)

layout(location = 0) out vec4 o_ao;

vec4 result(float ao, float z) { return u_pack_depth ? vec4(ao, z, 0.0, 1.0) : vec4(ao, ao, ao, 1.0); }
