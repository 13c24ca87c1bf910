// cli.h - ssao-host's command line: every flag, its parsing and validation,
// and the --help text (whose plugin defaults come from the plugin itself).
#pragma once

#include "flags.h"
#include "camera.h"

#include <ssao/ssao.h>

#include <glm/glm.hpp>

#include <optional>
#include <string>
#include <vector>

namespace cli {

enum class DepthFormat { D16, D24, D32F };
enum class NormalSpace { View, World };
enum class NormalFormat { RGBA16F, RGBA8 };

// What the user asked for. Unset optionals mean "let the scene, the camera
// chooser or the plugin decide".
struct Options {
    std::string scene_path;         // empty = the bundled default scene
    bool allow_outside_files = false;  // the scene's buffer URIs may leave its folder (scene_limits.h)
    std::string out_dir = "out";
    std::string plugin_path;        // empty = plugin::Library::search_order()
    int width = 800;
    int height = 600;
    bool gl33 = false;
    int frames = 8;                 // plugin executions to measure GPU times over

    // Camera overrides (--eye --target --fov --near --far --ortho --reverse-z).
    camera::Overrides cam;
    std::optional<DepthFormat> depth_format;   // default d32f

    // G-buffer.
    NormalSpace normal_space = NormalSpace::View;
    NormalFormat normal_format = NormalFormat::RGBA16F;
    bool normals_from_depth = false;  // --normals depth: the plugin gets normal_texture = 0

    // Which outputs.
    bool only_ao = false;
    std::optional<bool> sheet;      // default: on for the full run, off for --only ao

    // Plugin settings (unset = preset / scene hints / plugin default).
    std::optional<ssao_preset> preset;
    std::optional<int> samples;
    std::optional<float> radius, bias, depth_step_bias, power, strength;
    std::optional<ssao_kernel_shape> kernel;
    std::optional<ssao_kernel_distribution> distribution;
    std::optional<ssao_rotation> rotation;
    std::optional<uint32_t> seed;
    std::optional<ssao_blur> blur;
    std::optional<int> blur_radius;
    std::optional<float> blur_sigma, blur_tolerance;
    std::optional<ssao_output_format> output_format;
    std::optional<ssao_resolution> resolution;
    std::optional<ssao_method> method;
    std::optional<float> thickness;  // visibility: view units
    std::optional<int> steps;        // visibility: steps per direction
    std::optional<float> max_step_texels;  // visibility: longest step on screen, sampling-grid texels
    // Distance fade (view depth; --fade-end 0 turns a scene hint's fade
    // off) and the radius in viewport pixels (0 = off).
    std::optional<float> fade_start, fade_end, radius_pixels;
    // inputs.frame_index of the first frame (0 = the fixed noise), and
    // how many consecutive frame indices ao.png/ao.exr average (1 = none).
    uint32_t frame_index = 0;
    int accumulate = 1;
    // --debug-view: what the extra execute writes into debug_view.png (none:
    // no extra execute, no file). Names: debug_view_text.h.
    ssao_debug_view debug_view = SSAO_DEBUG_VIEW_NONE;

    // MSAA inputs and the multiply output mode.
    int msaa = 0;                    // > 1: the plugin reads a G-buffer rendered with this many samples
    uint32_t sample_index = 0;       // the sample it reads, < msaa
    bool output_multiply = false;    // lit_ao.png: the plugin multiplies AO into the lit image
};

using ParseResult = flags::Outcome;

// Parses argv. On Error, `error` holds one sentence naming the flag and the
// problem. "--flag value" and "--flag=value" are both accepted.
ParseResult parse(int argc, const char* const* argv, Options& out, std::string& error);

// The --help text. `defaults` are the plugin's resolved defaults (a zeroed
// ssao_settings through resolve_settings), or nullptr when the plugin could not
// be loaded, in which case the plugin's defaults are shown as unavailable.
// presets: the four presets (LOW..ULTRA) resolved by the plugin, or null.
std::string help_text(const ssao_settings* defaults, const std::string& default_scene,
                      const ssao_settings* presets = nullptr);

// Names as the flags spell them (also used in the printed summary).
const char* name(ssao_kernel_shape v);
const char* name(ssao_kernel_distribution v);
const char* name(ssao_rotation v);
const char* name(ssao_blur v);
const char* name(ssao_output_format v);
const char* name(ssao_resolution v);
const char* name(ssao_method v);
const char* name(DepthFormat v);
// Parses a --blur name ("depth-aware", "box", "gaussian", "none"); used for
// scene hints too.
std::optional<ssao_blur> parse_blur(const std::string& s);

}  // namespace cli
