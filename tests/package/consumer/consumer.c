/* consumer.c - an outside program built against an installed (or embedded)
 * ssao, shared by the three consumer projects of the package test.
 *
 * It makes a surfaceless EGL context, uploads a CPU-made G-buffer of a floor
 * meeting a wall (a 90-degree crease, as examples/minimal_host.c), runs the
 * plugin once and reads the AO back. Exit 0 only when the open floor is
 * unoccluded and the crease is darker: a real execute, not just a link.
 *
 * Linked (default): calls ssao_get_api directly (ssao::ssao, -lssao).
 * -DCONSUMER_DLOPEN: includes only the header (ssao::headers) and dlopens
 * "libssao.so.1" through the system's search path, as an engine would.
 * GL comes through eglGetProcAddress: a consumer needs no GL loader.
 */
#include <ssao/ssao.h>

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/glcorearb.h>

#ifdef CONSUMER_DLOPEN
#include <dlfcn.h>
#endif
#include <math.h>
#include <stdio.h>
#include <string.h>

enum { W = 96, H = 96 };

static ssao_gl_proc get_proc(void* user, const char* name) {
    (void)user;
    return (ssao_gl_proc)eglGetProcAddress(name);
}

/* eglGetProcAddress returns a function pointer already: copy it into the typed one. */
#define LOAD(type, var, name)                                   \
    type var;                                                   \
    do {                                                        \
        void (*p_)(void) = eglGetProcAddress(name);             \
        memcpy(&var, &p_, sizeof var);                          \
        if (!p_) {                                              \
            fprintf(stderr, "consumer: no %s\n", name);         \
            return 1;                                           \
        }                                                       \
    } while (0)

