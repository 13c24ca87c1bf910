// gl_object_counter.cpp - see gl_object_counter.h.
#include "gl_object_counter.h"

#include <egl_context.h>

#include <glad/gl.h>

#include <cstring>
#include <set>

namespace reliability {

namespace {

std::map<std::string, std::set<GLuint>> g_live;
long long g_calls = 0;

void made(const char* kind, GLsizei n, const GLuint* names) {
    ++g_calls;
    for (GLsizei i = 0; i < n; ++i)
        if (names[i] != 0) g_live[kind].insert(names[i]);
}

void gone(const char* kind, GLsizei n, const GLuint* names) {
    ++g_calls;
    for (GLsizei i = 0; i < n; ++i) g_live[kind].erase(names[i]);
}

// One wrapper per function: the real pointer, then the counting call.
#define SSAO_GEN(fn, kind)                                                                 \
    PFNGL##fn##PROC real_##fn = nullptr;                                                   \
    void GLAD_API_PTR wrap_##fn(GLsizei n, GLuint* names) {                                \
        real_##fn(n, names);                                                               \
        made(kind, n, names);                                                              \
    }
#define SSAO_CREATE_T(fn, kind)                                                            \
    PFNGL##fn##PROC real_##fn = nullptr;                                                   \
    void GLAD_API_PTR wrap_##fn(GLenum target, GLsizei n, GLuint* names) {                 \
        real_##fn(target, n, names);                                                       \
        made(kind, n, names);                                                              \
    }
#define SSAO_DELETE(fn, kind)                                                              \
    PFNGL##fn##PROC real_##fn = nullptr;                                                   \
    void GLAD_API_PTR wrap_##fn(GLsizei n, const GLuint* names) {                          \
        gone(kind, n, names);                                                              \
        real_##fn(n, names);                                                               \
    }

SSAO_GEN(GENTEXTURES, "texture")
SSAO_CREATE_T(CREATETEXTURES, "texture")
SSAO_DELETE(DELETETEXTURES, "texture")
SSAO_GEN(GENBUFFERS, "buffer")
SSAO_GEN(CREATEBUFFERS, "buffer")
SSAO_DELETE(DELETEBUFFERS, "buffer")
SSAO_GEN(GENFRAMEBUFFERS, "framebuffer")
SSAO_GEN(CREATEFRAMEBUFFERS, "framebuffer")
SSAO_DELETE(DELETEFRAMEBUFFERS, "framebuffer")
SSAO_GEN(GENRENDERBUFFERS, "renderbuffer")
SSAO_GEN(CREATERENDERBUFFERS, "renderbuffer")
SSAO_DELETE(DELETERENDERBUFFERS, "renderbuffer")
SSAO_GEN(GENVERTEXARRAYS, "vertex_array")
SSAO_GEN(CREATEVERTEXARRAYS, "vertex_array")
SSAO_DELETE(DELETEVERTEXARRAYS, "vertex_array")
SSAO_GEN(GENSAMPLERS, "sampler")
SSAO_GEN(CREATESAMPLERS, "sampler")
SSAO_DELETE(DELETESAMPLERS, "sampler")
SSAO_GEN(GENQUERIES, "query")
SSAO_CREATE_T(CREATEQUERIES, "query")
SSAO_DELETE(DELETEQUERIES, "query")
SSAO_GEN(GENTRANSFORMFEEDBACKS, "transform_feedback")
SSAO_GEN(CREATETRANSFORMFEEDBACKS, "transform_feedback")
SSAO_DELETE(DELETETRANSFORMFEEDBACKS, "transform_feedback")

PFNGLCREATEPROGRAMPROC real_CREATEPROGRAM = nullptr;
GLuint GLAD_API_PTR wrap_CREATEPROGRAM() {
    const GLuint p = real_CREATEPROGRAM();
    made("program", 1, &p);
    return p;
}
PFNGLDELETEPROGRAMPROC real_DELETEPROGRAM = nullptr;
void GLAD_API_PTR wrap_DELETEPROGRAM(GLuint p) {
    if (p != 0) gone("program", 1, &p);
    real_DELETEPROGRAM(p);
}
PFNGLCREATESHADERPROC real_CREATESHADER = nullptr;
GLuint GLAD_API_PTR wrap_CREATESHADER(GLenum type) {
    const GLuint s = real_CREATESHADER(type);
    made("shader", 1, &s);
    return s;
}
PFNGLDELETESHADERPROC real_DELETESHADER = nullptr;
void GLAD_API_PTR wrap_DELETESHADER(GLuint s) {
    if (s != 0) gone("shader", 1, &s);
    real_DELETESHADER(s);
}

