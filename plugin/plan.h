// plan.h - the frame plan: a pure function from (resolved settings, analysed
// inputs) to the ordered passes of one execute and the intermediate textures
// they need. No GL here: the plan is unit tested without a context
// (tests/unit/test_plan*.cpp), and everything that touches GL reads it:
//   resources.cpp (allocates the plan's intermediates, masks and the owned output),
//   runner.cpp    (binds what each pass declares, draws, one timestamp per pass),
//   timers.cpp    (per-pass GPU times).
// What a pass is called, which bit and timing figure it reports and which
// program it draws with is its row in pass_table.cpp; how to add one is told
// in pass_table.h. Per-pass values a shader reads (target origin, packing,
// direction, grid scale) are fields of Pass that pass_uniforms.cpp sets in
// every program that declares them. A feature that is off by default is a
// variant bit (namespace variant below).
// Limits to know: a pass samples at most SSAO_UNITS_USED (4) units, the ones
// the state guard saves and the ABI documents; an intermediate of a new
// format needs its TexFormat here and its GL triple in resources.cpp
// (gl_format); a pass writes one colour target, or two (target2).
#pragma once

#include "inputs.h"
#include "uniforms.h"  // SSAO_UNIT_* and SSAO_UNITS_USED (shaders/ssao_constants.h)

#include <ssao/ssao.h>

#include <cstdint>

