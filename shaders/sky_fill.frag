// The sky fill: drawn with the complement of a sky-tested pass's depth test
// (runner.cpp draw_sky_fill), so it runs exactly on the pixels that pass skips and
// writes there what that pass's shader writes at the sky (ao_texture.glsl
// result): every texel of the pass's rectangle is written once, by the pass
// or by the fill.
void main() { o_ao = result(1.0, SKY_Z); }