struct Entry {
    const char* name;
    void** real;
    ssao_gl_proc wrapper;
};

#define SSAO_ENTRY(gl_name, fn) \
    {gl_name, reinterpret_cast<void**>(&real_##fn), reinterpret_cast<ssao_gl_proc>(&wrap_##fn)}

const Entry kEntries[] = {
    SSAO_ENTRY("glGenTextures", GENTEXTURES),         SSAO_ENTRY("glCreateTextures", CREATETEXTURES),
    SSAO_ENTRY("glDeleteTextures", DELETETEXTURES),   SSAO_ENTRY("glGenBuffers", GENBUFFERS),
    SSAO_ENTRY("glCreateBuffers", CREATEBUFFERS),     SSAO_ENTRY("glDeleteBuffers", DELETEBUFFERS),
    SSAO_ENTRY("glGenFramebuffers", GENFRAMEBUFFERS), SSAO_ENTRY("glCreateFramebuffers", CREATEFRAMEBUFFERS),
    SSAO_ENTRY("glDeleteFramebuffers", DELETEFRAMEBUFFERS),
    SSAO_ENTRY("glGenRenderbuffers", GENRENDERBUFFERS), SSAO_ENTRY("glCreateRenderbuffers", CREATERENDERBUFFERS),
    SSAO_ENTRY("glDeleteRenderbuffers", DELETERENDERBUFFERS),
    SSAO_ENTRY("glGenVertexArrays", GENVERTEXARRAYS), SSAO_ENTRY("glCreateVertexArrays", CREATEVERTEXARRAYS),
    SSAO_ENTRY("glDeleteVertexArrays", DELETEVERTEXARRAYS),
    SSAO_ENTRY("glGenSamplers", GENSAMPLERS),         SSAO_ENTRY("glCreateSamplers", CREATESAMPLERS),
    SSAO_ENTRY("glDeleteSamplers", DELETESAMPLERS),   SSAO_ENTRY("glGenQueries", GENQUERIES),
    SSAO_ENTRY("glCreateQueries", CREATEQUERIES),     SSAO_ENTRY("glDeleteQueries", DELETEQUERIES),
    SSAO_ENTRY("glGenTransformFeedbacks", GENTRANSFORMFEEDBACKS),
    SSAO_ENTRY("glCreateTransformFeedbacks", CREATETRANSFORMFEEDBACKS),
    SSAO_ENTRY("glDeleteTransformFeedbacks", DELETETRANSFORMFEEDBACKS),
    SSAO_ENTRY("glCreateProgram", CREATEPROGRAM),     SSAO_ENTRY("glDeleteProgram", DELETEPROGRAM),
    SSAO_ENTRY("glCreateShader", CREATESHADER),       SSAO_ENTRY("glDeleteShader", DELETESHADER),
};

}  // namespace

ssao_gl_proc SSAO_CALL counting_get_proc(void* user, const char* name) {
    const ssao_gl_proc real = reinterpret_cast<ssao_gl_proc>(eglctx::Context::get_proc(user, name));
    if (!real || !name) return real;
    for (const Entry& e : kEntries) {
        if (std::strcmp(e.name, name) != 0) continue;
        *e.real = reinterpret_cast<void*>(real);
        return e.wrapper;
    }
    return real;
}

std::map<std::string, long long> live_objects() {
    std::map<std::string, long long> out;
    for (const auto& kind : g_live)
        if (!kind.second.empty()) out[kind.first] = static_cast<long long>(kind.second.size());
    return out;
}

long long live_total() {
    long long n = 0;
    for (const auto& kind : g_live) n += static_cast<long long>(kind.second.size());
    return n;
}

long long wrapped_calls() { return g_calls; }

}  // namespace reliability
