// api.cpp - the C ABI: ssao_get_api and the functions of its table. Every
// entry point checks its pointers and struct sizes, and no C++ exception
// crosses the boundary.
#include "context.h"
#include "context_identity.h"
#include "raw_enum.h"
#include "settings.h"
#include "struct_versions.h"
#include "timers.h"

#include <memory>
#include <new>
#include <string>

namespace {

using ssao_impl::resolve_settings;

const char* const kNoContext = "no context (NULL)";

template <typename F>
ssao_status guarded(ssao_context* ctx, F&& body) {
    try {
        return body();
    } catch (const std::bad_alloc&) {
        return ctx ? ctx->fail(SSAO_ERROR_OUT_OF_MEMORY, "out of memory") : SSAO_ERROR_OUT_OF_MEMORY;
    } catch (...) {
        return ctx ? ctx->fail(SSAO_ERROR_INTERNAL, "internal error (exception)") : SSAO_ERROR_INTERNAL;
    }
}

const char* SSAO_CALL status_string(ssao_status status) {
    // On the raw bits (raw_enum.h): a C caller may pass any 32-bit value.
    switch (ssao_impl::raw_enum(status)) {
        case SSAO_OK: return "success";
        case SSAO_ERROR_NULL_POINTER: return "a required pointer argument was NULL";
        case SSAO_ERROR_STRUCT_SIZE: return "a struct's size field matches no known version of that struct";
        case SSAO_ERROR_VERSION_MISMATCH: return "the requested interface version is not provided by this library";
        case SSAO_ERROR_INVALID_ENUM: return "an enum field holds a value outside its documented list";
        case SSAO_ERROR_INVALID_VALUE: return "a number is non-finite or outside its documented range";
        case SSAO_ERROR_INVALID_SIZE: return "a size or viewport is zero, too large, or outside the textures";
        case SSAO_ERROR_INVALID_TEXTURE: return "a texture name is missing, not a 2D texture, of the wrong size or sample count, or both input and output";
        case SSAO_ERROR_UNSUPPORTED_FORMAT: return "a texture's format is not supported";
        case SSAO_ERROR_INVALID_PROJECTION: return "the projection matrix is not a supported projection";
        case SSAO_ERROR_GL_VERSION: return "no GL context is current, or it is older than 3.3 core";
        case SSAO_ERROR_GL_LOAD: return "a required GL function could not be loaded";
        case SSAO_ERROR_SHADER: return "a shader failed to compile or link";
        case SSAO_ERROR_FRAMEBUFFER: return "an internal framebuffer is incomplete";
        case SSAO_ERROR_OUT_OF_MEMORY: return "out of memory";
        case SSAO_ERROR_INTERNAL: return "internal error";
        case SSAO_ERROR_WRONG_CONTEXT: return "the current GL context is not the one the context was created on";
        case SSAO_STATUS_MAX_ENUM: break;
    }
    return "unknown status";
}

ssao_status SSAO_CALL api_resolve_settings(const ssao_settings* in, ssao_settings* out) {
    if (!in || !out) return SSAO_ERROR_NULL_POINTER;
    if (!ssao_impl::is_known_size<ssao_settings>(out->size)) return SSAO_ERROR_STRUCT_SIZE;
    return guarded(nullptr, [&] {
        std::string why;
        ssao_settings resolved{};
        const ssao_status st = resolve_settings(*in, resolved, why);
        if (st == SSAO_OK) ssao_impl::write_prefix(out, resolved);
        return st;
    });
}

ssao_status SSAO_CALL api_preset_settings(ssao_preset preset, ssao_settings* out) {
    if (!out) return SSAO_ERROR_NULL_POINTER;
    if (!ssao_impl::is_known_size<ssao_settings>(out->size)) return SSAO_ERROR_STRUCT_SIZE;
    return guarded(nullptr, [&] {
        std::string why;
        ssao_settings resolved{};
        const ssao_status st = ssao_impl::preset_settings(ssao_impl::raw_enum(preset), resolved, why);
        if (st == SSAO_OK) ssao_impl::write_prefix(out, resolved);
        return st;
    });
}

ssao_status SSAO_CALL api_destroy_context(ssao_context* ctx) {
    if (!ctx) return SSAO_OK;
    // On a foreign GL context the library's names may be that context's own
    // objects: none is deleted there, but the memory is freed all the same
    // (the handle cannot be used on any context afterwards either way).
    std::unique_ptr<ssao_context> owned(ctx);
    return guarded(nullptr, [&] {
        if (ctx->gl_ready && !ssao_impl::on_creating_context(*ctx))
            return ssao_impl::wrong_context(*ctx, "destroy_context (memory freed, no GL object deleted)");
        ssao_impl::release(*ctx);
        return SSAO_OK;
    });
}

ssao_status SSAO_CALL api_create_context(const ssao_context_desc* desc, ssao_context** out) {
    if (!out) return SSAO_ERROR_NULL_POINTER;
    *out = nullptr;
    if (!desc) return SSAO_ERROR_NULL_POINTER;
    auto report = [&](ssao_status st, const char* message) {
        if (desc->size == sizeof(ssao_context_desc) && desc->log) desc->log(desc->log_user, SSAO_LOG_ERROR, message);
        return st;
    };
    if (desc->size != sizeof(ssao_context_desc))
        return report(SSAO_ERROR_STRUCT_SIZE, "ssao_context_desc.size does not match this library");
    if (!desc->get_proc_address)
        return report(SSAO_ERROR_NULL_POINTER, "ssao_context_desc.get_proc_address is NULL");
    return guarded(nullptr, [&]() -> ssao_status {
        ssao_settings settings{};
        settings.size = sizeof settings;
        std::string why;
        if (desc->settings) {
            const ssao_status st = resolve_settings(*desc->settings, settings, why);
            if (st != SSAO_OK) return report(st, ("ssao_context_desc.settings: " + why).c_str());
        } else {
            resolve_settings(settings, settings, why);
        }
        // Owned until handed out: a failure, or an exception out of
        // initialise, releases whatever GL objects were made so far.
        auto destroy = [](ssao_context* c) {
            ssao_impl::release(*c);
            delete c;
        };
        std::unique_ptr<ssao_context, decltype(destroy)> ctx(new (std::nothrow) ssao_context(), destroy);
        if (!ctx) return report(SSAO_ERROR_OUT_OF_MEMORY, "out of memory");
        ctx->log = desc->log;
        ctx->log_user = desc->log_user;
        ctx->settings = settings;
        const ssao_status st = ssao_impl::initialise(*ctx, *desc);
        if (st != SSAO_OK) return st;  // initialise already sent the message to the log
        *out = ctx.release();
        return SSAO_OK;
    });
}

ssao_status SSAO_CALL api_set_settings(ssao_context* ctx, const ssao_settings* settings) {
    if (!ctx || !settings) return ctx ? ctx->fail(SSAO_ERROR_NULL_POINTER, "settings is NULL") : SSAO_ERROR_NULL_POINTER;
    return guarded(ctx, [&] {
        ssao_settings resolved{};
        std::string why;
        const ssao_status st = resolve_settings(*settings, resolved, why);
        if (st != SSAO_OK) return ctx->fail(st, "settings: " + why);
        ctx->settings = resolved;
        ctx->last_error.clear();
        return SSAO_OK;
    });
}

ssao_status SSAO_CALL api_get_settings(const ssao_context* ctx, ssao_settings* out) {
    if (!ctx) return SSAO_ERROR_NULL_POINTER;
    if (!out) return ctx->fail(SSAO_ERROR_NULL_POINTER, "get_settings: out is NULL");
    if (!ssao_impl::is_known_size<ssao_settings>(out->size))
        return ctx->fail(SSAO_ERROR_STRUCT_SIZE, "get_settings: ssao_settings.size matches no version this library knows");
    ssao_impl::write_prefix(out, ctx->settings);
    return SSAO_OK;
}

ssao_status SSAO_CALL api_execute(ssao_context* ctx, const ssao_inputs* inputs, ssao_output* out) {
    if (!ctx) return SSAO_ERROR_NULL_POINTER;
    if (!inputs) return ctx->fail(SSAO_ERROR_NULL_POINTER, "inputs is NULL");
    if (!ssao_impl::is_known_size<ssao_inputs>(inputs->size))
        return ctx->fail(SSAO_ERROR_STRUCT_SIZE, "ssao_inputs.size matches no version of ssao_inputs this library knows");
    if (out && out->size != sizeof(ssao_output))
        return ctx->fail(SSAO_ERROR_STRUCT_SIZE, "ssao_output.size does not match this library");
    const ssao_inputs full = ssao_impl::read_prefix(*inputs);  // a 1.1 host's: the 1.2 fields read as zero
    return guarded(ctx, [&] {
        if (!ssao_impl::on_creating_context(*ctx)) return ssao_impl::wrong_context(*ctx, "execute");
        return ssao_impl::execute(*ctx, full, out);
    });
}

ssao_status SSAO_CALL api_get_timings(ssao_context* ctx, ssao_timings* out) {
    if (!ctx || !out) return ctx ? ctx->fail(SSAO_ERROR_NULL_POINTER, "timings is NULL") : SSAO_ERROR_NULL_POINTER;
    if (!ssao_impl::is_known_size<ssao_timings>(out->size))
        return ctx->fail(SSAO_ERROR_STRUCT_SIZE, "ssao_timings.size matches no version of ssao_timings this library knows");
    return guarded(ctx, [&] {
        if (!ssao_impl::on_creating_context(*ctx)) return ssao_impl::wrong_context(*ctx, "get_timings");
        ssao_impl::collect_timings(*ctx);
        ssao_impl::write_prefix(out, ctx->timings);  // a 1.0 caller gets the fields up to total_ms
        return SSAO_OK;
    });
}

ssao_status SSAO_CALL api_get_frame_info(const ssao_context* ctx, ssao_frame_info* out) {
    if (!ctx) return SSAO_ERROR_NULL_POINTER;
    if (!out) return ctx->fail(SSAO_ERROR_NULL_POINTER, "get_frame_info: out is NULL");
    if (out->size != sizeof(ssao_frame_info))
        return ctx->fail(SSAO_ERROR_STRUCT_SIZE, "get_frame_info: ssao_frame_info.size does not match this library");
    *out = ctx->info;
    out->size = sizeof(ssao_frame_info);
    return SSAO_OK;
}

const char* SSAO_CALL api_last_error(const ssao_context* ctx) {
    return ctx ? ctx->last_error.c_str() : kNoContext;
}

}  // namespace

