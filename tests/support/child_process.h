// child_process.h - runs this test executable again in a fresh process with
// other arguments, for cases whose failure may be a crash (a NULL GL function
// called by the library) that must fail one test, not the whole run.
#pragma once

#include <initializer_list>

namespace testgl {

struct ChildResult {
    bool crashed = false;  // ended by a signal
    int code = -1;         // the exit status, -1 when it crashed
};

// Runs /proc/self/exe with argv[0] = `name` and then `args`; waits for it.
// Throws when fork or waitpid fails.
ChildResult run_self(const char* name, std::initializer_list<const char*> args);

}  // namespace testgl
