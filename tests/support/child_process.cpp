#include "child_process.h"

#include <sys/wait.h>
#include <unistd.h>

#include <stdexcept>
#include <vector>

namespace testgl {

ChildResult run_self(const char* name, std::initializer_list<const char*> args) {
    std::vector<char*> argv;
    argv.push_back(const_cast<char*>(name));
    for (const char* a : args) argv.push_back(const_cast<char*>(a));
    argv.push_back(nullptr);
    const pid_t pid = fork();
    if (pid < 0) throw std::runtime_error("fork failed");
    if (pid == 0) {
        execv("/proc/self/exe", argv.data());
        _exit(127);
    }
    int status = 0;
    if (waitpid(pid, &status, 0) != pid) throw std::runtime_error("waitpid failed");
    ChildResult r;
    r.crashed = WIFSIGNALED(status);
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}

}  // namespace testgl
