// ssao-host: renders a glTF scene headless, runs the SSAO plugin (seen only
// through include/ssao/ssao.h and dlopen) and writes pictures with and without
// ambient occlusion. See docs/tools.md, "ssao-host".
#include "camera.h"
#include "cli.h"
#include "composite.h"
#include "debug_view_text.h"
#include "egl_context.h"
#include "gbuffer.h"
#include "gl_util.h"
#include "flags.h"
#include "image_io.h"
#include "locate.h"
#include "modes.h"
#include "plugin_loader.h"
#include "preset_text.h"
#include "provenance.h"
#include "report_text.h"
#include "run_setup.h"
#include "scene.h"

#include <ssao/ssao.h>

#include <glm/glm.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

struct RunError : std::runtime_error {
    using std::runtime_error::runtime_error;
};


std::string fmt(double v, int precision = 4) {
    std::ostringstream s;
    s.precision(precision);
    s << v;
    return s.str();
}

std::string fmt(const glm::vec3& v) { return "(" + fmt(v.x) + ", " + fmt(v.y) + ", " + fmt(v.z) + ")"; }

std::string with_commas(size_t n) {
    std::string s = std::to_string(n);
    for (int i = static_cast<int>(s.size()) - 3; i > 0; i -= 3) s.insert(static_cast<size_t>(i), ",");
    return s;
}


// ------------------------------------------------------------------ plugin
struct PluginContext {
    const ssao_api& api;
    ssao_context* ctx = nullptr;
    // The last error the plugin logged: its log_user, so it lives as long as the context.
    std::string logged_error;
    explicit PluginContext(const ssao_api& a) : api(a) {}
    PluginContext(const PluginContext&) = delete;
    PluginContext& operator=(const PluginContext&) = delete;
    ~PluginContext() {
        if (ctx) api.destroy_context(ctx);
    }
    std::string error(ssao_status st) const {
        const char* detail = api.last_error(ctx);
        return std::string(api.status_string(st)) + (detail && *detail ? std::string(": ") + detail : std::string());
    }
};

void SSAO_CALL plugin_log(void* user, ssao_log_level level, const char* message) {
    // Errors come back through the status and last_error; keep the last one
    // for create_context, which has no context to ask. Others go to stdout.
    if (level == SSAO_LOG_ERROR) {
        *static_cast<std::string*>(user) = message ? message : "";
        return;
    }
    std::printf("  plugin %s: %s\n", level == SSAO_LOG_WARNING ? "warning" : "info", message ? message : "");
}

// Reads the plugin's output (viewport-sized at output.origin), `components`
// channels (1: the AO; 3: a normal debug view's RGB), top row first.
std::vector<float> read_ao(GladGLContext& gl, const ssao_output& out, int w, int h, int components = 1) {
    std::vector<float> bottom_up =
        gl_util::read_texture(gl, out.texture, out.origin[0], out.origin[1], w, h, components);
    std::vector<float> top_down(bottom_up.size());
    const ptrdiff_t row = static_cast<ptrdiff_t>(w) * components;
    for (int y = 0; y < h; ++y)
        std::copy_n(bottom_up.begin() + y * row, row, top_down.begin() + (h - 1 - y) * row);
    return top_down;
}

// --accumulate K: the mean AO of frame indices N..N+K-1 (`first` is frame
// N's), what a TAA host converges to. Ends with frame N executed again, so
// the lit pictures drawn from `output` show frame N as without the flag.
std::vector<float> accumulate_ao(const ssao_api& api, PluginContext& plugin, GladGLContext& gl, ssao_inputs& inputs,
                                 ssao_output& output, const std::vector<float>& first, int frames, int w, int h) {
    std::vector<double> sum(first.begin(), first.end());
    const uint32_t n = inputs.frame_index;
    for (int k = 1; k < frames; ++k) {
        inputs.frame_index = n + static_cast<uint32_t>(k);  // wraps past 2^32 - 1 like a frame counter
        const ssao_status st = api.execute(plugin.ctx, &inputs, &output);
        if (st != SSAO_OK) throw RunError("the SSAO plugin failed: " + plugin.error(st));
        const std::vector<float> ao = read_ao(gl, output, w, h);
        for (size_t i = 0; i < sum.size(); ++i) sum[i] += ao[i];
    }
    inputs.frame_index = n;
    const ssao_status st = api.execute(plugin.ctx, &inputs, &output);
    if (st != SSAO_OK) throw RunError("the SSAO plugin failed: " + plugin.error(st));
    std::vector<float> mean(sum.size());
    for (size_t i = 0; i < sum.size(); ++i) mean[i] = static_cast<float>(sum[i] / frames);
    return mean;
}

