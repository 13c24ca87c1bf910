// The visibility pass: the cosine-weighted open fraction of the hemisphere
// within the radius, as far as one depth layer can show it. Each of
// consts.sample_count directions (cosine-distributed, in the kernel block) is marched
// from P to the radius in consts.step_count steps or more (direction_steps),
// offset per pixel (march_step_length); a step is
// blocked when the depth layer (read through the texel's tangent plane) lies
// in front of it by at least the bias and at most the thickness (a thin object does not shadow what lies far behind
// it), and a direction is blocked by its first blocked step. Sky, off-screen
// and behind-the-eye steps are open. AO = visible fraction, then strength and
// power as in the kernel pass.
//
// A coarse step can land more than the thickness behind a surface that the
// segment from the previous point (P, or the previous step) crossed: a wall
// or slab seen at a grazing angle, where a short move along the segment is a
// long way in view depth. An exact march (the depth-only limit) finds the
// point just behind that surface and blocks. So a step beyond the thickness
// still blocks when the previous point lies in front of the same tangent
// plane (the crossing test): the segment went through the surface the step's
// texel shows. It costs no fetch, only the plane's depth under the previous
// point. The plane's extension can stand where the surface does not (beside
// a convex object's flank, at large radii), where it darkens a little.

// How far (view z) the depth layer lies in front of step point s, read
// through the fetched texel's tangent plane: the surface there is taken as
// the plane through Q (the texel centre's position) with the texel's normal,
// met by the eye ray through s itself. Exact for planar surfaces however
// grazing, so neither a receding floor nor a wall seen edge-on occludes
// itself or hides a step by up to a texel's depth extent. Where the eye ray
// runs nearly parallel to that plane, the pass's snap (the plane through s
// parallel to the surface at P, met by the texel's ray) stands in. So it
// does where the texel's normal says nothing about its surface: broken (zero,
// NaN, inf) or facing away from the camera (interpolated normals at
// silhouettes). The pixel's own pass bends such a normal to face the camera,
// but as a tangent plane that bent normal is nearly edge-on along the eye
// ray, and reading other rays through it misplaces the surface by far more
// than the thickness: one such texel would shade the whole disc of pixels
// whose marches cross it (hard case "normals: zero, NaN, ...").
//
// The pass always reads the grid (variant GRID_INPUT, at full resolution
// too: plan.cpp), one plane texel per step.
//
// The snap (snap_to_texel_ray) with the pixel's own normal n, set up once per
// pixel so that a step needs only the texel's view z and picked pixel centre
// u0: along the texel's ray Q = (z D(u0) + add_1, z) in perspective,
// D(u0) = (view_mul_z u0 + view_add_z, 1), so n.Q = z (a.u0 + k) + e;
// orthographic Q.xy = view_mul_1 u0 + view_add_1, so n.Q.xy = a.u0 + k. And
// s.n = n.P + t (dir.n) along a direction. The perspective guard's |Q| is
// |z| |D| with |D| taken at the pixel's own ray: across a march the two
// rays' lengths differ by a few percent, the guard's threshold with them.
struct StepSetup {
    vec2 a;
    float k, e;
    float pn;        // n.P
    float grazing;   // perspective: 1e-3 |D(pixel)|
    float nz;        // orthographic: n.z
    bool ortho_snap; // orthographic: |n.z| > 1e-3
    GridMap g;       // the uniforms a step reads, read once (GridMap says why)
    vec2 inv_plane_size;  // 1 / the plane texture's size (owned_texel)
    DepthSteps ds;
};

StepSetup step_setup(Surface sf) {
    StepSetup st;
    vec3 n = sf.n;
    st.pn = dot(n, sf.P);
    st.nz = n.z;
    st.ortho_snap = abs(n.z) > 1e-3;
    st.g = grid_map();
    st.inv_plane_size = inv_size_of(u_depth_tex);
    st.ds = depth_steps();
    mat2 mul_z = mat2(consts.view_mul_z.xy, consts.view_mul_z.zw);
    if (sf.ortho) {
        st.a = n.xy * mat2(consts.view_mul_1.xy, consts.view_mul_1.zw);
        st.k = dot(n.xy, consts.view_add_1);
        st.e = 0.0;
        st.grazing = 0.0;
    } else {
        st.a = n.xy * mul_z;
        st.k = dot(n.xy, consts.view_add_z) + n.z;
        st.e = dot(n.xy, consts.view_add_1);
        vec2 up = vec2(grid_pixel(sf.vpx)) + 0.5;
        st.grazing = 1e-3 * length(vec3(mul_z * up + consts.view_add_z, 1.0));
    }
    return st;
}

// A step's clip coordinates in viewport-pixel units: (x_px w, y_px w, z, w),
// still linear in the step, so a step's pixel position is one division.
vec4 step_clip(StepSetup st, vec4 c) { return vec4((c.xy + c.w) * (0.5 * st.g.size), c.zw); }

