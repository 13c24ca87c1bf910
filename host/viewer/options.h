// options.h - ssao-viewer's command line.
#pragma once

#include "flags.h"
#include <ssao/ssao.h>

#include <optional>
#include <string>

namespace viewer {

struct Options {
    std::string scene_path;          // empty = the bundled scene
    std::string plugin_path;         // empty = plugin::Library::default_path()
    int width = 800, height = 600;   // the window's client area, as ssao-host's default image
    std::optional<ssao_preset> preset;
    std::string script_path;         // --script: timed key presses
    long frames = 0;                 // --frames: exit after this many frames (0 = run until closed)
    std::string screenshot_dir = "."; // where F12 writes
    bool allow_outside_files = false; // the scene's buffer URIs may leave its folder (scene_limits.h)
};

using Parse = flags::Outcome;

// "--flag value" and "--flag=value"; on Error `error` names the flag.
Parse parse(int argc, const char* const* argv, Options& out, std::string& error);

// The --help text; `demo_script` is where the shipped tour of the keys is.
std::string help_text(const std::string& default_scene, const std::string& demo_script);

// The shipped --script tour of the keys, under the bundled data (locate.h).
inline constexpr const char* kDemoScript = "viewer/demo.txt";

}  // namespace viewer