std::vector<uint8_t> to_bytes(const std::vector<float>& v) {
    std::vector<uint8_t> b(v.size());
    for (size_t i = 0; i < v.size(); ++i) {
        const float x = std::isfinite(v[i]) ? std::clamp(v[i], 0.0f, 1.0f) : 0.0f;
        b[i] = static_cast<uint8_t>(std::lround(x * 255.0f));
    }
    return b;
}


// Bytes of memory available (MemAvailable of /proc/meminfo), 0 if unknown.
uint64_t available_memory() {
    std::FILE* f = std::fopen("/proc/meminfo", "r");
    if (!f) return 0;
    char line[256];
    uint64_t kib = 0;
    while (std::fgets(line, sizeof line, f)) {
        unsigned long long v = 0;
        if (std::sscanf(line, "MemAvailable: %llu kB", &v) == 1) {
            kib = v;
            break;
        }
    }
    std::fclose(f);
    return kib * 1024;
}

// A generous estimate of the memory one run needs per pixel (GL textures,
// which llvmpipe keeps in system memory, plus the read-backs and images).
uint64_t bytes_needed(int w, int h, bool full, bool sheet) {
    uint64_t per_pixel = 4 + 8 + 16 + 4 + 4;          // G-buffer, plugin's targets, AO read-back
    if (full || sheet) per_pixel += 4 + 16 + 3 * 2;   // composite target, its read-back, lit images
    if (full) per_pixel += 4 + 16 + 4 + 3 + 1;        // depth and normal read-backs, view depth, PNGs
    if (sheet) per_pixel += 15 + 3;                   // the sheet and a panel
    return per_pixel * static_cast<uint64_t>(w) * static_cast<uint64_t>(h);
}

// ------------------------------------------------------------------- run
// What the run reads before any GL: the scene, the settings and the camera.
struct Setup {
    std::string scene_path;
    scene::Scene sc;
    ssao_settings settings{};
    std::string radius_note;
    camera::Camera cam;
    camera::Source camera_source = camera::Source::Framed;
    glm::mat4 view{1.0f}, projection{1.0f};
    cli::DepthFormat depth_format = cli::DepthFormat::D32F;
    bool full = true;   // every picture, not only the AO
    bool sheet = true;  // the modes sheet
};

// Everything rendered, kept in memory and written at the end.
struct Rendered {
    std::vector<float> ao, view_depth;
    std::vector<uint8_t> lit_ao, lit_no_ao, normals_png, depth_png, modes_png, debug_png;
    int debug_channels = 1;
    ssao_timings timings{};
    ssao_frame_info info{};
    std::string renderer;
    int gl_major = 0, gl_minor = 0;
};

std::string scene_path_of(const cli::Options& o) {
    const std::string path = o.scene_path.empty() ? scene::default_path() : o.scene_path;
    std::error_code ec;
    if (o.scene_path.empty() && !fs::exists(path, ec))
        throw RunError("the bundled scene '" + path + "' is missing (looked in $SSAO_DATA_DIR, " +
                       "<program>/../share/ssao and, for an uninstalled build, the source tree); " +
                       "pass a .gltf or .glb file");
    return path;
}

void check_memory(int W, int H, bool full, bool sheet) {
    const uint64_t available = available_memory();
    if (!available) return;
    const uint64_t needed = bytes_needed(W, H, full, sheet);
    if (needed > available)
        throw RunError("a " + std::to_string(W) + "x" + std::to_string(H) + " image needs about " +
                       fmt(double(needed) / double(1ull << 30), 3) + " GiB of memory, but only " +
                       fmt(double(available) / double(1ull << 30), 3) + " GiB are available; use a smaller --width/--height");
}

