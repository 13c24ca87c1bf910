// The sampling pass: normal-oriented hemisphere (or sphere, or two-plane)
// SSAO with a range check, a bias that follows the depth format's step, and
// samples snapped to the texel they read so flat surfaces at grazing angles do
// not occlude themselves.

void main() {
    Surface sf;
    if (!load_surface(sf)) { o_ao = result(1.0, SKY_Z); return; }
#ifdef SSAO_FADE
    if (fade_weight(sf.P) >= 1.0) { o_ao = result(1.0, sf.P.z, plane_gradient(sf.vpx)); return; }  // faded out: nothing to sample
#endif
    vec3 P = sf.P, n = sf.n;
    mat3 TBN = sf.TBN;
    bool ortho = sf.ortho;

    float radius = sf.radius;  // the kernel scales with the per-pixel radius (RADIUS_PIXELS)
    float step_p = sf.step;
    float occlusion = 0.0;
    float valid = 0.0;
    int count = consts.sample_count;
    int i = 0;
    do {  // tests at the end (common.glsl, "Loops"): count is at least 1; a continue goes to the test
        vec3 s = P + TBN * kernel.vectors[i].xyz * radius;
        ivec2 spx;
        if (!project_to_texel(s, spx)) continue;          // behind the eye or off screen: unknown, not counted
        valid += 1.0;
        vec3 Q;
        float q_step;
        if (!texel_surface(spx, Q, q_step)) continue;     // the sky occludes nothing
        vec3 sn = snap_to_texel_ray(s, n, Q, ortho);
        float bias = consts.bias * sf.radius_scale + consts.depth_step_bias * (step_p + q_step);
        // The chapter's range check smoothstep(0, 1, radius / |dz|), which is 1
        // for |dz| <= radius: written so that dz = 0 divides nothing.
        float dz = abs(P.z - Q.z);
        float range = dz <= radius ? 1.0 : smoothstep(0.0, 1.0, radius / dz);
        occlusion += (Q.z >= sn.z + bias ? 1.0 : 0.0) * range;
    } while (++i < count);
    float o = valid > 0.0 ? occlusion / valid : 0.0;
    float ao = pow(clamp(1.0 - consts.strength * o, 0.0, 1.0), consts.power);
#ifdef SSAO_FADE
    ao = apply_fade(ao, P);
#endif
    o_ao = result(ao, P.z, plane_gradient(sf.vpx));
}
