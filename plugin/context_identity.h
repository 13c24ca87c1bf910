// context_identity.h - tells whether the GL context current on this thread is
// the one a context was created on, asking GL only queries that raise no
// error and change nothing. Container objects (vertex arrays, framebuffers,
// queries) are never shared between GL contexts, so the library's vertex
// array names its context: it exists only there, and with KHR_debug it
// carries a label no other context in the process has.
#pragma once

#include <ssao/ssao.h>

struct ssao_context;

namespace ssao_impl {

// create_context, after the vertex array's name was generated: makes it an
// object (one bind, with the host's binding put back) and, with KHR_debug,
// gives it its unique label.
void mark_creating_context(ssao_context& ctx);

// Whether the GL context current now is the creating one.
bool on_creating_context(const ssao_context& ctx);

// SSAO_ERROR_WRONG_CONTEXT, with last_error (and the log) saying which call
// was refused and what to do.
ssao_status wrong_context(const ssao_context& ctx, const char* call);

}  // namespace ssao_impl