namespace ssao_impl {

// Pass and intermediate limits of one frame. kMaxPasses is the ABI's
// SSAO_MAX_PASSES: ssao_timings has room for that many per-pass times.
constexpr int kMaxPasses = SSAO_MAX_PASSES;
constexpr int kMaxIntermediates = 4;
// Depth textures a pass tests (DepthUse): the grid's sky mask and the copy of the host's depth.
constexpr int kMaxMasks = 2;

// What a pass does: an index into the pass table (pass_table.cpp), which
// gives its name, its public ssao_pass bit and its program.
enum class PassKind : uint8_t {
    clear,         // strength 0: the output's rectangle cleared to 1, nothing sampled
    grid,          // one picked texel's view z and normal per block (every pixel at full resolution)
    kernel,        // the point-kernel occlusion estimator (method KERNEL, any kernel_shape)
    visibility,    // the occlusion estimator marching directions (method VISIBILITY)
    normals_view,  // the debug views NORMALS and RECONSTRUCTED_NORMALS: the grid's normal packed into RGB
    blur_x,        // horizontal blur (or the box blur's single pass)
    blur_y,        // vertical blur
    upsample,      // reduced resolution: depth-aware upsample to every viewport pixel
    count
};

// The compiled programs (one per shader file; the two blurs share one). The
// clear pass draws nothing (none). sky_fill is no pass's own: the runner
// draws it inside every pass that fills the sky (Pass::fills_sky).
enum class ProgramId : int8_t { none = -1, grid, kernel, visibility, normals_view, blur, upsample, sky_fill, count };

// Compile-time variants of a program. Each bit is a feature that is off by
// default and free when off: its shader code sits behind `#ifdef SSAO_<NAME>`
// (shader_source.cpp adds the defines), so a plan that does not ask for it
// runs not one instruction or branch of it. The runner compiles a variant the
// first time a plan uses it (program_cache.cpp); each program's base variant
// (ProgramInfo::base_variant, pass_table.cpp) is compiled at create_context. A new bit: a constant here, its name in
// kVariantNames (shader_source.cpp), the #ifdef code, and the plan sets it.
namespace variant {
constexpr uint32_t grid_input = 1u << 0;          // GRID_INPUT: the sampling pass reads the prepared grid (depth,
                                                  // normal) instead of the host's depth and normal textures
constexpr uint32_t multisample = 1u << 1;         // MULTISAMPLE: the host's depth/normal are sampler2DMS, sample u_sample_index
constexpr uint32_t normals_from_depth = 1u << 2;  // NORMALS_FROM_DEPTH: the grid pass rebuilds normals from depth
constexpr uint32_t fade = 1u << 3;                // FADE: AO fades to 1 between fade_start and fade_end
constexpr uint32_t radius_pixels = 1u << 4;       // RADIUS_PIXELS: per-pixel radius from radius_pixels
constexpr uint32_t frame_noise = 1u << 5;         // FRAME_NOISE: rotation and jitter move with frame_index, and
                                                  // below full resolution the grid's picked pixels swap corners
constexpr uint32_t blur_weights = 1u << 6;        // BLUR_WEIGHTS: the blur writes its accepted weight share
constexpr uint32_t upsample_nearest = 1u << 7;    // UPSAMPLE_NEAREST: the upsample takes the pixel's own grid texel,
                                                  // no depth weights (debug views RAW_AO and BLUR_WEIGHTS)
constexpr uint32_t unorm_depth = 1u << 8;         // UNORM_DEPTH: the host's depth is unorm (D16, D24): a depth-format
                                                  // step is the format's fixed step, not a float's ulp
constexpr uint32_t step_texels = 1u << 9;         // STEP_TEXELS: the visibility march's step count follows the
                                                  // radius on screen (max_step_texels)
constexpr uint32_t upsample_plane_fit = 1u << 10; // UPSAMPLE_PLANE_FIT: the upsample fits a plane through its taps
                                                  // (frame_index != 0: a TAA host's mean shows no checkerboard)
constexpr int kBits = 11;
}  // namespace variant

// Formats of the textures the plan renders into.
enum class TexFormat : uint8_t {
    rg32f,  // intermediate: (ao, view z) for the next pass, where the sampling pass reads no grid
    rgba32f,  // intermediate: the grid pass's plane texel (view z, SKY_Z for the sky; depth gradient;
              // grazing cosine) and its view-space normal (xyz, 0) per block; where the sampling
              // pass reads the grid also the AO texture (ao, view z, the plane's gradient) for the
              // blur and the upsample
    r8,     // owned output, SSAO_OUTPUT_R8
    r16f,   // owned output, SSAO_OUTPUT_R16F
    rgba8,  // owned output of the normal debug views: n * 0.5 + 0.5 in RGB, alpha 1
    // Depth formats (DepthUse): the grid's sky mask (d16), and the copy of
    // the host's depth in the host's own format (a blit copies depth only
    // between matching formats).
    d16,
    d24,
    d24s8,
    d32f,
    d32fs8,
};

// How a pass uses its depth attachment. A sky pixel's output is a constant
// (the AO texture's sky value, or 1), so a depth test can reject it before
// its fragment shader runs: a software rasteriser (llvmpipe) skips a batch
// of pixels whose depth test fails, but not one whose shader returns early,
// and a GPU skips whole tiles by their depth range. The pixels a tested pass
// skips get the sky's value (Pass::fills_sky) as FramePlan::sky_fill says.
// The host's depth is copied for a test at the output only on a software
// rasteriser (AnalysedInputs::software_rasterizer): a GPU's SIMD groups of
// sky pixels already leave its shaders early, and there the copy cost more
// than it saved (docs/benchmark.md, "Sky skipped by a depth test").
enum class DepthUse : uint8_t {
    none,             // no depth attachment, no depth test
    write_grid_mask,  // the grid pass: writes the grid's sky mask, 1 at sky texels, 0 elsewhere
    grid_mask,        // runs where the grid's sky mask is 0
    depth_copy,       // runs where the host's depth, copied into depth_target (once per frame, before the
                      // first pass that tests it), is not the sky's (FramePlan::sky_depth)
};

// How a tested pass's skipped pixels get the sky's value. A software
// rasteriser clears the target first: a clear is a memset there, while a
// draw rasterises every block of the rectangle even where its test fails. A
// GPU draws the sky fill (shaders/sky_fill.frag) with the complementary
// test: it rejects the tiles without sky before any fragment runs, while a
// clear of a 32-bit float target to the sky's value writes every texel (on
// an NVIDIA H200 the clears cost more than the sky test saved).
enum class SkyFill : uint8_t {
    clear,  // the pass's rectangle of its target cleared before the pass draws
    draw,   // the sky fill drawn where the pass's depth test fails
};

// A texture a pass samples or renders into.
struct TexRef {
    enum class Source : uint8_t {
        none,          // nothing (an input unit the pass leaves unbound)
        depth,         // the host's depth texture
        normal,        // the host's normal texture
        noise,         // the library's rotation-noise texture
        intermediate,  // FramePlan::intermediates[index]
        mask,          // FramePlan::masks[index]: a depth texture, only ever a pass's depth_target
        output,        // the final output: the host's output_texture or the library's own
    };
    Source source = Source::none;
    int index = 0;  // intermediates and masks

