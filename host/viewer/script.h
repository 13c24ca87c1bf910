// script.h - the viewer's --script file: timed key presses and window
// resizes, so a test (or a demo recording) drives the window without a person.
//
//   # a comment; blank lines are ignored
//   12 E              tap E on frame 12 (pressed before frame 12 renders, released before frame 13)
//   20 hold W 15      hold W from frame 20 for 15 frames
//   30 resize 200 150 ask the window for a 200 x 150 client area on frame 30
//   40 memory         print the resident memory on frame 40 (leak checks)
//   50 quit           close the window on frame 50
//
// Frames count from 0, the first frame the window shows. Key names are the
// letters A..Z, the digits 0..9, F1..F12, SPACE, ESCAPE, TAB, UP, DOWN, LEFT,
// RIGHT (upper or lower case).
#pragma once

#include <string>
#include <vector>

namespace viewer {

struct ScriptEvent {
    enum class Kind { Press, Release, Resize, Memory, Quit };
    long frame = 0;
    Kind kind = Kind::Press;
    int key = 0;                 // GLFW key code (Press, Release)
    int width = 0, height = 0;   // Resize
};

// Parses a script's text; events come back sorted by frame (stable, so two
// events on one frame keep their order). On a bad line returns false and sets
// `error` to "LINE: what is wrong".
bool parse_script(const std::string& text, std::vector<ScriptEvent>& events, std::string& error);

// Reads and parses a script file. `error` names the file.
bool load_script(const std::string& path, std::vector<ScriptEvent>& events, std::string& error);

// The GLFW key code of a name ("E", "f12", "space"), or -1 (GLFW_KEY_UNKNOWN).
int key_from_name(const std::string& name);
// The name of a GLFW key code as key_from_name takes it, or "?" for others.
std::string key_name(int key);

}  // namespace viewer