// What needs no plugin and no scene: the scene's path, an unwritable --out
// (found here, not only when the files are written) and the memory a run of
// this size needs.
Setup preflight(const cli::Options& o) {
    Setup s;
    s.scene_path = scene_path_of(o);
    image_io::check_output_dir(o.out_dir);
    s.full = !o.only_ao;
    s.sheet = o.sheet.value_or(s.full);
    check_memory(o.width, o.height, s.full, s.sheet);
    return s;
}

// The scene, the settings (the plugin resolves the preset) and the camera.
void load(const cli::Options& o, const ssao_api& api, Setup& s) {
    std::string error;
    scene::Limits limits;
    limits.allow_outside_files = o.allow_outside_files;
    if (!scene::load(s.scene_path, s.sc, error, limits)) throw RunError("cannot load the scene: " + error);
    if (s.sc.mesh.triangle_count() == 0) throw RunError("'" + s.scene_path + "' has nothing to draw (no triangles)");

    s.settings = run_setup::build_settings(api, o, s.sc, s.radius_note);
    const float aspect = static_cast<float>(o.width) / static_cast<float>(o.height);
    s.cam = run_setup::build_camera(o, s.sc, aspect, s.camera_source);
    s.view = camera::view_matrix(s.cam);
    s.projection = camera::projection_matrix(s.cam, aspect);
    s.depth_format = o.depth_format.value_or(cli::DepthFormat::D32F);
}

// The GL context, refused before anything is rendered when it cannot hold
// this run (clip control for reverse-Z, the image size, --msaa's samples).
std::unique_ptr<eglctx::Context> open_gl(const cli::Options& o, const camera::Camera& cam) {
    eglctx::Options gl_options;
    if (o.gl33) {
        gl_options.major = 3;
        gl_options.minor = 3;
    }
    std::string error;
    auto context = eglctx::Context::create(gl_options, error);
    if (!context) throw RunError(error);
    GladGLContext& gl = context->gl();
    if (cam.zero_to_one && !gl.ClipControl)
        throw RunError("--reverse-z needs glClipControl (GL 4.5 or ARB_clip_control), which this context lacks");
    GLint max_size = 0;
    gl.GetIntegerv(GL_MAX_TEXTURE_SIZE, &max_size);
    if (o.width > max_size || o.height > max_size)
        throw RunError("the image size " + std::to_string(o.width) + "x" + std::to_string(o.height) +
                       " exceeds this GPU's largest texture, " + std::to_string(max_size));
    // --msaa N is a power of two (checked when parsed); here: within this context's limit.
    if (o.msaa > 1) {
        GLint max_depth = 0, max_color = 0;
        gl.GetIntegerv(GL_MAX_DEPTH_TEXTURE_SAMPLES, &max_depth);
        gl.GetIntegerv(GL_MAX_COLOR_TEXTURE_SAMPLES, &max_color);
        const int max_samples = std::min(max_depth, max_color);
        if (o.msaa > max_samples)
            throw RunError("--msaa " + std::to_string(o.msaa) + ": this GL allows at most " +
                           std::to_string(max_samples) + " samples in a multisampled texture");
    }
    return context;
}

gbuffer::Desc gbuffer_desc(const cli::Options& o, const Setup& s) {
    gbuffer::Desc d;
    d.width = o.width;
    d.height = o.height;
    d.depth = s.depth_format;
    d.space = o.normal_space;
    d.format = o.normal_format;
    d.reverse_z = s.cam.reverse_z;
    d.zero_to_one = s.cam.zero_to_one;
    return d;
}

void start_plugin(const ssao_api& api, const ssao_settings& settings, PluginContext& plugin) {
    ssao_context_desc desc{};
    desc.size = sizeof desc;
    desc.get_proc_address = [](void* user, const char* name) -> ssao_gl_proc {
        return eglctx::Context::get_proc(user, name);
    };
    desc.log = plugin_log;
    desc.log_user = &plugin.logged_error;
    desc.settings = &settings;
    const ssao_status st = api.create_context(&desc, &plugin.ctx);
    if (st != SSAO_OK)
        throw RunError("the SSAO plugin could not start: " + std::string(api.status_string(st)) +
                       (plugin.logged_error.empty() ? "" : ": " + plugin.logged_error));
}

