// The grid pass: for each block of u_scale x u_scale viewport pixels (scale
// 1: every pixel), one real pixel of it (grid_pixel, common.glsl) - its view
// z, never an average, so no depth floats in the gap of a silhouette - and its normal in view
// space: the host's decoded (unit length; zero when broken) or, variant
// NORMALS_FROM_DEPTH, rebuilt from the host's depth around the picked pixel.
// Two outputs (one framebuffer, two colour attachments), both RGBA32F: the
// plane texel (plane_texel below), what every march step reads, 16 bytes,
// whose .r is the picked pixel's view z (SKY_Z for the sky and for a depth
// whose position is not finite), all that the other readers use; and
// (normal xyz, 0), read once per pixel by the sampling pass.

layout(location = 1) out vec4 o_normal;

#ifdef SSAO_NORMALS_FROM_DEPTH
// Viewport pixel q's depth, when q lies inside the viewport and holds a
// surface (not sky, a finite position): a neighbour the reconstruction may use.
bool surface_at(ivec2 q, out float d, out vec3 P) {
    d = 0.0;
    P = vec3(0.0);
    if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, consts.viewport_size))) return false;
    d = input_depth(q);
    P = view_position_at(vec2(q) + 0.5, d).xyz;
    return !is_sky(d) && finite3(P);
}

// The surface's tangent at p (depth d0, position P0) along axis a, one pixel
// long. A plane's stored depth is affine in window coordinates in every
// convention (perspective: affine in 1/z; orthographic: in z), so the line
// through a side's two pixels, extrapolated to p, hits d0 exactly when they
// lie on p's plane: a side's error is the smaller of this miss and the plain
// depth difference (the latter alone decides a side with one pixel in the
// viewport, and saves a thin strip whose second pixel is background). The
// side of the smaller error wins: across a silhouette the miss is the depth
// jump, at a crease it grows with the other plane's bend, so neither smears
// into p, and a flat surface is never faceted. When the two sides' errors are
// within a factor 2 of each other (a smooth surface: both misses are its
// curvature) the two are averaged, a central difference, whose error on a
// curved surface is second order instead of first. False: no usable side.
bool side_tangent(ivec2 p, float d0, vec3 P0, ivec2 a, out vec3 T) {
    T = vec3(0.0);
    vec3 t[2];
    float err[2];
    bool ok[2];
    for (int i = 0; i < 2; ++i) {
        int s = 2 * i - 1;
        float d1, d2;
        vec3 P1, P2;
        t[i] = vec3(0.0);
        err[i] = 0.0;
        ok[i] = surface_at(p + a * s, d1, P1);
        if (!ok[i]) continue;
        err[i] = abs(d1 - d0);
        if (surface_at(p + a * (2 * s), d2, P2)) err[i] = min(err[i], abs(2.0 * d1 - d2 - d0));
        t[i] = (P1 - P0) * float(s);
    }
    if (ok[0] && ok[1]) {
        float lo = min(err[0], err[1]), hi = max(err[0], err[1]);
        T = hi <= 2.0 * lo ? 0.5 * (t[0] + t[1]) : (err[0] < err[1] ? t[0] : t[1]);
        return true;
    }
    T = ok[0] ? t[0] : t[1];
    return ok[0] || ok[1];
}

// The unit view-space normal at viewport pixel p (a surface at P0), turned
// towards the camera (to_eye). With one usable axis: the direction closest to
// the camera's that is perpendicular to it; with none: towards the camera.
vec3 normal_from_depth(ivec2 p, float d0, vec3 P0, vec3 to_eye) {
    vec3 tx, ty;
    bool hx = side_tangent(p, d0, P0, ivec2(1, 0), tx);
    bool hy = side_tangent(p, d0, P0, ivec2(0, 1), ty);
    vec3 n = to_eye;
    if (hx && hy) {
        float k = unit_scale(max(largest_abs(tx), largest_abs(ty)));
        n = cross(tx * k, ty * k);
    } else if (hx || hy) {
        vec3 t = near_unit(hx ? tx : ty);
        float tt = dot(t, t);
        if (tt > 0.0) n = to_eye - t * (dot(to_eye, t) / tt);
    }
    float nn = dot(n, n);
    if (!(nn > 0.0) || !finite3(n)) return to_eye;  // degenerate (parallel tangents, underflow)
    n *= inversesqrt(nn);
    return dot(n, to_eye) < 0.0 ? -n : n;
}
#endif

