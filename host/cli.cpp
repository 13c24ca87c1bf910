#include "cli.h"

#include "debug_view_text.h"
#include "preset_text.h"

#include "camera.h"
#include "camera_flags.h"
#include "flags.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <map>
#include <sstream>

namespace cli {

namespace {

using flags::fail;
using flags::quoted;

template <typename T>
T parse_choice(const std::string& flag, const std::string& text, const std::vector<std::pair<const char*, T>>& choices) {
    std::string list;
    for (const auto& c : choices) {
        if (text == c.first) return c.second;
        list += std::string(list.empty() ? "" : "|") + c.first;
    }
    fail(flag + " expects one of " + list + ", got " + quoted(text));
}

const std::vector<std::pair<const char*, ssao_kernel_shape>> kKernels = {
    {"hemisphere", SSAO_KERNEL_HEMISPHERE}, {"sphere", SSAO_KERNEL_SPHERE}, {"separable", SSAO_KERNEL_SEPARABLE}};
const std::vector<std::pair<const char*, ssao_kernel_distribution>> kDistributions = {
    {"accelerating", SSAO_DISTRIBUTION_ACCELERATING}, {"uniform", SSAO_DISTRIBUTION_UNIFORM}};
const std::vector<std::pair<const char*, ssao_rotation>> kRotations = {
    {"gradient", SSAO_ROTATION_GRADIENT_NOISE},
    {"noise", SSAO_ROTATION_NOISE_4X4},
    {"hash", SSAO_ROTATION_HASH},
    {"none", SSAO_ROTATION_NONE}};
const std::vector<std::pair<const char*, ssao_blur>> kBlurs = {
    {"depth-aware", SSAO_BLUR_DEPTH_AWARE}, {"box", SSAO_BLUR_BOX_4X4}, {"gaussian", SSAO_BLUR_GAUSSIAN}, {"none", SSAO_BLUR_NONE}};
const std::vector<std::pair<const char*, ssao_output_format>> kOutputs = {
    {"r8", SSAO_OUTPUT_R8}, {"r16f", SSAO_OUTPUT_R16F}};
const std::vector<std::pair<const char*, ssao_resolution>> kResolutions = {
    {"full", SSAO_RESOLUTION_FULL}, {"half", SSAO_RESOLUTION_HALF}, {"quarter", SSAO_RESOLUTION_QUARTER}};
const std::vector<std::pair<const char*, ssao_method>> kMethods = {
    {"kernel", SSAO_METHOD_KERNEL}, {"visibility", SSAO_METHOD_VISIBILITY}};
const std::vector<std::pair<const char*, DepthFormat>> kDepths = {
    {"d16", DepthFormat::D16}, {"d24", DepthFormat::D24}, {"d32f", DepthFormat::D32F}};

template <typename T>
const char* choice_name(T v, const std::vector<std::pair<const char*, T>>& choices) {
    for (const auto& c : choices)
        if (c.second == v) return c.first;
    return "?";
}

// A number with a range, written once for the parser and the help text.
float ranged(const std::string& flag, const std::string& text, double lo, bool lo_open, double hi, bool hi_open) {
    const double v = flags::number(flag, text);
    const bool below = lo_open ? v <= lo : v < lo;
    const bool above = hi_open ? v >= hi : v > hi;
    if (below || above) {
        std::ostringstream r;
        r << (lo_open ? "(" : "[") << lo << ", " << hi << (hi_open ? ")" : "]");
        fail(flag + " " + text + " is out of range " + r.str());
    }
    flags::check_normal_float(flag, text, v);
    return static_cast<float>(v);
}

constexpr double kBig = 1e30;

}  // namespace

const char* name(ssao_kernel_shape v) { return choice_name(v, kKernels); }
const char* name(ssao_kernel_distribution v) { return choice_name(v, kDistributions); }
const char* name(ssao_rotation v) { return choice_name(v, kRotations); }
const char* name(ssao_blur v) { return choice_name(v, kBlurs); }
const char* name(ssao_output_format v) { return choice_name(v, kOutputs); }
const char* name(ssao_method v) { return choice_name(v, kMethods); }
const char* name(ssao_resolution v) { return choice_name(v, kResolutions); }
const char* name(DepthFormat v) { return choice_name(v, kDepths); }

std::optional<ssao_blur> parse_blur(const std::string& s) {
    for (const auto& c : kBlurs)
        if (s == c.first) return c.second;
    return std::nullopt;
}

namespace {

// The flags that take a value, by what they set; each adds its entries to `table`.

void run_flags(flags::Valued& table, Options& o) {
    table.insert({
        {"--out", [&](const std::string& f, const std::string& v) {
             if (v.empty()) fail(f + " expects a directory");
             o.out_dir = v;
         }},
        {"--plugin", [&](const std::string& f, const std::string& v) {
             if (v.empty()) fail(f + " expects a path to libssao.so");
             o.plugin_path = v;
         }},
        {"--width", [&](const std::string& f, const std::string& v) {
             o.width = static_cast<int>(flags::integer(f, v, 1, SSAO_MAX_DIMENSION));
         }},
        {"--height", [&](const std::string& f, const std::string& v) {
             o.height = static_cast<int>(flags::integer(f, v, 1, SSAO_MAX_DIMENSION));
         }},
        {"--frames", [&](const std::string& f, const std::string& v) {
             o.frames = static_cast<int>(flags::integer(f, v, 1, 1000));
         }},
    });
}

void camera_flags(flags::Valued& table, Options& o) {
    table.insert({
        {"--eye", [&](const std::string& f, const std::string& v) { o.cam.eye = flags::vec3(f, v); }},
        {"--target", [&](const std::string& f, const std::string& v) { o.cam.target = flags::vec3(f, v); }},
        {"--fov", [&](const std::string& f, const std::string& v) { o.cam.fov_deg = flags::fov_degrees(f, v); }},
        {"--near", [&](const std::string& f, const std::string& v) { o.cam.znear = ranged(f, v, 0, true, kBig, false); }},
        {"--far", [&](const std::string& f, const std::string& v) { o.cam.zfar = flags::far_plane(f, v); }},
        {"--ortho", [&](const std::string& f, const std::string& v) {
             o.cam.ortho_half_height = ranged(f, v, 0, true, kBig, false);
         }},
    });
}

// What the host's G-buffer holds and how the plugin reads it.
void input_flags(flags::Valued& table, Options& o) {
    table.insert({
        {"--depth", [&](const std::string& f, const std::string& v) { o.depth_format = parse_choice(f, v, kDepths); }},
        {"--normals", [&](const std::string& f, const std::string& v) {
             // depth: the plugin gets no normal texture and rebuilds normals
             // from depth; the G-buffer still stores view-space normals for
             // the lighting and normals.png.
             const int c = parse_choice<int>(f, v, {{"view", 0}, {"world", 1}, {"depth", 2}});
             o.normal_space = c == 1 ? NormalSpace::World : NormalSpace::View;
             o.normals_from_depth = c == 2;
         }},
        {"--normal-format", [&](const std::string& f, const std::string& v) {
             o.normal_format = parse_choice<NormalFormat>(f, v, {{"rgba16f", NormalFormat::RGBA16F}, {"rgba8", NormalFormat::RGBA8}});
         }},
        {"--only", [&](const std::string& f, const std::string& v) {
             o.only_ao = parse_choice<bool>(f, v, {{"ao", true}, {"all", false}});
         }},
        {"--msaa", [&](const std::string& f, const std::string& v) {
             o.msaa = static_cast<int>(flags::integer(f, v, 1, 32));
             // GL rounds a sample count up to one it supports: 3 would run
             // with 4 and report 3. The largest allowed is checked once the
             // context exists.
             if ((o.msaa & (o.msaa - 1)) != 0) fail(f + " " + v + " is not a power of two (1, 2, 4, 8, 16 or 32)");
         }},
        {"--sample-index", [&](const std::string& f, const std::string& v) {
             o.sample_index = static_cast<uint32_t>(flags::integer(f, v, 0, 31));
         }},
        {"--output", [&](const std::string& f, const std::string& v) {
             o.output_multiply = parse_choice<bool>(f, v, {{"overwrite", false}, {"multiply", true}});
         }},
    });
}

// The plugin's settings.
void settings_flags(flags::Valued& table, Options& o) {
    table.insert({
        {"--preset", [&](const std::string& f, const std::string& v) {
             o.preset = preset_text::parse(v);
             if (!o.preset) fail(f + " expects one of " + preset_text::choices() + ", got " + quoted(v));
         }},
        {"--samples", [&](const std::string& f, const std::string& v) {
             o.samples = static_cast<int>(flags::integer(f, v, 1, SSAO_MAX_SAMPLES));
         }},
        {"--radius", [&](const std::string& f, const std::string& v) { o.radius = ranged(f, v, 0, true, kBig, false); }},
        {"--bias", [&](const std::string& f, const std::string& v) { o.bias = ranged(f, v, 0, false, kBig, false); }},
        {"--depth-step-bias", [&](const std::string& f, const std::string& v) {
             o.depth_step_bias = ranged(f, v, 0, false, SSAO_MAX_DEPTH_STEP_BIAS, false);
         }},
        {"--power", [&](const std::string& f, const std::string& v) { o.power = ranged(f, v, 0, true, SSAO_MAX_POWER, false); }},
        {"--strength", [&](const std::string& f, const std::string& v) { o.strength = ranged(f, v, 0, false, SSAO_MAX_STRENGTH, false); }},
        {"--kernel", [&](const std::string& f, const std::string& v) { o.kernel = parse_choice(f, v, kKernels); }},
        {"--distribution", [&](const std::string& f, const std::string& v) {
             o.distribution = parse_choice(f, v, kDistributions);
         }},
        {"--rotation", [&](const std::string& f, const std::string& v) { o.rotation = parse_choice(f, v, kRotations); }},
        {"--seed", [&](const std::string& f, const std::string& v) {
             o.seed = static_cast<uint32_t>(flags::integer(f, v, 0, 4294967295LL));
         }},
        {"--blur", [&](const std::string& f, const std::string& v) { o.blur = parse_choice(f, v, kBlurs); }},
        {"--blur-radius", [&](const std::string& f, const std::string& v) {
             o.blur_radius = static_cast<int>(flags::integer(f, v, 1, SSAO_MAX_BLUR_RADIUS));
         }},
        {"--blur-sigma", [&](const std::string& f, const std::string& v) { o.blur_sigma = ranged(f, v, 0, true, SSAO_MAX_BLUR_SIGMA, false); }},
        {"--blur-tolerance", [&](const std::string& f, const std::string& v) {
             o.blur_tolerance = ranged(f, v, 0, true, 1, false);
         }},
        {"--output-format", [&](const std::string& f, const std::string& v) { o.output_format = parse_choice(f, v, kOutputs); }},
        {"--resolution", [&](const std::string& f, const std::string& v) { o.resolution = parse_choice(f, v, kResolutions); }},
        {"--method", [&](const std::string& f, const std::string& v) { o.method = parse_choice(f, v, kMethods); }},
        {"--thickness", [&](const std::string& f, const std::string& v) { o.thickness = ranged(f, v, 0, true, kBig, false); }},
        {"--steps", [&](const std::string& f, const std::string& v) {
             o.steps = static_cast<int>(flags::integer(f, v, 1, SSAO_MAX_STEPS));
         }},
        {"--max-step-texels", [&](const std::string& f, const std::string& v) {
             o.max_step_texels = ranged(f, v, 0, false, SSAO_MAX_STEP_TEXELS, false);
         }},
        {"--fade-start", [&](const std::string& f, const std::string& v) { o.fade_start = ranged(f, v, 0, false, kBig, false); }},
        {"--fade-end", [&](const std::string& f, const std::string& v) { o.fade_end = ranged(f, v, 0, false, kBig, false); }},
        {"--radius-pixels", [&](const std::string& f, const std::string& v) {
             o.radius_pixels = ranged(f, v, 0, false, SSAO_MAX_DIMENSION, false);
         }},
        {"--frame-index", [&](const std::string& f, const std::string& v) {
             o.frame_index = static_cast<uint32_t>(flags::integer(f, v, 0, 4294967295LL));
         }},
        {"--accumulate", [&](const std::string& f, const std::string& v) {
             o.accumulate = static_cast<int>(flags::integer(f, v, 1, 1024));
         }},
        {"--debug-view", [&](const std::string& f, const std::string& v) {
             const auto view = debug_view_text::parse(v);
             if (!view) fail(f + " expects one of " + debug_view_text::choices() + ", got " + quoted(v));
             o.debug_view = *view;
         }},
    });
}

}  // namespace

ParseResult parse(int argc, const char* const* argv, Options& o, std::string& error) {
    flags::Valued valued;
    run_flags(valued, o);
    camera_flags(valued, o);
    input_flags(valued, o);
    settings_flags(valued, o);
    // Flags without a value.
    const flags::Switches switches = {
        {"--gl33", [&] { o.gl33 = true; }},
        {"--reverse-z", [&] { o.cam.reverse_z = true; }},
        {"--sheet", [&] { o.sheet = true; }},
        {"--allow-outside-files", [&] { o.allow_outside_files = true; }},
        {"--no-sheet", [&] { o.sheet = false; }},
    };

    return flags::parse(argc, argv, valued, switches, o.scene_path, error, [&] {
        flags::check_camera(o.cam);
        if (o.sample_index > 0 && static_cast<int>(o.sample_index) >= std::max(o.msaa, 1))
            fail("--sample-index " + std::to_string(o.sample_index) + " needs --msaa N with N > " +
                 std::to_string(o.sample_index) + " (a pixel has samples 0..N-1)");
    });
}

// One line per preset, from what the plugin returns (preset_text.h).
static std::string preset_lines(const ssao_settings* presets) {
    if (!presets) return "                          (presets unknown: the plugin could not be loaded)\n";
    std::string out;
    for (int i = 0; i < preset_text::kPresetCount; ++i) {
        std::string n = preset_text::name(preset_text::kPresetOrder[i]);
        n.resize(8, ' ');
        out += "                            " + n + preset_text::describe(presets[i]) + "\n";
    }
    return out;
}

std::string help_text(const ssao_settings* d, const std::string& default_scene, const ssao_settings* presets) {
    auto def = [&](const std::function<std::string(const ssao_settings&)>& f) -> std::string {
        return d ? f(*d) : std::string("unknown: the plugin could not be loaded");
    };
    auto num = [](double v) {
        std::ostringstream s;
        s << v;
        return s.str();
    };
    std::ostringstream h;
    h << "usage: ssao-host [SCENE.gltf|SCENE.glb] [flags]\n"
         "\n"
         "Renders a glTF scene headless (EGL), runs the SSAO plugin on its depth and normals\n"
         "and writes pictures with and without ambient occlusion.\n"
         "Without a scene it renders " << default_scene << ".\n"
         "\n"
         "Output\n"
         "  --out DIR               output directory (default out)\n"
         "  --only ao|all           ao: only ao.png and ao.exr, no lighting pass (default all)\n"
         "  --sheet / --no-sheet    the E/R/T/Y/U mode sheet modes.png (default: on for all, off for --only ao)\n"
         "  --width N, --height N   image size, 1..16384 (default 800 x 600)\n"
         "  --frames N              plugin executions before reading GPU times, 1..1000 (default 8)\n"
         "  --plugin PATH           libssao.so to load (default $SSAO_PLUGIN, else ../lib/libssao.so.1 beside\n"
         "                          the program, else the build tree's, else the system's; docs/install.md, \"Finding the plugin\")\n"
         "  --gl33                  ask for a GL 3.3 core context (default 4.5 core)\n"
         "  --allow-outside-files   let the scene's buffer URIs name files outside its folder (absolute\n"
         "                          paths, '..', symbolic links leading out); refused by default\n"
         "\n"
         "Camera (default: the scene's camera, else framed from the scene bounds; without a scene argument,\n"
         "the bundled view of the cow, eye 2.3,1.6,-2.6 and target 0,0.65,0. ssao-reference and ssao-viewer\n"
         "start from the same camera; ao.exr records it for ssao-error)\n"
         "  --eye x,y,z --target x,y,z\n"
         "  --fov DEG               vertical field of view, (0, 180)\n"
         "  --near N --far F        clip planes; --far inf for an infinite far plane\n"
         "  --ortho HALF_HEIGHT     orthographic, half the view height in scene units\n"
         "  --reverse-z             reverse-Z with a [0,1] clip range (glClipControl), depth cleared to 0, GL_GREATER\n"
         "  --depth d16|d24|d32f    depth buffer format (default d32f)\n"
         "\n"
         "G-buffer\n"
         "  --normals view|world|depth  space of the stored normals handed to the plugin, or depth: no normal\n"
         "                          texture, the plugin rebuilds normals from depth (default view)\n"
         "  --normal-format rgba16f|rgba8   rgba16f stores signed normals, rgba8 n*0.5+0.5 (default rgba16f)\n"
         "\n"
         "SSAO settings (precedence: flags > scene hints (glTF extras \"ssao\") > --preset > plugin defaults)\n"
         "  --preset low|medium|high|ultra|chapter   start from a plugin preset (default: the plugin's defaults, which\n"
         "                          are the medium (DEFAULT) preset)\n"
      << preset_lines(presets) <<
         "  --method kernel|visibility  estimator: the chapter's point kernel, or ray-marched visibility\n"
         "                          (default " << def([](const ssao_settings& s) { return std::string(name(s.method)); }) << ")\n"
         "  --samples N             kernel samples (visibility: directions), 1.." << SSAO_MAX_SAMPLES << " (default " << def([](const ssao_settings& s) { return std::to_string(s.sample_count); }) << ")\n"
         "  --radius R              sampling radius in scene units, > 0 (default: scene hint, else 0.05 x the\n"
         "                          scene's bounding-box diagonal; plugin's own default "
      << def([&](const ssao_settings& s) { return num(s.radius); }) << ")\n"
         "  --bias B                depth bias in scene units, >= 0 (default "
      << (d ? num(d->bias / d->radius) + " x radius, i.e. " + num(d->bias) + " at radius " + num(d->radius)
            : std::string("a fraction of the radius")) << ")\n"
         "  --depth-step-bias K     multiple of the depth format's step, [0, " << num(SSAO_MAX_DEPTH_STEP_BIAS) << "] (default "
      << def([&](const ssao_settings& s) { return num(s.depth_step_bias); }) << ")\n"
         "  --power P               exponent on the AO, (0, " << num(SSAO_MAX_POWER) << "] (default " << def([&](const ssao_settings& s) { return num(s.power); }) << ")\n"
         "  --strength S            occlusion multiplier, [0, " << num(SSAO_MAX_STRENGTH) << "]; 0 = no AO at all (default "
      << def([&](const ssao_settings& s) { return num(s.strength); }) << ")\n"
         "  --kernel hemisphere|sphere|separable (default " << def([](const ssao_settings& s) { return std::string(name(s.kernel_shape)); }) << ")\n"
         "  --distribution accelerating|uniform (default " << def([](const ssao_settings& s) { return std::string(name(s.distribution)); }) << ")\n"
         "  --rotation gradient|noise|hash|none (default " << def([](const ssao_settings& s) { return std::string(name(s.rotation)); }) << ")\n"
         "  --seed N                seed of kernel, noise and hash, 0..4294967295; 0 = default (default "
      << def([](const ssao_settings& s) { return std::to_string(s.seed); }) << ")\n"
         "  --blur depth-aware|box|gaussian|none (default " << def([](const ssao_settings& s) { return std::string(name(s.blur)); }) << ")\n"
         "  --blur-radius N         blur taps either side, 1.." << SSAO_MAX_BLUR_RADIUS << " (default " << def([](const ssao_settings& s) { return std::to_string(s.blur_radius); }) << ")\n"
         "  --blur-sigma S          gaussian sigma in pixels, (0, " << num(SSAO_MAX_BLUR_SIGMA) << "] (default: the blur radius"
      << (d ? ", " + num(d->blur_sigma) : std::string()) << ")\n"
         "  --blur-tolerance T      depth-aware blur's relative depth tolerance, (0, 1] (default "
      << def([&](const ssao_settings& s) { return num(s.blur_depth_tolerance); }) << ")\n"
         "  --thickness T           visibility: how far behind the depth buffer a step still counts as blocked,\n"
         "                          view units, > 0 (default radius x (0.5 + 1.5 / steps): "
      << def([&](const ssao_settings& s) { return num(s.thickness / s.radius) + " x radius"; }) << ")\n"
         "  --steps N               visibility: steps per direction, 1.." << SSAO_MAX_STEPS << " (default "
      << def([](const ssao_settings& s) { return std::to_string(s.step_count); }) << ")\n"
         "  --max-step-texels X     visibility: the longest a step may be on screen, sampling-grid texels; more\n"
         "                          steps (up to " << SSAO_MAX_STEPS << ") where the radius spans more, [0, " << num(SSAO_MAX_STEP_TEXELS) << "]; 0 = off: --steps\n"
         "                          fixed (default "
      << def([&](const ssao_settings& s) { return s.max_step_texels > 0.0f ? num(s.max_step_texels) : std::string("off"); })
      << ")\n"
         "  --output-format r8|r16f plugin output texture format (default " << def([](const ssao_settings& s) { return std::string(name(s.output_format)); }) << ")\n"
         "  --resolution full|half|quarter  the grid the AO is estimated on, upsampled to the viewport below full\n"
         "                          (default " << def([](const ssao_settings& s) { return std::string(name(s.resolution)); }) << ")\n"
         "  --fade-start D          distance fade: view depth where AO starts fading to 1, >= 0 (default: scene\n"
         "                          hint, else 0); needs a fade end\n"
         "  --fade-end D            view depth beyond which AO is 1, > fade start; 0 = no fade (default: scene\n"
         "                          hint, else 0)\n"
         "  --radius-pixels N       radius in viewport pixels at each pixel's depth, at most --radius, (0, 16384];\n"
         "                          0 = off, radius in scene units (default: scene hint, else 0)\n"
         "  --frame-index N         inputs.frame_index, 0..4294967295: 0 = the fixed noise pattern, else rotation\n"
         "                          and jitter move with it for a TAA host (default 0)\n"
         "  --accumulate K          ao.png/ao.exr = the mean AO of frame indices N..N+K-1 (what a TAA host\n"
         "                          converges to), 1..1024; the lit pictures use frame N (default 1)\n"
         "  --debug-view " << debug_view_text::choices() << "\n"
         "                          one more execute with this debug view, written to debug_view.png (normal\n"
         "                          views: RGB, n*0.5+0.5; raw-ao, blur-weights: grey) (default none)\n"
         "  --msaa N                the plugin reads a G-buffer rendered with N samples per pixel: 1, 2, 4..32,\n"
         "                          a power of two and at most what the GL allows\n"
         "                          (GL_TEXTURE_2D_MULTISAMPLE; default 1 = single-sample); the lighting uses\n"
         "                          the single-sample G-buffer\n"
         "  --sample-index I        with --msaa N: the sample the plugin reads, 0..N-1 (default 0)\n"
         "  --output overwrite|multiply  lit_ao.png: overwrite = the host lights with AO on the ambient term;\n"
         "                          multiply = the plugin multiplies AO into the host's lit image (default overwrite)\n"
         "\n"
         "Files written to the output directory (all or none: written to temporary names, renamed at the end)\n"
         "  ao.png ao.exr           ambient occlusion (EXR: one float channel Y, 1 = unoccluded)\n"
         "  lit_ao.png lit_no_ao.png  Blinn-Phong lighting with and without AO on the ambient term\n"
         "  normals.png             view-space normals as n*0.5+0.5\n"
         "  depth.png               linear view depth, nearest surface black, farthest white, sky white\n"
         "  view_depth.exr          view distance along -z (one float channel Y); sky = +inf\n"
         "  debug_view.png          with --debug-view (not none): what that view writes\n"
         "  modes.png               panels left to right: E no SSAO, R no rotation, T noise rotation,\n"
         "                          Y accelerating distribution, U hemisphere kernel (each lit with its AO)\n"
         "\n"
         "  --help, -h / --version  this text / the version (every ssao tool takes both)\n"
         "Exit status: 0 on success, 1 when rendering or loading fails, 2 on a bad command line.\n";
    return h.str();
}

}  // namespace cli
