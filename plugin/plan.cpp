// plan.cpp - plan_frame: which passes run, in which order, reading what and
// writing where. The only place that decides the pass sequence.
#include "plan.h"

#include "settings.h"

namespace ssao_impl {

namespace {

using Source = TexRef::Source;

TexFormat output_format_of(const ssao_settings& s) {
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

    // A pass writing `target` over the rectangle `rect` of it.
    Pass& add(PassKind kind, ProgramId program, TexRef target, const Rect& rect) {
        Pass& p = plan_.passes[plan_.pass_count++];
        p = Pass{};
        p.kind = kind;
        p.program = program;
        p.target = target;
        p.rect = rect;
        p.pack_depth = target.source == Source::intermediate;
        return p;
    }

private:
    FramePlan& plan_;
};

// Below full resolution: downsample -> AO -> [blur x -> [blur y]] on the
// reduced grid, ceil(w/scale) x ceil(h/scale) (the last block of an odd size
// is partial, never dropped; every blur kind is made depth-aware there) ->
// depth-aware upsample into the output, which writes every viewport pixel.
void plan_reduced(Builder& b, int scale, ProgramId estimator, bool blur, bool separable, int vw, int vh,
                  const TexRef& output, const Rect& final_rect) {
    const int lw = (vw + scale - 1) / scale, lh = (vh + scale - 1) / scale;
    const Rect low{0, 0, lw, lh};

    const TexRef grid = TexRef::of(Source::intermediate, b.intermediate(lw, lh, TexFormat::rgba32f));
    Pass& down = b.add(PassKind::downsample, ProgramId::downsample, grid, low);
    down.inputs[SSAO_UNIT_DEPTH] = TexRef::of(Source::depth);
    down.inputs[SSAO_UNIT_NORMAL] = TexRef::of(Source::normal);
    down.scale = scale;

    // The sampling pass reads depth and normal from the grid on both units.
    const TexRef ao_target = TexRef::of(Source::intermediate, b.intermediate(lw, lh, TexFormat::rg32f));
    Pass& ao = b.add(PassKind::ao, estimator, ao_target, low);
    ao.inputs[SSAO_UNIT_DEPTH] = grid;
    ao.inputs[SSAO_UNIT_NORMAL] = grid;
    ao.inputs[SSAO_UNIT_NOISE] = TexRef::of(Source::noise);
    ao.scale = scale;

    TexRef low_ao = ao_target;
    if (blur) {
        const TexRef x_target = TexRef::of(Source::intermediate, b.intermediate(lw, lh, TexFormat::rg32f));
        Pass& bx = b.add(PassKind::blur_x, ProgramId::blur, x_target, low);
        bx.inputs[SSAO_UNIT_AO] = ao_target;
        bx.direction[0] = 1;
        bx.depth_aware = true;
        low_ao = x_target;
        if (separable) {
            // Back into the AO pass's texture: its contents are no longer needed.
            Pass& by = b.add(PassKind::blur_y, ProgramId::blur, ao_target, low);
            by.inputs[SSAO_UNIT_AO] = x_target;
            by.direction[1] = 1;
            by.depth_aware = true;
            low_ao = ao_target;
        }
    }

    Pass& up = b.add(PassKind::upsample, ProgramId::upsample, output, final_rect);
    up.inputs[SSAO_UNIT_DEPTH] = TexRef::of(Source::depth);
    up.inputs[SSAO_UNIT_AO] = low_ao;
    up.scale = scale;
}

}  // namespace

uint32_t FramePlan::passes_run() const {
    uint32_t bits = 0;
    for (int i = 0; i < pass_count; ++i) bits |= static_cast<uint32_t>(passes[i].kind);
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
    const Rect full{0, 0, vw, vh};

    Builder b(plan);
    if (s.strength == SSAO_STRENGTH_OFF) {
        // Strength 0: no sampling at all, the output is exactly 1.
        b.add(PassKind::clear, ProgramId::none, output, final_rect);
        return plan;
    }
    const bool blur = s.blur != SSAO_BLUR_NONE;
    const bool separable = blur && s.blur != SSAO_BLUR_BOX_4X4;
    const ProgramId estimator = s.method == SSAO_METHOD_VISIBILITY ? ProgramId::visibility : ProgramId::ao;
    const int scale = resolution_scale(s);
    if (scale > 1) {
        plan_reduced(b, scale, estimator, blur, separable, vw, vh, output, final_rect);
        return plan;
    }

    // AO -> [blur x -> [blur y]] -> output. Intermediates hold (ao, view z) at
    // the viewport's size, texel (0,0) = viewport pixel (x,y).
    const TexRef ao_target = blur ? TexRef::of(Source::intermediate, b.intermediate(vw, vh, TexFormat::rg32f)) : output;
    Pass& ao = b.add(PassKind::ao, estimator, ao_target, blur ? full : final_rect);
    ao.inputs[SSAO_UNIT_DEPTH] = TexRef::of(Source::depth);
    ao.inputs[SSAO_UNIT_NORMAL] = TexRef::of(Source::normal);
    ao.inputs[SSAO_UNIT_NOISE] = TexRef::of(Source::noise);
    if (!blur) return plan;

    // The blur reads the AO and its view z from the intermediate only.
    const TexRef x_target = separable ? TexRef::of(Source::intermediate, b.intermediate(vw, vh, TexFormat::rg32f))
                                      : output;
    Pass& bx = b.add(PassKind::blur_x, ProgramId::blur, x_target, separable ? full : final_rect);
    bx.inputs[SSAO_UNIT_AO] = ao_target;
    bx.direction[0] = 1;
    if (!separable) return plan;

    Pass& by = b.add(PassKind::blur_y, ProgramId::blur, output, final_rect);
    by.inputs[SSAO_UNIT_AO] = x_target;
    by.direction[1] = 1;
    return plan;
}

const char* pass_name(PassKind kind) {
    switch (kind) {
        case PassKind::clear: return "ssao: clear";
        case PassKind::ao: return "ssao: ao";
        case PassKind::blur_x: return "ssao: blur x";
        case PassKind::blur_y: return "ssao: blur y";
        case PassKind::downsample: return "ssao: downsample";
        case PassKind::upsample: return "ssao: upsample";
    }
    return "ssao: pass";
}

TimingBucket timing_bucket(PassKind kind) {
    switch (kind) {
        case PassKind::clear:
        case PassKind::downsample:
        case PassKind::ao: return TimingBucket::ao;
        case PassKind::blur_x:
        case PassKind::blur_y:
        case PassKind::upsample: return TimingBucket::blur;
    }
    return TimingBucket::ao;
}

}  // namespace ssao_impl
