// run_program.h - running one of the project's programs from a test, the way
// a user does: under a kill timeout, stdout and stderr captured, the exit
// status kept. Header-only (no library to link): the host, fade, MSAA and
// debug-view tests share it.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace testrun {

inline std::string read_file(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    std::ostringstream s;
    s << f.rdbuf();
    return s.str();
}

// An empty directory `work`/`name` (removed first if it exists).
inline std::string fresh_dir(const std::string& work, const std::string& name) {
    const std::filesystem::path p = std::filesystem::path(work) / name;
    std::filesystem::remove_all(p);
    std::filesystem::create_directories(p);
    return p.string();
}

inline std::string shell_quote(const std::string& s) {
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

struct Run {
    int exit_code = -1;  // -1: killed by a signal or by the timeout
    std::string out, err;
};

// `prefix program args...` under `timeout -s KILL timeout_s`; stdout and
// stderr go through files in `log_dir` (removed afterwards). `prefix` runs
// the command under another (xvfb-run, say).
inline Run run(const std::string& program, const std::vector<std::string>& args, const std::string& log_dir,
               int timeout_s = 60, const std::string& prefix = "") {
    static int counter = 0;
    std::filesystem::create_directories(log_dir);
    const std::string tag = std::to_string(::getpid()) + "_" + std::to_string(counter++);
    const std::string out_path = log_dir + "/out_" + tag, err_path = log_dir + "/err_" + tag;
    std::string cmd = prefix + (prefix.empty() ? "" : " ") + "timeout -s KILL " + std::to_string(timeout_s) + " " +
                      shell_quote(program);
    for (const auto& a : args) cmd += " " + shell_quote(a);
    cmd += " >" + shell_quote(out_path) + " 2>" + shell_quote(err_path);
    const int status = std::system(cmd.c_str());
    Run r;
    if (WIFEXITED(status) && WEXITSTATUS(status) < 128) r.exit_code = WEXITSTATUS(status);
    r.out = read_file(out_path);
    r.err = read_file(err_path);
    std::filesystem::remove(out_path);
    std::filesystem::remove(err_path);
    return r;
}

}  // namespace testrun