// The plane texel of a surface at view z z, picked pixel centre u0, unit
// normal n (zero when broken): its tangent plane as the depth it puts under
// every viewport position u, so that a march step reads the surface under
// its own screen position from one texel (visibility.frag step_surface). Along a pixel's ray X = D(u) z + (view_add_1, 0),
// D(u) = (view_mul_z u + view_add_z, 1) (view_position_from_z), so on the
// plane n.X = n.Q:
//   perspective:  1/z is affine in u, z(u) = z / (1 + g.(u - u0)),
//                 g = (n.xy view_mul_z) / (n.D(u0));
//   orthographic: z is affine in u,    z(u) = z + g.(u - u0),
//                 g = -(n.xy view_mul_1) / n.z.
// Alpha: the cosine between the eye ray at u0 and the plane (|n.D(u0)| /
// |D(u0)|; orthographic n.z), which the march scales by the step's
// (1 + g.(u - u0)) to test for a grazing ray; 0 marks a normal the march
// must not use as a tangent plane: broken, facing away from the camera, or
// so nearly edge-on to its own ray that g is not finite.
vec4 plane_texel(vec2 u0, float z, vec3 n) {
    vec2 g;
    float cos0;
    if (consts.orthographic != 0) {
        g = -(n.xy * mat2(consts.view_mul_1.xy, consts.view_mul_1.zw)) / n.z;
        cos0 = n.z;  // facing the camera: +z
    } else {
        vec3 D0 = vec3(mat2(consts.view_mul_z.xy, consts.view_mul_z.zw) * u0 + consts.view_add_z, 1.0);
        float nd = dot(n, D0);
        g = (n.xy * mat2(consts.view_mul_z.xy, consts.view_mul_z.zw)) / nd;
        // Facing the camera: n points from the plane towards the eye, whose
        // side of the plane n.X = n.Q is where n.Q - n.eye = z n.D(u0) < 0.
        cos0 = -z * nd > 0.0 ? abs(nd) / length(D0) : 0.0;
    }
    bool usable = dot(n, n) > 0.5 && cos0 > 0.0 && all(lessThan(abs(g), vec2(3.0e38)));
    return usable ? vec4(z, g, cos0) : vec4(z, 0.0, 0.0, 0.0);
}

void main() {
    ivec2 t = ivec2(gl_FragCoord.xy) - u_target_origin;
    ivec2 p = grid_pixel(t);
    float d = input_depth(p);
    vec3 P = view_position_at(vec2(p) + 0.5, d).xyz;
    vec3 n = vec3(0.0, 0.0, 1.0);  // sky and unusable depths: never read as a surface
    if (!is_sky(d) && finite3(P)) {
#ifdef SSAO_NORMALS_FROM_DEPTH
        // Rebuilt from the full-resolution neighbours of the picked pixel,
        // already unit length and facing the camera.
        n = normal_from_depth(p, d, P, consts.orthographic != 0 ? vec3(0.0, 0.0, 1.0) : normalize(near_unit(-P)));
#else
        // Unit length but not yet turned towards the camera (raw_normal,
        // sampling.glsl): the visibility pass must see which normals face
        // away; zero marks a broken one.
        n = decode_raw_normal(input_normal(p), n) ? normalize(n) : vec3(0.0);
#endif
    }
    bool surface = !is_sky(d) && finite3(P);
    o_ao = surface ? plane_texel(vec2(p) + 0.5, P.z, n) : vec4(SKY_Z, 0.0, 0.0, 0.0);
    o_normal = vec4(n, 0.0);
    // The grid's sky mask (plan.h DepthUse): 1 where a pass on the grid
    // would only write the sky's value, which its depth test then skips.
    gl_FragDepth = surface ? 0.0 : 1.0;
}
