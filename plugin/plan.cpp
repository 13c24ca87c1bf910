// plan.cpp - plan_frame: which passes run, in which order, reading what and
// writing where. The only place that decides the pass sequence.
#include "plan.h"

#include "pass_table.h"
#include "settings.h"

namespace ssao_impl {

namespace {

using Source = TexRef::Source;

TexFormat output_format_of(const ssao_settings& s) {
    if (writes_normals(s)) return TexFormat::rgba8;  // ssao.h: the normal views' own output is RGBA8
    return s.output_format == SSAO_OUTPUT_R16F ? TexFormat::r16f : TexFormat::r8;
}

// Builds a plan pass by pass; the caller states where each pass writes.
class Builder {
public:
    explicit Builder(FramePlan& plan) : plan_(plan) {}

    int intermediate(int w, int h, TexFormat format) {
        const int i = plan_.intermediate_count++;
        plan_.intermediates[i] = {w, h, format};
        return i;
    }

    TexRef mask(int w, int h, TexFormat format) {
        const int i = plan_.mask_count++;
        plan_.masks[i] = {w, h, format};
        return TexRef::of(TexRef::Source::mask, i);
    }

    // A pass writing `target` over the rectangle `rect` of it.
    Pass& add(PassKind kind, TexRef target, const Rect& rect) {
        Pass& p = plan_.passes[plan_.pass_count++];
        p = Pass{};
        p.kind = kind;
        p.target = target;
        p.rect = rect;
        p.pack_depth = target.source == Source::intermediate;
        return p;
    }

private:
    FramePlan& plan_;
};

bool same_rect(const Rect& a, const Rect& b) {
    return a.x == b.x && a.y == b.y && a.width == b.width && a.height == b.height;
}

// The copy of the host's depth is made by a blit, which copies depth only
// between matching formats: the host's own.
TexFormat depth_copy_format(const DepthFormat& d) {
    if (d.is_float) return d.has_stencil ? TexFormat::d32fs8 : TexFormat::d32f;
    if (d.bits == 16) return TexFormat::d16;
    return d.has_stencil ? TexFormat::d24s8 : TexFormat::d24;
}

// The sky tests of a plan of AO passes (DepthUse). A pass that writes the
// output (and, without a grid, one that writes an intermediate at the
// output's rectangle) runs where the copy of the host's depth is not the
// sky, on a software rasteriser and if that depth is single-sampled (a blit
// of a multisampled depth resolves it); a pass on the grid, where the grid's
// sky mask is 0. Each rejects only pixels where its shader writes the sky's
// value, which the plan's SkyFill puts there instead: the host's
// sky is sky on the grid too (grid.frag), and the passes after the grid
// read the sky from it. The grid pass writes its mask only where a pass
// tests it, and the copy is made only where one tests that.
void add_sky_tests(Builder& b, FramePlan& plan, const AnalysedInputs& in, const Rect& final_rect) {
    int grid = -1;
    TexRef grid_mask, depth_copy;
    for (int i = 0; i < plan.pass_count; ++i) {
        Pass& p = plan.passes[i];
        if (p.kind == PassKind::grid) grid = i;
        if (p.kind == PassKind::grid || p.kind == PassKind::clear) continue;
        const bool writes_output = p.target.source == Source::output;
        if (writes_output || (grid < 0 && same_rect(p.rect, final_rect))) {
            if (in.multisample || !in.software_rasterizer) continue;
            if (depth_copy.source == Source::none)
                depth_copy = b.mask(final_rect.x + final_rect.width, final_rect.y + final_rect.height,
                                    depth_copy_format(in.depth));
            p.depth = DepthUse::depth_copy;
            p.depth_target = depth_copy;
        } else if (grid >= 0) {
            const Rect& g = plan.passes[grid].rect;
            if (grid_mask.source == Source::none) grid_mask = b.mask(g.width, g.height, TexFormat::d16);
            p.depth = DepthUse::grid_mask;
            p.depth_target = grid_mask;
        }
    }
    plan.sky_fill = in.software_rasterizer ? SkyFill::clear : SkyFill::draw;
    if (grid_mask.source == Source::none) return;
    plan.passes[grid].depth = DepthUse::write_grid_mask;
    plan.passes[grid].depth_target = grid_mask;
}

// Variant bits of a pass that reads the host's depth and normal textures.
uint32_t host_input_variant(const AnalysedInputs& in) { return in.multisample ? variant::multisample : 0u; }

// Variant bit of every pass that maps grid texels to the pixels they
// picked (grid_pixel, common.glsl): with a moving frame index the picks swap
// corners every other frame, and all passes of a frame must agree on them.
uint32_t grid_pick_variant(const AnalysedInputs& in) { return in.frame_index != 0 ? variant::frame_noise : 0u; }

// Variant bits of the sampling pass's optional features: each only
// when asked for, so a plan without them compiles and runs none of their code.
uint32_t sampling_feature_variant(const ssao_settings& s, const AnalysedInputs& in) {
    uint32_t v = 0;
    if (s.fade_end > 0.0f) v |= variant::fade;                // distance fade
    if (s.radius_pixels > 0.0f) v |= variant::radius_pixels;  // radius in viewport pixels
    if (in.frame_index != 0) v |= variant::frame_noise;       // noise moving with the frame index
    if (s.method == SSAO_METHOD_VISIBILITY && s.max_step_texels > 0.0f) v |= variant::step_texels;  // steps per texels
    // The bias's depth-format step, per march step: one formula, not both
    // (a SIMD rasteriser pays for both sides of a branch on the format).
    if (!in.depth.is_float) v |= variant::unorm_depth;
    return v;
}

// The textures of the grid pass: its plane texels (RGBA32F: view z and the
// tangent plane as depth over the screen, what each march step reads; the
// other passes read the view z alone) and its normal (RGBA32F, read once per
// pixel).
struct GridTextures {
    TexRef plane, normal;
};

// The grid pass: one picked texel per scale x scale block (scale 1: every
// pixel) -> RGBA32F plane texels and RGBA32F view-space normals, in one draw
// to two targets. It runs below full resolution, for the visibility estimator
// and the depth-aware blur (below), for multisampled inputs (it reads one
// sample, so no later pass sees the multisampled textures) and when normals
// come from depth (it rebuilds them once, not in every sampling step).
GridTextures add_grid_pass(Builder& b, const AnalysedInputs& in, int scale, const Rect& low) {
    GridTextures g;
    g.plane = TexRef::of(Source::intermediate, b.intermediate(low.width, low.height, TexFormat::rgba32f));
    g.normal = TexRef::of(Source::intermediate, b.intermediate(low.width, low.height, TexFormat::rgba32f));
    Pass& down = b.add(PassKind::grid, g.plane, low);
    down.target2 = g.normal;
    down.inputs[SSAO_UNIT_DEPTH] = TexRef::of(Source::depth);
    if (!in.normals_from_depth) down.inputs[SSAO_UNIT_NORMAL] = TexRef::of(Source::normal);
    down.scale = scale;
    down.variant = host_input_variant(in) | (in.normals_from_depth ? variant::normals_from_depth : 0u) |
                   grid_pick_variant(in);
    down.sample_index = in.sample_index;
    return g;
}

// On the grid: [grid pass ->] AO -> [blur x -> [blur y]], ceil(w/scale) x
// ceil(h/scale) (the last block of an odd size is partial, never dropped).
// Below full resolution every blur kind is made depth-aware there and a
// depth-aware upsample writes every viewport pixel of the output; at full
// resolution the last pass writes the output itself.
void plan_sampling(Builder& b, const ssao_settings& s, const AnalysedInputs& in, const TexRef& output,
                   const Rect& final_rect) {
    const int scale = resolution_scale(s);
    const int vw = in.viewport[2], vh = in.viewport[3];
    const int lw = (vw + scale - 1) / scale, lh = (vh + scale - 1) / scale;
    const Rect low{0, 0, lw, lh};
    const bool reduced = scale > 1;
    const bool blur = s.blur != SSAO_BLUR_NONE;
    const bool separable = blur && s.blur != SSAO_BLUR_BOX_4X4;
    const PassKind estimator = s.method == SSAO_METHOD_VISIBILITY ? PassKind::visibility : PassKind::kernel;

    // The visibility march reads one plane texel per step (grid.frag), which
    // is cheaper than the host's depth through the inverse projection and a
    // normal, so it runs on the grid at full resolution too. The kernel reads
    // the host's textures there unless the depth-aware blur follows, which
    // tests its taps against the grid's tangent planes (blur.frag).
    const bool grid = reduced || in.multisample || in.normals_from_depth || estimator == PassKind::visibility ||
                      s.blur == SSAO_BLUR_DEPTH_AWARE;
    const GridTextures grid_tex = grid ? add_grid_pass(b, in, scale, low) : GridTextures{};

    // Where the last pass on the grid writes: the output at full resolution,
    // else an intermediate for the upsample.
    const bool last_is_ao = !blur;
    const bool ao_to_output = !reduced && last_is_ao;
    // Read from the grid, the AO texture also carries the plane's screen
    // gradient (ao_texture.glsl), which the blur's and the upsample's depth
    // tests read.
    const TexFormat ao_format = grid ? TexFormat::rgba32f : TexFormat::rg32f;
    const TexRef ao_target =
        ao_to_output ? output : TexRef::of(Source::intermediate, b.intermediate(lw, lh, ao_format));
    Pass& ao = b.add(estimator, ao_target, ao_to_output ? final_rect : low);
    ao.inputs[SSAO_UNIT_DEPTH] = grid ? grid_tex.plane : TexRef::of(Source::depth);
    ao.inputs[SSAO_UNIT_NORMAL] = grid ? grid_tex.normal : TexRef::of(Source::normal);
    ao.inputs[SSAO_UNIT_NOISE] = TexRef::of(Source::noise);
    ao.scale = scale;
    ao.variant = (grid ? variant::grid_input : 0u) | sampling_feature_variant(s, in);

    // The blurs read the AO and its view z from the intermediates only.
    TexRef low_ao = ao_target;
    if (blur) {
        const bool x_to_output = !reduced && !separable;
        const TexRef x_target =
            x_to_output ? output : TexRef::of(Source::intermediate, b.intermediate(lw, lh, ao_format));
        Pass& bx = b.add(PassKind::blur_x, x_target, x_to_output ? final_rect : low);
        bx.inputs[SSAO_UNIT_AO] = ao_target;
        bx.direction[0] = 1;
        bx.depth_aware = reduced;
        bx.scale = scale;
        bx.variant = grid_pick_variant(in);
        low_ao = x_target;
        if (separable) {
            // Below full resolution back into the estimator's texture: its
            // contents are no longer needed.
            const TexRef y_target = reduced ? ao_target : output;
            Pass& by = b.add(PassKind::blur_y, y_target, reduced ? low : final_rect);
            by.inputs[SSAO_UNIT_AO] = x_target;
            by.direction[1] = 1;
            by.depth_aware = reduced;
            by.scale = scale;
            by.variant = grid_pick_variant(in);
            low_ao = y_target;
        }
    }
    if (!reduced) return;

    Pass& up = b.add(PassKind::upsample, output, final_rect);
    up.inputs[SSAO_UNIT_DEPTH] = TexRef::of(Source::depth);
    up.inputs[SSAO_UNIT_AO] = low_ao;
    up.scale = scale;
    // A host that averages frames (a moving frame index) averages the grid's
    // noise away and would see what the weighted mean leaves: the picked
    // pixels' checkerboard puts the four taps on a skewed quad, whose mean
    // reads a soft gradient at the wrong place, a diagonal stripe every two
    // blocks. A plane through the taps reads it at the pixel; for one frame
    // the noise hides the stripes and the fit would buy nothing for its time.
    up.variant = host_input_variant(in) | grid_pick_variant(in) |
                 (in.frame_index != 0 ? variant::upsample_plane_fit : 0u);
    up.sample_index = in.sample_index;
}

// Debug views RAW_AO and BLUR_WEIGHTS (settings.debug_view): the same passes
// as the AO, with the last one writing what the view shows. Returns false for
// the views this function does not plan. The upsample below full resolution
// takes each pixel's own grid texel (variant UPSAMPLE_NEAREST): the view shows
// what the grid holds, not what depth weights make of it.
//   RAW_AO: planned as blur NONE, so at full resolution it is exactly the
//     output with blur NONE.
//   BLUR_WEIGHTS: the blurs run as variant BLUR_WEIGHTS and write the share
//     of their gaussian weight that passed the depth test (blur.frag); with
//     blur NONE there is nothing to weigh and the output is cleared to 1.
bool plan_ao_debug_view(Builder& b, const ssao_settings& s, const AnalysedInputs& in, const TexRef& output,
                        const Rect& final_rect, FramePlan& plan) {
    const bool raw = s.debug_view == SSAO_DEBUG_VIEW_RAW_AO;
    if (!raw && s.debug_view != SSAO_DEBUG_VIEW_BLUR_WEIGHTS) return false;
    if (!raw && s.blur == SSAO_BLUR_NONE) {
        b.add(PassKind::clear, output, final_rect);
        return true;
    }
    ssao_settings planned = s;
    if (raw) planned.blur = SSAO_BLUR_NONE;
    plan_sampling(b, planned, in, output, final_rect);
    for (int i = 0; i < plan.pass_count; ++i) {
        Pass& p = plan.passes[i];
        if (p.kind == PassKind::upsample) p.variant = (p.variant & ~variant::upsample_plane_fit) | variant::upsample_nearest;
        if (p.kind == PassKind::blur_x || p.kind == PassKind::blur_y) p.variant |= variant::blur_weights;
    }
    add_sky_tests(b, plan, in, final_rect);
    return true;
}

// The debug views NORMALS and RECONSTRUCTED_NORMALS: the grid pass at full
// resolution (RECONSTRUCTED: rebuilding normals from depth whatever the
// inputs), then the view pass writing the grid's normal packed into RGB.
// False, planning nothing, for every other view.
bool plan_normals_view(Builder& b, const ssao_settings& s, const AnalysedInputs& in, const TexRef& output,
                       const Rect& final_rect) {
    if (!writes_normals(s)) return false;
    AnalysedInputs grid_in = in;
    if (s.debug_view == SSAO_DEBUG_VIEW_RECONSTRUCTED_NORMALS) grid_in.normals_from_depth = true;
    const GridTextures grid = add_grid_pass(b, grid_in, 1, Rect{0, 0, in.viewport[2], in.viewport[3]});
    Pass& view = b.add(PassKind::normals_view, output, final_rect);
    view.inputs[SSAO_UNIT_DEPTH] = grid.plane;
    view.inputs[SSAO_UNIT_NORMAL] = grid.normal;
    view.variant = variant::grid_input;
    return true;
}

}  // namespace

bool writes_normals(const ssao_settings& s) {
    return s.debug_view == SSAO_DEBUG_VIEW_NORMALS || s.debug_view == SSAO_DEBUG_VIEW_RECONSTRUCTED_NORMALS;
}

uint32_t FramePlan::passes_run() const {
    uint32_t bits = 0;
    for (int i = 0; i < pass_count; ++i) bits |= pass_info(passes[i].kind).bit;
    return bits;
}

FramePlan plan_frame(const ssao_settings& s, const AnalysedInputs& in) {
    FramePlan plan;
    const int vw = in.viewport[2], vh = in.viewport[3];
    plan.owned_output = in.output_texture == 0;
    plan.output_width = vw;
    plan.output_height = vh;
    plan.output_format = output_format_of(s);
    // The host's texture is written at the viewport's own rectangle; the
    // library's is viewport-sized, texel (0,0) = viewport pixel (x,y).
    plan.output_origin[0] = plan.owned_output ? 0 : in.viewport[0];
    plan.output_origin[1] = plan.owned_output ? 0 : in.viewport[1];
    const TexRef output = TexRef::of(Source::output);
    const Rect final_rect{plan.output_origin[0], plan.output_origin[1], vw, vh};
    plan.viewport = Rect{in.viewport[0], in.viewport[1], vw, vh};
    plan.sky_depth = in.proj.sky_depth;

    Builder b(plan);
    if (plan_normals_view(b, s, in, output, final_rect)) return plan;
    if (s.strength == SSAO_STRENGTH_OFF) {
        // Multiplying the host's image by 1 changes nothing: no pass at all
        // (passes_run 0, the host's texture untouched). A debug view
        // overwrites whatever the output mode (ssao.h): its 1s are cleared.
        if (in.multiply_output && s.debug_view == SSAO_DEBUG_VIEW_NONE) return plan;
        // Strength 0: no sampling at all, the output is exactly 1.
        b.add(PassKind::clear, output, final_rect);
        return plan;
    }
    if (plan_ao_debug_view(b, s, in, output, final_rect, plan)) return plan;
    plan_sampling(b, s, in, output, final_rect);
    // Multiply mode: the one pass that writes the output blends into it.
    if (in.multiply_output)
        for (int i = 0; i < plan.pass_count; ++i)
            if (plan.passes[i].target == output) plan.passes[i].multiply = true;
    add_sky_tests(b, plan, in, final_rect);
    return plan;
}

}  // namespace ssao_impl
