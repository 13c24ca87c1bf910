// The visibility pass: the cosine-weighted open fraction of the hemisphere
// within the radius, as far as one depth layer can show it. Each of
// u_counts.x directions (cosine-distributed, in the kernel block) is marched
// from P to the radius in u_method.y steps, offset per pixel; a step is
// blocked when the depth buffer lies in front of it by at least the bias and
// at most the thickness (a thin object does not shadow what lies far behind
// it), and a direction is blocked by its first blocked step. Sky, off-screen
// and behind-the-eye steps are open. AO = visible fraction, then strength and
// power as in the kernel pass.

void main() {
    Surface sf;
    if (!load_surface(sf)) { o_ao = result(1.0, SKY_Z); return; }

    float radius = u_ao.x;
    float thickness = u_march.x;
    int steps = u_method.y;
    float jitter = step_jitter(sf.vpx);
    int count = u_counts.x;
    float open = 0.0;
    for (int i = 0; i < count; ++i) {
        vec3 dir = sf.TBN * u_kernel[i].xyz;
        bool blocked = false;
        for (int j = 0; j < steps && !blocked; ++j) {
            vec3 s = sf.P + dir * (radius * (float(j) + jitter) / float(steps));
            ivec2 spx;
            if (!project_to_texel(s, spx)) continue;        // unknown: open
            float sd = fetch_depth(spx);
            if (is_sky(sd)) continue;                       // the sky blocks nothing
            vec4 Qw = view_position_w(spx, sd);
            vec3 sn = snap_to_texel_ray(s, sf.n, Qw.xyz, sf.ortho);
            float bias = u_ao.y + u_ao.z * (sf.step + depth_step(Qw, sd));
            float in_front = Qw.z - sn.z;                   // > 0: the surface hides the step
            blocked = in_front >= bias && in_front <= thickness;
        }
        open += blocked ? 0.0 : 1.0;
    }
    float occlusion = 1.0 - open / float(count);
    float ao = pow(clamp(1.0 - u_ao.w * occlusion, 0.0, 1.0), u_ao2.x);
    o_ao = result(ao, sf.P.z);
}