ssao_inputs plugin_inputs(const cli::Options& o, const Setup& s, const gbuffer::GBuffer& g) {
    ssao_inputs in{};
    in.size = sizeof in;
    in.depth_texture = g.depth_texture();
    in.normal_texture = o.normals_from_depth ? 0u : g.normal_texture();
    in.sample_index = o.sample_index;
    in.normal_space = o.normal_space == cli::NormalSpace::World ? SSAO_NORMAL_SPACE_WORLD : SSAO_NORMAL_SPACE_VIEW;
    in.normal_packing = o.normal_format == cli::NormalFormat::RGBA8 ? SSAO_NORMAL_PACKING_UNORM : SSAO_NORMAL_PACKING_SIGNED;
    std::copy_n(glm::value_ptr(s.projection), 16, in.projection);
    std::copy_n(glm::value_ptr(s.view), 16, in.view_matrix);
    in.clip_range = s.cam.zero_to_one ? SSAO_CLIP_ZERO_TO_ONE : SSAO_CLIP_NEGATIVE_ONE_TO_ONE;
    in.output_texture = 0;  // the plugin's own texture, in settings.output_format
    in.frame_index = o.frame_index;
    return in;
}

// --frames executes, then the AO read back (--accumulate: the mean over frame indices).
void render_ao(GladGLContext& gl, const cli::Options& o, PluginContext& plugin, ssao_inputs& inputs,
               ssao_output& output, Rendered& r) {
    const ssao_api& api = plugin.api;
    for (int frame = 0; frame < o.frames; ++frame) {
        const ssao_status st = api.execute(plugin.ctx, &inputs, &output);
        if (st != SSAO_OK) throw RunError("the SSAO plugin failed: " + plugin.error(st));
        gl.Flush();
    }
    gl.Finish();
    r.timings.size = sizeof r.timings;
    api.get_timings(plugin.ctx, &r.timings);
    r.info.size = sizeof r.info;
    api.get_frame_info(plugin.ctx, &r.info);
    gl_util::check(gl, "the SSAO plugin's execute");
    r.ao = read_ao(gl, output, o.width, o.height);
    if (o.accumulate > 1)
        r.ao = accumulate_ao(api, plugin, gl, inputs, output, r.ao, o.accumulate, o.width, o.height);
}

// The modes sheet: panels E R T Y U left to right, each lit with its own AO.
std::vector<uint8_t> render_sheet(const cli::Options& o, const Setup& s, PluginContext& plugin,
                                  composite::Compositor& compositor, const composite::Lighting& lighting,
                                  const gbuffer::GBuffer& gbuf, const ssao_inputs& inputs,
                                  const std::vector<uint8_t>& no_ao) {
    const int W = o.width, H = o.height;
    const size_t row_bytes = static_cast<size_t>(W) * 3;
    const size_t sheet_row = row_bytes * 5;
    std::vector<uint8_t> sheet(sheet_row * static_cast<size_t>(H), 0);
    for (int m = 0; m < 5; ++m) {
        const modes::Mode& mode = modes::kModes[m];
        std::vector<uint8_t> panel;
        if (!mode.ssao) {
            panel = no_ao;
        } else {
            ssao_settings ms = s.settings;
            modes::apply(mode, ms);
            ssao_status st = plugin.api.set_settings(plugin.ctx, &ms);
            if (st != SSAO_OK) throw RunError("the SSAO plugin refused a mode's settings: " + plugin.error(st));
            ssao_output mode_output{};
            mode_output.size = sizeof mode_output;
            st = plugin.api.execute(plugin.ctx, &inputs, &mode_output);
            if (st != SSAO_OK) throw RunError("the SSAO plugin failed: " + plugin.error(st));
            panel = compositor.render(gbuf, s.view, s.projection, mode_output.texture,
                                      glm::ivec2(mode_output.origin[0], mode_output.origin[1]), lighting);
        }
        const int scale = std::max(1, std::min(W, H) / 64);
        image_io::draw_label(panel, W, H, 2 * scale, 2 * scale, mode.letter, scale);
        for (int y = 0; y < H; ++y)
            std::copy_n(panel.begin() + static_cast<ptrdiff_t>(static_cast<size_t>(y) * row_bytes), row_bytes,
                        sheet.begin() + static_cast<ptrdiff_t>(static_cast<size_t>(y) * sheet_row +
                                                               static_cast<size_t>(m) * row_bytes));
    }
    return sheet;
}

