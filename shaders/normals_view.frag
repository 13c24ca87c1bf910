// The debug views NORMALS and RECONSTRUCTED_NORMALS (ssao_settings.debug_view):
// the normal of every viewport pixel as the sampling passes see it (read from
// the full-resolution grid, variant GRID_INPUT: unit length, turned towards
// the camera, a broken one replaced by the direction to the camera), packed
// as n * 0.5 + 0.5 into RGB, alpha 1. Sky has no normal: (0.5, 0.5, 0.5).

void main() {
    ivec2 t = ivec2(gl_FragCoord.xy) - u_target_origin;
    vec3 P;
    float step;
    vec3 n = vec3(0.0);
    if (texel_surface(t, P, step) && finite3(P))
        n = load_normal(t, consts.orthographic != 0 ? vec3(0.0, 0.0, 1.0) : normalize(near_unit(-P)));
    o_ao = vec4(n * 0.5 + 0.5, 1.0);
}
