// gl_object_counter.h - a proc-address function for ssao_context_desc that
// hands the plugin counting wrappers of every glGen* / glCreate* / glDelete*
// it asks for, so a test can see how many GL objects the library owns at any
// moment (made through the wrappers and not yet deleted). One thread only.
#pragma once

#include <ssao/ssao.h>

#include <map>
#include <string>

namespace reliability {

// Give this to ssao_context_desc.get_proc_address; `user` is unused. Real
// functions come from eglctx::Context::get_proc.
ssao_gl_proc SSAO_CALL counting_get_proc(void* user, const char* name);

// Live objects per kind ("texture", "buffer", "program", ...), kinds with
// none left out; and their total.
std::map<std::string, long long> live_objects();
long long live_total();

// Calls of each wrapped function so far (to show the wrappers were used).
long long wrapped_calls();

}  // namespace reliability