// The lit pictures with and without AO (--output multiply: the plugin
// multiplies AO into the compositor's lit image), and the modes sheet.
void render_lit(const cli::Options& o, const Setup& s, GladGLContext& gl, PluginContext& plugin,
                const gbuffer::GBuffer& gbuf, const ssao_inputs& inputs, const ssao_output& output, Rendered& r) {
    composite::Compositor compositor(gl, o.width, o.height);
    const composite::Lighting lighting = composite::default_lighting(s.sc.bounds_min, s.sc.bounds_max, s.view);
    const glm::ivec2 origin(output.origin[0], output.origin[1]);
    if (s.full && !o.output_multiply)
        r.lit_ao = compositor.render(gbuf, s.view, s.projection, output.texture, origin, lighting);
    std::vector<uint8_t> no_ao = compositor.render(gbuf, s.view, s.projection, 0, origin, lighting);
    if (s.full && o.output_multiply) {
        // The lit image without AO is still in the compositor's texture.
        ssao_inputs multiply = inputs;
        multiply.output_texture = compositor.texture();
        multiply.output_mode = SSAO_OUTPUT_MODE_MULTIPLY;
        const ssao_status st = plugin.api.execute(plugin.ctx, &multiply, nullptr);
        if (st != SSAO_OK) throw RunError("the SSAO plugin failed to multiply: " + plugin.error(st));
        r.lit_ao = compositor.read();
    }
    if (s.sheet) r.modes_png = render_sheet(o, s, plugin, compositor, lighting, gbuf, inputs, no_ao);
    if (s.full) r.lit_no_ao = std::move(no_ao);
}

// Depth: view distance along -z from the depth buffer and the inverse
// projection (in double), sky = +inf; its picture scaled to the scene's
// depth range. Normals as an RGB picture (n * 0.5 + 0.5).
void depth_and_normal_pictures(GladGLContext& gl, const cli::Options& o, const Setup& s, const gbuffer::GBuffer& gbuf,
                               Rendered& r) {
    const int W = o.width, H = o.height;
    const std::vector<float> depth = gl_util::read_texture(gl, gbuf.depth_texture(), 0, 0, W, H, 1, true);
    const std::vector<float> normal = gl_util::read_texture(gl, gbuf.normal_texture(), 0, 0, W, H, 4);
    const glm::dmat4 inv = glm::inverse(glm::dmat4(s.projection));
    const glm::mat3 rotation(s.view);
    const float clear = gbuf.clear_depth();
    const size_t count = static_cast<size_t>(W) * static_cast<size_t>(H);
    r.view_depth.assign(count, std::numeric_limits<float>::infinity());
    r.normals_png.assign(count * 3, 0);
    double zmin = std::numeric_limits<double>::infinity(), zmax = -zmin;
    for (int y = 0; y < H; ++y) {
        for (int x = 0; x < W; ++x) {
            const size_t src = static_cast<size_t>(y) * static_cast<size_t>(W) + static_cast<size_t>(x);
            const size_t dst = static_cast<size_t>(H - 1 - y) * static_cast<size_t>(W) + static_cast<size_t>(x);
            const float d = depth[src];
            if (d == clear) continue;
            const double ndc_z = s.cam.zero_to_one ? d : 2.0 * d - 1.0;
            const glm::dvec4 p = inv * glm::dvec4((x + 0.5) / W * 2.0 - 1.0, (y + 0.5) / H * 2.0 - 1.0, ndc_z, 1.0);
            const double z = -p.z / p.w;
            r.view_depth[dst] = static_cast<float>(z);
            zmin = std::min(zmin, z);
            zmax = std::max(zmax, z);
            glm::vec3 n(normal[src * 4], normal[src * 4 + 1], normal[src * 4 + 2]);
            if (o.normal_format == cli::NormalFormat::RGBA8) n = n * 2.0f - 1.0f;
            if (o.normal_space == cli::NormalSpace::World) n = rotation * n;
            const float len = glm::length(n);
            if (len > 0.0f && std::isfinite(len)) n /= len;
            for (int c = 0; c < 3; ++c)
                r.normals_png[dst * 3 + static_cast<size_t>(c)] =
                    static_cast<uint8_t>(std::lround(std::clamp(n[c] * 0.5f + 0.5f, 0.0f, 1.0f) * 255.0f));
        }
    }
    r.depth_png.assign(count, 255);
    const double span = zmax > zmin ? zmax - zmin : 1.0;
    for (size_t i = 0; i < count; ++i)
        if (std::isfinite(r.view_depth[i]))
            r.depth_png[i] = static_cast<uint8_t>(std::lround(std::clamp((r.view_depth[i] - zmin) / span, 0.0, 1.0) * 255.0));
}

