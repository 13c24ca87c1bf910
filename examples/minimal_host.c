/* minimal_host.c - the README's integration example as a complete C99 program.
 *
 * A headless host in one file: it makes a GL context with EGL, builds a
 * G-buffer of a floor meeting a wall (a 90-degree crease) on the CPU, loads
 * libssao.so with dlopen (one dlsym), runs the pass and prints the AO on the
 * open floor and in the crease. It exits 0 only when the crease is darker
 * than the open floor, so CTest runs it as a test.
 *
 *   minimal_host [path/to/libssao.so]
 */
#include <ssao/ssao.h>

#include <glad/gl.h>

#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <dlfcn.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { W = 96, H = 96 };

static ssao_gl_proc get_proc(void* user, const char* name) {
    (void)user;
    return (ssao_gl_proc)eglGetProcAddress(name);
}

static GLADapiproc glad_proc(const char* name) { return (GLADapiproc)eglGetProcAddress(name); }

static void log_message(void* user, ssao_log_level level, const char* message) {
    (void)user;
    fprintf(stderr, "ssao [%d]: %s\n", (int)level, message);
}

/* Camera at the origin looking down -z, 60 degrees vertical fov, GL [-1,1]
 * depth. The floor is y = -1 (normal +y), the wall z = -4 (normal +z). */
static void make_gbuffer(float proj[16], float* depth, float* normals) {
    const float n = 0.1f, f = 100.0f, t = 1.0f / tanf(0.5236f);
    memset(proj, 0, 16 * sizeof(float));
    proj[0] = t;                          /* column-major: [col * 4 + row] */
    proj[5] = t;
    proj[10] = -(f + n) / (f - n);
    proj[11] = -1.0f;
    proj[14] = -2.0f * f * n / (f - n);
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            /* Both planes span all x, so only the ray's y slope matters. */
            const float dy = ((y + 0.5f) / H * 2.0f - 1.0f) / t;
            float hit = 4.0f, nx = 0.0f, ny = 0.0f, nz = 1.0f;  /* the wall, at view distance 4 */
            if (dy < 0.0f && -1.0f / dy < hit) { hit = -1.0f / dy; nz = 0.0f; ny = 1.0f; }
            const float z = -hit;
            const float ndc = (proj[10] * z + proj[14]) / -z;
            const int i = y * W + x;
            depth[i] = ndc * 0.5f + 0.5f;
            normals[i * 4 + 0] = nx;
            normals[i * 4 + 1] = ny;
            normals[i * 4 + 2] = nz;
            normals[i * 4 + 3] = 1.0f;
        }
}

int main(int argc, char** argv) {
    const char* plugin_path = argc > 1 ? argv[1] : "libssao.so.1";

    /* 1. A headless GL 4.5 core context (Mesa's surfaceless platform). */
    PFNEGLGETPLATFORMDISPLAYEXTPROC get_display =
        (PFNEGLGETPLATFORMDISPLAYEXTPROC)eglGetProcAddress("eglGetPlatformDisplayEXT");
    EGLDisplay display = get_display ? get_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL)
                                     : eglGetDisplay(EGL_DEFAULT_DISPLAY);
    if (display == EGL_NO_DISPLAY || !eglInitialize(display, NULL, NULL) || !eglBindAPI(EGL_OPENGL_API)) {
        fprintf(stderr, "minimal_host: no EGL display\n");
        return 1;
    }
    const EGLint attribs[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                              EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
    EGLContext context = eglCreateContext(display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attribs);
    if (context == EGL_NO_CONTEXT || !eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
        fprintf(stderr, "minimal_host: no GL 4.5 core context\n");
        return 1;
    }
    GladGLContext gl = {0};
    if (!gladLoadGLContext(&gl, glad_proc)) return 1;

    /* 2. The plugin: dlopen, one dlsym, negotiate this header's interface version. */
    void* lib = dlopen(plugin_path, RTLD_NOW | RTLD_LOCAL);
    void* symbol = lib ? dlsym(lib, "ssao_get_api") : NULL;
    PFN_ssao_get_api get_api = NULL;
    memcpy(&get_api, &symbol, sizeof get_api);  /* ISO C has no object-to-function pointer cast */
    ssao_api api = {0};
    api.size = sizeof(api);
    if (!get_api || get_api(SSAO_API_VERSION, &api) != SSAO_OK) {
        fprintf(stderr, "minimal_host: cannot use %s (%s)\n", plugin_path, lib ? "wrong version" : dlerror());
        return 1;
    }
    ssao_settings settings = {0};          /* zero fields = defaults */
    settings.size = sizeof(settings);
    settings.radius = 0.5f;                /* view-space units */
    ssao_context_desc desc = {0};
    desc.size = sizeof(desc);
    desc.get_proc_address = get_proc;
    desc.log = log_message;
    desc.settings = &settings;
    ssao_context* ctx = NULL;
    ssao_status status = api.create_context(&desc, &ctx);
    if (status != SSAO_OK) {
        fprintf(stderr, "minimal_host: create_context: %s\n", api.status_string(status));
        return 1;
    }

    /* 3. The G-buffer a renderer already has: D32F depth, RGBA16F view normals. */
    static float depth[W * H], normals[W * H * 4];
    float proj[16];
    make_gbuffer(proj, depth, normals);
    GLuint tex[2];
    gl.GenTextures(2, tex);
    gl.BindTexture(GL_TEXTURE_2D, tex[0]);
    gl.TexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT32F, W, H, 0, GL_DEPTH_COMPONENT, GL_FLOAT, depth);
    gl.BindTexture(GL_TEXTURE_2D, tex[1]);
    gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA16F, W, H, 0, GL_RGBA, GL_FLOAT, normals);

    /* 4. Each frame: execute. */
    ssao_inputs in = {0};
    in.size = sizeof(in);
    in.depth_texture = tex[0];
    in.normal_texture = tex[1];
    in.normal_packing = SSAO_NORMAL_PACKING_SIGNED;
    memcpy(in.projection, proj, sizeof(in.projection));
    in.clip_range = SSAO_CLIP_NEGATIVE_ONE_TO_ONE;
    in.viewport[2] = W;
    in.viewport[3] = H;
    ssao_output out = {0};
    out.size = sizeof(out);
    status = api.execute(ctx, &in, &out);
    if (status != SSAO_OK) {
        fprintf(stderr, "minimal_host: execute: %s\n", api.last_error(ctx));
        return 1;
    }

    /* 5. Read the AO back: out.texture, R8, 1 = open. */
    static float ao[W * H];
    GLuint fbo;
    gl.GenFramebuffers(1, &fbo);
    gl.BindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
    gl.FramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, out.texture, 0);
    gl.ReadPixels(out.origin[0], out.origin[1], W, H, GL_RED, GL_FLOAT, ao);
    /* The crease is the row where the floor meets the wall: view slope -1/4. */
    const int crease_row = (int)((-0.25f / tanf(0.5236f) * 0.5f + 0.5f) * H);
    float open = 0.0f, crease = 0.0f;
    for (int x = W / 4; x < 3 * W / 4; ++x) {
        open += ao[4 * W + x];                    /* floor, well in front of the wall */
        crease += ao[(crease_row - 1) * W + x];   /* floor, right at the wall */
    }
    open /= W / 2;
    crease /= W / 2;
    printf("AO on the open floor %.3f, in the crease %.3f\n", open, crease);

    api.destroy_context(ctx);
    gl.DeleteTextures(2, tex);
    gl.DeleteFramebuffers(1, &fbo);
    eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display, context);
    eglTerminate(display);
    return open > 0.95f && crease < open - 0.1f ? 0 : 2;
}
