// The downsample (below full resolution): for each block of u_scale x u_scale
// viewport pixels, one real pixel of it (grid_pixel, common.glsl) - its depth
// copied bit for bit, never an average, so no depth floats in the gap of a
// silhouette and the sky keeps its exact clear value - and its normal decoded
// into view space (unit length; zero when broken).
// Output RGBA32F: (depth as stored, normal xyz).

void main() {
    ivec2 t = ivec2(gl_FragCoord.xy) - u_target_origin;
    ivec2 p = grid_pixel(t);
    float d = input_depth(p);
    vec3 P = view_position_at(vec2(p) + 0.5, d).xyz;
    vec3 n = vec3(0.0, 0.0, 1.0);  // sky and unusable depths: never read as a surface
    if (!is_sky(d) && finite3(P)) {
        // Unit length but not yet turned towards the camera (raw_normal,
        // sampling.glsl): the visibility pass must see which normals face
        // away; zero marks a broken one.
        n = decode_raw_normal(input_normal(p), n) ? normalize(n) : vec3(0.0);
    }
    o_ao = vec4(d, n);
}