// Where a step (step_clip's coordinates) lands, as clip_to_texel (sampling.glsl); spf: its
// viewport pixel coordinates.
bool step_to_texel(StepSetup st, vec4 c, out ivec2 texel, out vec2 spf) {
    texel = ivec2(0);
    spf = vec2(0.0);
    if (!(c.w > 0.0)) return false;
    spf = c.xy * (1.0 / c.w);
    return pixel_to_texel(st.g, spf, texel);
}

// From the grid: one 16-byte plane texel (grid.frag plane_texel) per step,
// which holds the tangent plane as the depth it puts under each viewport
// position: the plane's depth under the step's own position spf (the eye
// ray through s) is z / (1 + g.(spf - u0)) in perspective, z + g.(spf - u0)
// orthographic. The ray is grazing where the cosine between it and the plane
// (the texel's, scaled to the step's ray) is 1e-3 or less, and meets the plane
// only behind the eye where that is negative (spf past the plane's vanishing
// line: a step above a horizon that a ground texel's block straddles); alpha 0
// marks a texel whose normal is unusable. The snap in its place (StepSetup): the
// step's plane s.n = sn met by the texel's ray, perspective at view z
// z sn / n.Q, orthographic (sn - n.xy Q.xy) / n.z. False for the sky.
// prev_in_front: the same plane's view z under the previous point (viewport
// position prev_spf, view z prev_z) minus prev_z, for the crossing test; a
// huge value where the plane is grazing, behind the eye or unusable there (no
// crossing).
bool step_surface(vec3 s, float sn, vec2 spf, ivec2 spx, Surface sf, StepSetup st, vec2 prev_spf, float prev_z,
                  out float in_front, out float prev_in_front) {
    vec4 plane = owned_texel(u_depth_tex, spx, st.inv_plane_size);
    float z = plane.x;
    vec2 u0 = vec2(grid_pixel(st.g, spx)) + 0.5;
    float g_du = dot(plane.yz, spf - u0);
    float r = sf.ortho ? 1.0 : 1.0 + g_du;
    in_front = (sf.ortho ? z + g_du : z / r) - s.z;  // the tangent plane's view z under s
    float g_prev = dot(plane.yz, prev_spf - u0);
    float r_prev = sf.ortho ? 1.0 : 1.0 + g_prev;
    prev_in_front = plane.w * r_prev > 1e-3 ? (sf.ortho ? z + g_prev : z / r_prev) - prev_z : 1e30;
    // Grazing or unusable: the snap. Rare, so a branch; it still costs 4-8%
    // of DEFAULT's time on llvmpipe (which runs it masked for every batch)
    // and 7% on an H200. Reading these texels as a point instead takes the
    // converged estimator further from the limit on spot, past the bound of
    // reference.limit_convergence (docs/benchmark.md, "What the snap buys").
    if (!(plane.w * r > 1e-3)) {
        float l = dot(st.a, u0) + st.k;
        float qn = sf.ortho ? l : z * l + st.e;  // perspective: n.Q; orthographic: n.xy . Q.xy
        bool snap = sf.ortho ? st.ortho_snap : abs(qn) > st.grazing * abs(z);
        float q = (sf.ortho ? sn - qn : z * sn) / (sf.ortho ? st.nz : qn);  // the snapped step's view z
        in_front = z - (snap ? q : s.z);
        prev_in_front = 1e30;
    }
    return z != SKY_Z;
}

// The length of a step, N steps with jitter u: steps at (j + u) R / N, the
// even spacing, end at (N - 1 + u) R / N, short of the radius by R / (2N) on
// average, and miss what a segment meets only past the last step: a surface
// approached late in the march (the far part of a contact shadow or a
// crease's falloff, which read too light). Stretched so that the last step
// reaches R at u = 1, the steps lie further apart and pass over more thin
// occluders. SSAO_MARCH_STRETCH = 0.5, halfway, read best on the mean for
// MEDIUM and HIGH, and within 0.01 dB of the best for LOW and ULTRA, in quick
// runs of every benchmark case against 0, 0.25, 0.75 and 1
// (docs/benchmark.md, "Where the last step lands").
float march_step_length(float radius, int steps, float jitter) {
    return radius / (float(steps) - SSAO_MARCH_STRETCH * (1.0 - jitter));
}