// One more execute with the debug view (last: it overwrites the plugin's own
// output texture, which the pictures above read).
void render_debug_view(GladGLContext& gl, const cli::Options& o, const Setup& s, PluginContext& plugin,
                       const ssao_inputs& inputs, Rendered& r) {
    ssao_settings ds = s.settings;
    ds.debug_view = o.debug_view;
    ssao_status st = plugin.api.set_settings(plugin.ctx, &ds);
    if (st != SSAO_OK) throw RunError("the SSAO plugin refused the debug view: " + plugin.error(st));
    ssao_output debug_output{};
    debug_output.size = sizeof debug_output;
    st = plugin.api.execute(plugin.ctx, &inputs, &debug_output);
    if (st != SSAO_OK) throw RunError("the SSAO plugin failed in the debug view: " + plugin.error(st));
    // Finished before the read-back, as the frames are: without it Mesa
    // 22.3's llvmpipe now and then returned the texture's previous contents
    // after a clear pass (blur-weights without a blur).
    gl.Finish();
    r.debug_channels = debug_view_text::is_rgb(o.debug_view) ? 3 : 1;
    r.debug_png = to_bytes(read_ao(gl, debug_output, o.width, o.height, r.debug_channels));
}

// The G-buffer (and --msaa's multisampled one, which the plugin reads), the
// plugin's frames and every picture; GL objects are gone when it returns.
Rendered render(eglctx::Context& context, const ssao_api& api, const cli::Options& o, const Setup& s) {
    GladGLContext& gl = context.gl();
    Rendered r;
    const char* renderer = reinterpret_cast<const char*>(gl.GetString(GL_RENDERER));
    r.renderer = renderer ? renderer : "?";
    r.gl_major = context.major();
    r.gl_minor = context.minor();
    const gbuffer::Desc gdesc = gbuffer_desc(o, s);
    gbuffer::GBuffer gbuf(gl, gdesc, s.sc.mesh);
    gbuf.render(s.view, s.projection);
    std::unique_ptr<gbuffer::GBuffer> ms_gbuf;
    if (o.msaa > 1) {
        gbuffer::Desc ms_desc = gdesc;
        ms_desc.samples = o.msaa;
        ms_gbuf = std::make_unique<gbuffer::GBuffer>(gl, ms_desc, s.sc.mesh);
        ms_gbuf->render(s.view, s.projection);
    }
    PluginContext plugin(api);
    start_plugin(api, s.settings, plugin);
    ssao_inputs inputs = plugin_inputs(o, s, ms_gbuf ? *ms_gbuf : gbuf);
    ssao_output output{};
    output.size = sizeof output;
    render_ao(gl, o, plugin, inputs, output, r);
    if (s.full || s.sheet) render_lit(o, s, gl, plugin, gbuf, inputs, output, r);
    if (s.full) depth_and_normal_pictures(gl, o, s, gbuf, r);
    if (o.debug_view != SSAO_DEBUG_VIEW_NONE) render_debug_view(gl, o, s, plugin, inputs, r);
    gl_util::check(gl, "the read-back");
    return r;
}