int main(void) {
    /* A headless GL 3.3 core context on Mesa's surfaceless platform. */
    PFNEGLGETPLATFORMDISPLAYEXTPROC get_display =
        (PFNEGLGETPLATFORMDISPLAYEXTPROC)eglGetProcAddress("eglGetPlatformDisplayEXT");
    EGLDisplay display = get_display ? get_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL)
                                     : eglGetDisplay(EGL_DEFAULT_DISPLAY);
    if (display == EGL_NO_DISPLAY || !eglInitialize(display, NULL, NULL) || !eglBindAPI(EGL_OPENGL_API)) {
        fprintf(stderr, "consumer: no EGL display\n");
        return 1;
    }
    const EGLint attribs[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 3,
                              EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
    EGLContext context = eglCreateContext(display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attribs);
    if (context == EGL_NO_CONTEXT || !eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
        fprintf(stderr, "consumer: no GL 3.3 core context\n");
        return 1;
    }
    LOAD(PFNGLGENTEXTURESPROC, GenTextures, "glGenTextures");
    LOAD(PFNGLBINDTEXTUREPROC, BindTexture, "glBindTexture");
    LOAD(PFNGLTEXIMAGE2DPROC, TexImage2D, "glTexImage2D");
    LOAD(PFNGLGENFRAMEBUFFERSPROC, GenFramebuffers, "glGenFramebuffers");
    LOAD(PFNGLBINDFRAMEBUFFERPROC, BindFramebuffer, "glBindFramebuffer");
    LOAD(PFNGLFRAMEBUFFERTEXTURE2DPROC, FramebufferTexture2D, "glFramebufferTexture2D");
    LOAD(PFNGLREADPIXELSPROC, ReadPixels, "glReadPixels");

    /* The library's table. */
    PFN_ssao_get_api get_api = NULL;
#ifdef CONSUMER_DLOPEN
    void* lib = dlopen("libssao.so.1", RTLD_NOW | RTLD_LOCAL);
    void* symbol = lib ? dlsym(lib, "ssao_get_api") : NULL;
    memcpy(&get_api, &symbol, sizeof get_api);
    if (!get_api) {
        fprintf(stderr, "consumer: cannot dlopen libssao.so.1: %s\n", dlerror());
        return 1;
    }
#else
    get_api = ssao_get_api;
#endif
    ssao_api api = {0};
    api.size = sizeof(api);
    if (get_api(SSAO_API_VERSION, &api) != SSAO_OK) {
        fprintf(stderr, "consumer: the library refused interface version 1.0\n");
        return 1;
    }
    ssao_settings settings = {0};
    settings.size = sizeof(settings);
    settings.radius = 0.5f;
    ssao_settings resolved = {0};
    resolved.size = sizeof(resolved);
    if (api.resolve_settings(&settings, &resolved) != SSAO_OK || resolved.sample_count == 0) {
        fprintf(stderr, "consumer: resolve_settings failed\n");
        return 1;
    }
    ssao_context_desc desc = {0};
    desc.size = sizeof(desc);
    desc.get_proc_address = get_proc;
    desc.settings = &settings;
    ssao_context* ctx = NULL;
    ssao_status status = api.create_context(&desc, &ctx);
    if (status != SSAO_OK) {
        fprintf(stderr, "consumer: create_context: %s\n", api.status_string(status));
        return 1;
    }

    /* Camera at the origin looking down -z (fov 60 degrees, GL [-1,1] depth);
     * floor y = -1 (normal +y), wall z = -4 (normal +z). */
    static float depth[W * H], normals[W * H * 4];
    const float n = 0.1f, f = 100.0f, t = 1.0f / tanf(0.5236f);
    float proj[16] = {0};
    proj[0] = t;
    proj[5] = t;
    proj[10] = -(f + n) / (f - n);
    proj[11] = -1.0f;
    proj[14] = -2.0f * f * n / (f - n);
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            const float dy = ((y + 0.5f) / H * 2.0f - 1.0f) / t;
            float hit = 4.0f, ny = 0.0f, nz = 1.0f;
            if (dy < 0.0f && -1.0f / dy < hit) { hit = -1.0f / dy; nz = 0.0f; ny = 1.0f; }
            const float z = -hit;
            const int i = y * W + x;
            depth[i] = (proj[10] * z + proj[14]) / -z * 0.5f + 0.5f;
            normals[i * 4 + 0] = 0.0f;
            normals[i * 4 + 1] = ny;
            normals[i * 4 + 2] = nz;
            normals[i * 4 + 3] = 1.0f;
        }
    GLuint tex[2];
    GenTextures(2, tex);
    BindTexture(GL_TEXTURE_2D, tex[0]);
    TexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT32F, W, H, 0, GL_DEPTH_COMPONENT, GL_FLOAT, depth);
    BindTexture(GL_TEXTURE_2D, tex[1]);
    TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA16F, W, H, 0, GL_RGBA, GL_FLOAT, normals);

    ssao_inputs in = {0};
    in.size = sizeof(in);
    in.depth_texture = tex[0];
    in.normal_texture = tex[1];
    in.normal_packing = SSAO_NORMAL_PACKING_SIGNED;
    memcpy(in.projection, proj, sizeof(in.projection));
    ssao_output out = {0};
    out.size = sizeof(out);
    status = api.execute(ctx, &in, &out);
    if (status != SSAO_OK) {
        fprintf(stderr, "consumer: execute: %s\n", api.last_error(ctx));
        return 1;
    }

    static float ao[W * H];
    GLuint fbo;
    GenFramebuffers(1, &fbo);
    BindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
    FramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, out.texture, 0);
    ReadPixels(out.origin[0], out.origin[1], W, H, GL_RED, GL_FLOAT, ao);
    const int crease_row = (int)((-0.25f * t * 0.5f + 0.5f) * H);  /* view slope of the crease: -1/4 */
    float open = 0.0f, crease = 0.0f;
    for (int x = W / 4; x < 3 * W / 4; ++x) {
        open += ao[4 * W + x];                    /* floor, well in front of the wall */
        crease += ao[(crease_row - 1) * W + x];   /* floor, right at the wall */
    }
    open /= W / 2;
    crease /= W / 2;
    printf("consumer: AO on the open floor %.3f, in the crease %.3f\n", open, crease);
    api.destroy_context(ctx);
    eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(display, context);
    eglTerminate(display);
    return open > 0.95f && crease < open - 0.1f ? 0 : 2;
}