extern "C" SSAO_EXPORT ssao_status SSAO_CALL ssao_get_api(uint32_t requested_version, ssao_api* api) {
    if (!api) return SSAO_ERROR_NULL_POINTER;
    if (api->size < sizeof(ssao_api)) return SSAO_ERROR_STRUCT_SIZE;  // 1.0 is the first version
    if (SSAO_VERSION_MAJOR(requested_version) != SSAO_VERSION_MAJOR(SSAO_API_VERSION) ||
        SSAO_VERSION_MINOR(requested_version) > SSAO_VERSION_MINOR(SSAO_API_VERSION))
        return SSAO_ERROR_VERSION_MISMATCH;
    ssao_api table{};
    table.size = sizeof(ssao_api);
    table.version = SSAO_API_VERSION;
    table.status_string = status_string;
    table.resolve_settings = api_resolve_settings;
    table.preset_settings = api_preset_settings;
    table.create_context = api_create_context;
    table.destroy_context = api_destroy_context;
    table.set_settings = api_set_settings;
    table.get_settings = api_get_settings;
    table.execute = api_execute;
    table.get_timings = api_get_timings;
    table.get_frame_info = api_get_frame_info;
    table.last_error = api_last_error;
    *api = table;  // a larger (newer) caller table keeps its tail untouched
    return SSAO_OK;
}