// Every file under a temporary name, then all renamed; returns their names.
std::vector<std::string> write_files(const cli::Options& o, const Setup& s, const Rendered& r) {
    const int W = o.width, H = o.height;
    image_io::StagedOutput files(o.out_dir);
    files.png("ao.png", W, H, 1, to_bytes(r.ao));
    // What the picture was made with, for ssao-error to check against a reference.
    const ssao_settings& st = s.settings;
    files.exr("ao.exr", W, H, r.ao,
              provenance::describe(s.scene_path, W, H, s.cam, st.radius,
                                   st.method == SSAO_METHOD_VISIBILITY ? std::optional<double>(st.thickness) : std::nullopt));
    if (s.full) {
        files.png("lit_ao.png", W, H, 3, r.lit_ao);
        files.png("lit_no_ao.png", W, H, 3, r.lit_no_ao);
        files.png("normals.png", W, H, 3, r.normals_png);
        files.png("depth.png", W, H, 1, r.depth_png);
        files.exr("view_depth.exr", W, H, r.view_depth);
    }
    if (s.sheet) files.png("modes.png", W * 5, H, 3, r.modes_png);
    if (!r.debug_png.empty()) files.png("debug_view.png", W, H, r.debug_channels, r.debug_png);
    files.commit();
    return files.names();
}

void report_render(const cli::Options& o, const Setup& s, const Rendered& r) {
    const char* depth_names[] = {"d16", "d24", "d32f"};
    std::printf("ssao-host: %s\n", fs::absolute(s.scene_path).lexically_normal().c_str());
    std::printf("  scene: %s triangles, bounds %s .. %s\n", with_commas(s.sc.mesh.triangle_count()).c_str(),
                fmt(s.sc.bounds_min).c_str(), fmt(s.sc.bounds_max).c_str());
    std::printf("  render: %dx%d, GL %d.%d core%s on %s, depth %s, normals %s %s\n", o.width, o.height, r.gl_major,
                r.gl_minor, o.gl33 ? " (asked for 3.3 core)" : "", r.renderer.c_str(),
                depth_names[static_cast<int>(s.depth_format)], o.normals_from_depth ? "rebuilt from depth, G-buffer view"
                : o.normal_space == cli::NormalSpace::World ? "world" : "view",
                o.normal_format == cli::NormalFormat::RGBA8 ? "rgba8" : "rgba16f");
    const camera::Camera& cam = s.cam;
    std::printf("  camera: %s, %s, eye %s, target %s, near %s, far %s%s\n",
                (std::string(camera::describe(s.camera_source)) +
                 (o.cam.eye || o.cam.target || o.cam.fov_deg || o.cam.znear || o.cam.zfar || o.cam.ortho_half_height || o.cam.reverse_z
                      ? " with flag overrides"
                      : ""))
                    .c_str(),
                cam.orthographic ? ("orthographic half-height " + fmt(cam.ortho_half_height)).c_str()
                                 : ("perspective fov " + fmt(glm::degrees(cam.yfov)) + " deg").c_str(),
                fmt(cam.eye).c_str(), fmt(cam.target).c_str(), fmt(cam.znear).c_str(),
                std::isinf(cam.zfar) ? "inf" : fmt(cam.zfar).c_str(), cam.reverse_z ? ", reverse-Z [0,1]" : "");
}