    static TexRef of(Source s, int i = 0) { return TexRef{s, i}; }
    bool operator==(const TexRef& o) const { return source == o.source && index == o.index; }
    bool operator!=(const TexRef& o) const { return !(*this == o); }
};

struct Rect {
    int x = 0, y = 0, width = 0, height = 0;
};

struct Pass {
    PassKind kind = PassKind::clear;  // its program: program_of(kind) (pass_table.h)
    // What the pass samples, by texture unit (SSAO_UNIT_*). The runner binds
    // these; a unit left `none` keeps what it holds unless that is unknown
    // (the host's) or the pass's own target, which it unbinds, so a pass never
    // samples the texture it renders into.
    TexRef inputs[SSAO_UNITS_USED] = {};
    TexRef target;
    // A second colour target (attachment 1, fragment output location 1) or
    // none: the grid pass writes its view z and its normal in one draw.
    TexRef target2;
    // The depth attachment (a mask, or none) and what the pass does with it.
    TexRef depth_target;
    DepthUse depth = DepthUse::none;
    Rect rect;               // where it draws in its target: origin and size, in target texels
    bool pack_depth = false; // writes (ao, view z) for a following pass instead of the final AO
    int direction[2] = {0, 0};  // blur direction (u_blur_dir)
    // Viewport pixels per texel of the reduced grid (u_scale: 1, 2 or 4):
    // the grid the sampling pass reads (1: the host's textures, else the
    // grid pass's intermediate), the grid the grid pass writes, the grid
    // the upsample reads, the grid a blur runs on (its taps' offsets in
    // viewport pixels).
    int scale = 1;
    // Blurs: weigh taps by depth similarity whatever the blur kind
    // (u_depth_aware). Set below full resolution, where a blurred grid texel
    // spans several pixels and the upsample could not undo a leak.
    bool depth_aware = false;
    uint32_t variant = 0;  // bits of `variant::`: which compiled variant of its program runs
    // Variant MULTISAMPLE: the sample of the host's multisampled depth
    // and normal this pass reads at every pixel (u_sample_index).
    int sample_index = 0;
    // Output mode MULTIPLY: the pass writes the host's lit image through
    // blending, rgb = dst.rgb * src.rgb, alpha kept (the runner sets the blend;
    // the shader writes AO to rgb as in overwrite mode).
    bool multiply = false;

    // Whether the pixels the pass's depth test skips get what the pass
    // writes at the sky ((1, SKY_Z, 0, 0) when it packs depth, else 1), as
    // FramePlan::sky_fill says: every sky-tested pass, except one that
    // multiplies into the host's image (a multiply by 1 changes nothing).
    bool fills_sky() const {
        return (depth == DepthUse::grid_mask || depth == DepthUse::depth_copy) && !multiply;
    }
};

// A texture the plan renders into and a later pass samples (or, for a
// mask, tests).
struct Intermediate {
    int width = 0, height = 0;
    TexFormat format = TexFormat::rg32f;
};

struct FramePlan {
    Pass passes[kMaxPasses] = {};
    int pass_count = 0;
    Intermediate intermediates[kMaxIntermediates] = {};
    int intermediate_count = 0;
    Intermediate masks[kMaxMasks] = {};  // of a depth format
    int mask_count = 0;
    // The final output: the host's texture at the viewport's origin, or the
    // library's own (owned_output) of output_width x output_height and output_format at (0,0).
    bool owned_output = true;
    int output_width = 0, output_height = 0;
    TexFormat output_format = TexFormat::r8;
    int output_origin[2] = {0, 0};
    // DepthUse::depth_copy: the rectangle of the host's depth that is copied
    // (the viewport), to the tested pass's rectangle; the sky's depth value.
    Rect viewport;
    float sky_depth = 1.0f;
    SkyFill sky_fill = SkyFill::draw;  // how Pass::fills_sky is done

    // ssao_output.passes_run: the bits of the passes in the plan.
    uint32_t passes_run() const;
};

// The plan for one execute. Pure: the same arguments give the same plan.
FramePlan plan_frame(const ssao_settings& resolved, const AnalysedInputs& in);

// Whether the settings ask for a normals debug view (NORMALS or
// RECONSTRUCTED_NORMALS), whose output is x, y, z in red, green and blue.
bool writes_normals(const ssao_settings& s);

// The group around a whole execute; each pass has its own inside it
// (pass_table.cpp).
constexpr const char* kExecuteGroupName = "ssao";

}  // namespace ssao_impl