// Steps along one direction: consts.step_count, or, where max_step_texels is
// set (> 0), more where the march spans more than that many
// consts.max_step_texels on screen: as many as keep each step within it, up
// to SSAO_MARCH_MAX_STEPS. Steps many texels apart pass over
// thin occluders (a crease's rim, an edge seen close up) that a continuous
// march meets, which leaves close-ups and large radii too light. The span is
// the projected segment from P to the radius, at most the viewport's
// diagonal (also where the segment's end lies behind the eye), so that a
// huge max_step_texels keeps step_count. Written so that a NaN keeps
// step_count too (clamp and int() of a NaN are undefined). Variant
// STEP_TEXELS (max_step_texels > 0); without it every direction takes
// step_count steps and none of this runs.
#ifdef SSAO_STEP_TEXELS
int direction_steps(StepSetup st, vec4 clip_p, vec4 clip_dir, float radius) {
    vec4 clip_end = clip_p + clip_dir * radius;
    float diagonal = length(st.g.size);
    float span = clip_end.w > 0.0 ? min(length(clip_end.xy / clip_end.w - clip_p.xy / clip_p.w), diagonal) : diagonal;
    float wanted = ceil(span * st.g.inv_scale / consts.max_step_texels);
    return wanted > float(consts.step_count) ? int(min(wanted, float(SSAO_MARCH_MAX_STEPS))) : consts.step_count;
}
#endif

void main() {
    Surface sf;
    if (!load_surface(sf)) { o_ao = result(1.0, SKY_Z); return; }
#ifdef SSAO_FADE
    if (fade_weight(sf.P) >= 1.0) { o_ao = result(1.0, sf.P.z, plane_gradient(sf.vpx)); return; }  // faded out: nothing to march
#endif

    float radius = sf.radius;  // the step length scales with the per-pixel radius (RADIUS_PIXELS)
    float thickness = consts.thickness * sf.radius_scale;
    float jitter = step_jitter(sf.vpx);
#ifndef SSAO_STEP_TEXELS
    int steps = consts.step_count;
    float step_length = march_step_length(radius, steps, jitter);
#endif
    int count = consts.sample_count;
    float open = 0.0;
    // Projection is linear: a step's clip coordinates are those of P plus
    // those of the direction times the distance (no matrix product per step).
    StepSetup st = step_setup(sf);
    mat4 proj = consts.proj;
    vec4 clip_p = step_clip(st, proj * vec4(sf.P, 1.0));
    // The bias: the settings' part, and depth_step_bias steps of the depth
    // format at P and at the depth where the format's step is largest among
    // the surfaces that can block a step (in front of it by at most the
    // thickness, so within P.z - radius .. P.z + radius + thickness): the far
    // end in perspective, where the step grows with distance, and either end
    // in orthographic projections, where it is a convex function of view z.
    // One bound per pixel, nothing computed per step.
    float far_step = depth_step_z(st.ds, sf.P.z - radius);
    float near_step = sf.ortho ? depth_step_z(st.ds, sf.P.z + radius + thickness) : 0.0;
    float bias = consts.bias * sf.radius_scale + consts.depth_step_bias * (sf.step + max(far_step, near_step));
    // Both loops test at the end (common.glsl, "Loops"): count and steps
    // are at least 1 (settings.cpp).
    int i = 0;
    do {
        vec3 dir = sf.TBN * kernel.vectors[i].xyz;
        vec4 clip_dir = step_clip(st, proj * vec4(dir, 0.0));
        float dn = dot(dir, sf.n);
#ifdef SSAO_STEP_TEXELS
        int steps = direction_steps(st, clip_p, clip_dir, radius);
        float step_length = march_step_length(radius, steps, jitter);
#endif
        bool blocked = false;
        vec2 prev_spf = clip_p.xy / clip_p.w;  // the previous point: P, then each step
        float prev_z = sf.P.z;
        int j = 0;
        do {
            float t = (float(j) + jitter) * step_length;
            vec3 s = sf.P + dir * t;
            // Off screen or behind the eye is unknown and open, and the sky
            // blocks nothing: a mask decides, not a branch (the texel read
            // is then texel 0's, unused).
            ivec2 spx;
            vec2 spf;
            bool on_screen = step_to_texel(st, clip_p + clip_dir * t, spx, spf);
            float in_front, prev_in_front;  // in_front > 0: the surface hides the step
            bool surface = step_surface(s, st.pn + dn * t, spf, spx, sf, st, prev_spf, prev_z, in_front, prev_in_front);
            bool crossed = prev_in_front < bias;  // the previous point lay in front of this step's surface
            blocked = on_screen && surface && in_front >= bias && (in_front <= thickness || crossed);
            prev_spf = spf;
            prev_z = s.z;
        } while (++j < steps && !blocked);
        open += blocked ? 0.0 : 1.0;
    } while (++i < count);
    float occlusion = 1.0 - open / float(count);
    float ao = pow(clamp(1.0 - consts.strength * occlusion, 0.0, 1.0), consts.power);
#ifdef SSAO_FADE
    ao = apply_fade(ao, sf.P);
#endif
    o_ao = result(ao, sf.P.z, plane_gradient(sf.vpx));
}