void report_plugin(const cli::Options& o, const Setup& s, const Rendered& r, const std::string& plugin_path) {
    const ssao_settings& st = s.settings;
    std::printf("  ssao: %s, radius %s (%s), bias %s, rotation %s, strength %s, power %s, output %s\n",
                report_text::estimator(st).c_str(), fmt(st.radius).c_str(), s.radius_note.c_str(), fmt(st.bias).c_str(),
                cli::name(st.rotation), st.strength == SSAO_STRENGTH_OFF ? "0 (off)" : fmt(st.strength).c_str(),
                fmt(st.power).c_str(), cli::name(st.output_format));
    // Printed only when one of them is on, so other runs print what they always did.
    if (st.fade_end > 0.0f || st.radius_pixels > 0.0f || o.frame_index != 0 || o.accumulate > 1) {
        std::printf("  ssao 1.2: fade %s, radius pixels %s, frame index %u, accumulate %d\n",
                    st.fade_end > 0.0f ? (fmt(st.fade_start) + ".." + fmt(st.fade_end)).c_str() : "off",
                    st.radius_pixels > 0.0f ? fmt(st.radius_pixels).c_str() : "off", o.frame_index, o.accumulate);
    }
    std::printf("  plugin: %s\n", plugin_path.c_str());
    const ssao_frame_info& info = r.info;
    std::printf("  plugin saw: %s, %s depth%s%s, near %s, far %s\n", info.orthographic ? "orthographic" : "perspective",
                info.depth_bits == 32 ? "32-bit float" : (std::to_string(info.depth_bits) + "-bit").c_str(),
                info.reverse_z ? ", reverse-Z" : "", info.infinite_far ? ", infinite far" : "",
                fmt(info.near_distance).c_str(), std::isinf(info.far_distance) ? "inf" : fmt(info.far_distance).c_str());
    if (o.debug_view != SSAO_DEBUG_VIEW_NONE)
        std::printf("  debug view: %s (one more execute, debug_view.png)\n", debug_view_text::name(o.debug_view));
    if (r.timings.available)
        std::printf("  GPU times (frame %llu of %d): %s\n", static_cast<unsigned long long>(r.timings.frame), o.frames,
                    report_text::pass_times(r.timings, st.method).c_str());
    else
        std::printf("  GPU times: n/a (no timer results after %d frames)\n", o.frames);
}

void report_files(const cli::Options& o, const std::vector<std::string>& names) {
    const fs::path out_abs = fs::absolute(o.out_dir).lexically_normal();
    std::printf("wrote %zu files to %s/:\n", names.size(), out_abs.c_str());
    for (const std::string& n : names) std::printf("  %s\n", (out_abs / n).c_str());
}

// Check, load, open GL, render, write, report.
int run(const cli::Options& o) {
    Setup setup = preflight(o);
    plugin::Library library;
    std::string error;
    if (!library.open_default(o.plugin_path, error)) throw RunError(error);
    const ssao_api& api = library.api();
    load(o, api, setup);
    const std::unique_ptr<eglctx::Context> context = open_gl(o, setup.cam);
    const Rendered rendered = render(*context, api, o, setup);
    const std::vector<std::string> names = write_files(o, setup, rendered);
    report_render(o, setup, rendered);
    report_plugin(o, setup, rendered, library.loaded_path());
    report_files(o, names);
    return 0;
}

// Defaults and presets in --help come from the plugin itself (a zeroed
// struct resolved, the presets as preset_settings returns them), so the help
// never drifts from the library.
std::string help(const cli::Options& options) {
    plugin::Library library;
    std::string error;
    ssao_settings defaults{};
    defaults.size = sizeof defaults;
    bool have = false;
    ssao_settings presets[preset_text::kPresetCount] = {};
    if (library.open_default(options.plugin_path, error)) {
        ssao_settings zero{};
        zero.size = sizeof zero;
        have = library.api().resolve_settings(&zero, &defaults) == SSAO_OK;
        for (int i = 0; i < preset_text::kPresetCount && have; ++i) {
            presets[i].size = sizeof presets[i];
            have = library.api().preset_settings(preset_text::kPresetOrder[i], &presets[i]) == SSAO_OK;
        }
    }
    return cli::help_text(have ? &defaults : nullptr, scene::default_path(), have ? presets : nullptr);
}

}  // namespace

int main(int argc, char** argv) {
    cli::Options options;
    std::string error;
    const cli::ParseResult parsed = cli::parse(argc, argv, options, error);
    return flags::finish_main("ssao-host", parsed, error, [&] { return help(options); }, [&] { return run(options); });
}
