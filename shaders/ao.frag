// The sampling pass: normal-oriented hemisphere (or sphere, or two-plane)
// SSAO with a range check, a bias that follows the depth format's step, and
// samples snapped to the texel they read so flat surfaces at grazing angles do
// not occlude themselves.

uniform sampler2D u_normal_tex;
uniform sampler2D u_noise_tex;
uniform bool u_pack_depth;  // writing the blur's RG32F input: (ao, view z)

out vec4 o_ao;

vec4 result(float ao, float z) { return u_pack_depth ? vec4(ao, z, 0.0, 1.0) : vec4(ao, ao, ao, 1.0); }

bool finite3(vec3 v) { return all(lessThan(abs(v), vec3(3.0e38))) && !any(isnan(v)); }

// The normal in view space, unit length and facing the camera; a broken normal
// (zero, NaN, inf) falls back to the direction towards the camera.
vec3 load_normal(ivec2 px, vec3 to_eye) {
    vec3 n = texelFetch(u_normal_tex, px, 0).xyz;
    if (u_modes.w == SSAO_SHADER_PACKING_UNORM) n = n * 2.0 - 1.0;
    if (u_modes.z == SSAO_SHADER_NORMAL_WORLD) n = mat3(u_normal_to_view) * n;
    // Scale by the largest component first: a huge but finite normal (1e20)
    // would overflow dot(n, n) and a tiny one underflow it.
    float m = max(abs(n.x), max(abs(n.y), abs(n.z)));
    // max() need not propagate NaN (llvmpipe's does not), the sum does: a NaN
    // in any component fails the comparison.
    float sum = abs(n.x) + abs(n.y) + abs(n.z);
    if (!(m > 1e-30 && m < 3.0e38 && sum < 3.0e38)) return to_eye;  // zero, NaN or infinite
    n /= m;
    n *= inversesqrt(dot(n, n));
    // Facing away (back faces, interpolation at silhouettes): remove the part
    // pointing away, continuously, instead of flipping.
    float away = dot(n, to_eye);
    if (away < 0.0) {
        n -= to_eye * (away * 1.01);
        n = normalize(n);
    }
    return n;
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

vec2 rotation(ivec2 vpx) {
    if (u_modes.y == SSAO_SHADER_ROTATION_NOISE)
        return texelFetch(u_noise_tex, vpx & (SSAO_NOISE_SIZE - 1), 0).xy;  // tiles from the viewport's corner
    if (u_modes.y == SSAO_SHADER_ROTATION_HASH) {
        float a = pixel_hash(uvec2(vpx), uint(u_counts.y)) * 6.28318530718;
        return vec2(cos(a), sin(a));
    }
    return vec2(1.0, 0.0);
}

void main() {
    ivec2 vpx = ivec2(gl_FragCoord.xy) - u_target_origin;   // viewport-relative pixel
    ivec2 px = vpx + u_viewport.xy;                          // input texel
    float d = fetch_depth(px);
    vec4 Pw = view_position_w(px, d);
    vec3 P = Pw.xyz;
    if (is_sky(d) || !finite3(P)) { o_ao = result(1.0, SKY_Z); return; }

    bool ortho = u_depth.w > 0.5;
    vec3 to_eye = ortho ? vec3(0.0, 0.0, 1.0) : normalize(-P);
    vec3 n = load_normal(px, to_eye);
    vec3 b1, b2;
    basis(n, b1, b2);
    vec2 r = rotation(vpx);
    vec3 T = r.x * b1 + r.y * b2;
    mat3 TBN = mat3(T, cross(n, T), n);

    float radius = u_ao.x;
    float step_p = depth_step(Pw, d);
    float occlusion = 0.0;
    float valid = 0.0;
    int count = u_counts.x;
    for (int i = 0; i < count; ++i) {
        vec3 s = P + TBN * u_kernel[i].xyz * radius;
        vec4 c = u_proj * vec4(s, 1.0);
        if (!(c.w > 0.0)) continue;                       // behind the eye
        vec2 spf = (c.xy / c.w * 0.5 + 0.5) * vec2(u_viewport.zw);
        if (any(lessThan(spf, vec2(0.0))) || any(greaterThanEqual(spf, vec2(u_viewport.zw)))) continue;  // off screen: unknown, not counted
        ivec2 spx = ivec2(spf) + u_viewport.xy;
        valid += 1.0;
        float sd = fetch_depth(spx);
        if (is_sky(sd)) continue;                         // the sky occludes nothing
        vec4 Qw = view_position_w(spx, sd);
        vec3 Q = Qw.xyz;
        // Snap: the point on the ray through the fetched texel's centre that
        // lies on the plane through s parallel to the surface at P. It is
        // within half a texel of s on screen; comparing against s itself
        // would make flat receding planes occlude themselves by up to half a
        // texel times their depth slope (no depth bias covers that). Rays
        // almost parallel to that plane keep s.
        float plane = dot(s, n);
        vec3 sn = s;
        if (ortho) {
            if (abs(n.z) > 1e-3) sn = vec3(Q.xy, (plane - n.x * Q.x - n.y * Q.y) / n.z);
        } else {
            float qn = dot(Q, n);
            if (abs(qn) > 1e-3 * length(Q)) sn = Q * (plane / qn);
        }
        float bias = u_ao.y + u_ao.z * (step_p + depth_step(Qw, sd));
        // The chapter's range check smoothstep(0, 1, radius / |dz|), which is 1
        // for |dz| <= radius: written so that dz = 0 divides nothing.
        float dz = abs(P.z - Q.z);
        float range = dz <= radius ? 1.0 : smoothstep(0.0, 1.0, radius / dz);
        occlusion += (Q.z >= sn.z + bias ? 1.0 : 0.0) * range;
    }
    float o = valid > 0.0 ? occlusion / valid : 0.0;
    float ao = pow(clamp(1.0 - u_ao.w * o, 0.0, 1.0), u_ao2.x);
    o_ao = result(ao, P.z);
}
