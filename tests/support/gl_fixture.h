// gl_fixture.h - what every GL test needs: a headless EGL context with a
// KHR_debug callback that records every GL error, the plugin loaded with
// dlopen exactly as a host does, and helpers to upload G-buffers and read AO.
#pragma once

#include "analytic_scene.h"

#include <egl_context.h>
#include <plugin_loader.h>

#include <ssao/ssao.h>

#include <memory>
#include <string>
#include <vector>

namespace testgl {

// Records every GL error and undefined-behaviour message KHR_debug reports
// on the current context (a debug context), synchronously.
class DebugErrors {
public:
    explicit DebugErrors(GladGLContext& gl);
    const std::vector<std::string>& messages() const { return messages_; }

private:
    static void callback(GLenum source, GLenum type, GLuint id, GLenum severity, GLsizei length, const GLchar* message,
                         const void* user);
    std::vector<std::string> messages_;
};

// A linked GLSL 3.30 program of the host's own (draws nothing useful), or an exception.
GLuint make_host_program(GladGLContext& gl);

// A debug EGL context (4.5 core unless asked otherwise) or an exception.
std::unique_ptr<eglctx::Context> make_debug_context(int major = 4, int minor = 5);

// Sets in.viewport to (x, y, w, h).
void set_viewport(ssao_inputs& in, int x, int y, int w, int h);
// The normal_packing of a normal texture Fixture::make_normals made in this
// format: RGBA8 holds n * 0.5 + 0.5, the float formats n itself.
ssao_normal_packing packing_of(GLenum normal_format);

// create_context on the current GL context with the default description
// (EGL's get_proc_address, no log, default settings); *out is the new context.
ssao_status create_default_context(const ssao_api& api, ssao_context** out);

// A G-buffer's depth and normal textures.
struct Textures {
    GLuint depth = 0, normal = 0;
};

// The two kinds of renderer whose plans differ (plugin/renderer.h), as a
// test names them to the library through Fixture::recreate_context_as.
struct RendererKind {
    const char* gl_renderer;
    bool software;  // a software rasteriser's plan: the copy of the host's depth, the clears
};
inline constexpr RendererKind kRendererKinds[] = {{"llvmpipe (as the test names it)", true},
                                                  {"NVIDIA H200/PCIe/SSE2", false}};

class Fixture {
public:
    explicit Fixture(int major = 4, int minor = 5);
    ~Fixture();

    GladGLContext& gl() { return egl_->gl(); }
    const ssao_api& api() const { return lib_.api(); }
    ssao_context* ctx() { return ctx_; }
    // The test destroyed the context itself (on another GL context): the
    // fixture must not destroy it again.
    void forget_context() { ctx_ = nullptr; }
    // Replaces ctx() with a context whose glGetString reports `renderer` for
    // GL_RENDERER (a static string), so that a test runs the plan of that
    // kind of renderer, a GPU's on llvmpipe say (plugin/renderer.h). One
    // fixture at a time may do this.
    void recreate_context_as(const char* renderer);
    // glBlitFramebuffer calls that context made since it was created.
    static int blits_as_renamed();
    // GL errors reported through KHR_debug since the fixture was made.
    const std::vector<std::string>& gl_errors() const { return errors_->messages(); }

    // Depth texture of the given sized format from values in [0,1]
    // (GL_DEPTH_COMPONENT16/24/32F, GL_DEPTH24_STENCIL8, GL_DEPTH32F_STENCIL8).
    GLuint make_depth(GLenum internal, int w, int h, const std::vector<float>& depth);
    // Normal texture: RGBA16F signed (default), RGBA32F, or RGBA8 packed to [0,1].
    GLuint make_normals(GLenum internal, int w, int h, const std::vector<glm::vec3>& normals);
    // The G-buffer's depth and normals as textures of those formats (owned by the fixture).
    Textures upload(const analytic::GBuffer& g, GLenum depth_format = GL_DEPTH_COMPONENT32F,
                    GLenum normal_format = GL_RGBA16F);
    // Reads the red channel of a texture's level 0 (any colour format) as floats.
    std::vector<float> read_red(GLuint texture, int w, int h);

    ssao_settings settings(const ssao_settings& overrides);  // resolved, applied to ctx
    // Uploads the G-buffer (D32F + RGBA16F by default), runs execute, reads AO.
    struct Result {
        ssao_status status = SSAO_OK;
        std::vector<float> ao;
        ssao_output output{};
    };
    Result run(const analytic::GBuffer& g, const glm::dmat4& proj, ssao_clip_range clip,
               GLenum depth_format = 0x8CAC /* GL_DEPTH_COMPONENT32F */);
    ssao_inputs inputs(GLuint depth, GLuint normal, const glm::dmat4& proj, ssao_clip_range clip);

private:
    std::unique_ptr<eglctx::Context> egl_;
    plugin::Library lib_;
    ssao_context* ctx_ = nullptr;
    std::unique_ptr<DebugErrors> errors_;
    std::vector<GLuint> textures_;
};

// Sets MESA_GL_VERSION_OVERRIDE=3.3 for the rest of the process: Mesa's EGL
// hands out 4.5 when 3.3 is asked for, unless this is set before the context.
struct MesaGl33Override {
    MesaGl33Override();
};

// The fixture on a genuine GL 3.3 core context (GL_VERSION starts with 3.3,
// else the constructor throws, naming the version it got).
class Gl33Fixture : private MesaGl33Override, public Fixture {
public:
    Gl33Fixture();
};

}  // namespace testgl
