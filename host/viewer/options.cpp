#include "options.h"

#include "flags.h"
#include "preset_text.h"

namespace viewer {

Parse parse(int argc, const char* const* argv, Options& o, std::string& error) {
    const flags::Valued valued = {
        {"--width", [&](const std::string& f, const std::string& v) { o.width = int(flags::integer(f, v, 1, 16384)); }},
        {"--height", [&](const std::string& f, const std::string& v) { o.height = int(flags::integer(f, v, 1, 16384)); }},
        {"--plugin", [&](const std::string& f, const std::string& v) {
             if (v.empty()) flags::fail(f + " needs a path");
             o.plugin_path = v;
         }},
        {"--preset", [&](const std::string& f, const std::string& v) {
             o.preset = preset_text::parse(v);
             if (!o.preset) flags::fail(f + " expects one of " + preset_text::choices() + ", got " + flags::quoted(v));
         }},
        {"--script", [&](const std::string& f, const std::string& v) {
             if (v.empty()) flags::fail(f + " needs a file");
             o.script_path = v;
         }},
        {"--frames", [&](const std::string& f, const std::string& v) { o.frames = long(flags::integer(f, v, 1, 100000000)); }},
        {"--screenshot-dir", [&](const std::string& f, const std::string& v) {
             if (v.empty()) flags::fail(f + " needs a folder");
             o.screenshot_dir = v;
         }},
    };
    const flags::Switches switches = {{"--allow-outside-files", [&] { o.allow_outside_files = true; }}};
    return flags::parse(argc, argv, valued, switches, o.scene_path, error);
}

std::string help_text(const std::string& default_scene, const std::string& demo_script) {
    return "ssao-viewer - the SSAO plugin on a glTF scene in a window (GLFW), keys as the reference demo.\n"
           "\n"
           "usage: ssao-viewer [SCENE.gltf|SCENE.glb] [flags]\n"
           "  SCENE                glTF scene (default: " + default_scene + ")\n"
           "                       Camera: the scene's camera, else framed from its bounds; without a scene\n"
           "                       argument, the bundled view of the cow (eye 2.3,1.6,-2.6, target 0,0.65,0),\n"
           "                       the first frame being ssao-host's picture\n"
           "  --width N            window width in pixels (default 800)\n"
           "  --height N           window height in pixels (default 600)\n"
           "  --preset NAME        start from " + preset_text::choices() + " (default: the plugin's defaults, as\n"
           "                       ssao-host)\n"
           "  --plugin PATH        libssao.so to load (default: $SSAO_PLUGIN, then the same places as ssao-host)\n"
           "  --script FILE        timed key presses and resizes (lines 'FRAME KEY', 'FRAME hold KEY N',\n"
           "                       'FRAME resize W H', 'FRAME memory', 'FRAME quit'; frames count from 0);\n"
           "                       each event is printed as it happens. A tour of the keys: " + demo_script + "\n"
           "  --frames N           exit after N frames\n"
           "  --allow-outside-files  let the scene's buffer URIs name files outside its folder (absolute\n"
           "                       paths, '..', symbolic links leading out); refused by default\n"
           "  --screenshot-dir DIR where F12 writes frame-NNNNN.png (default: the current folder)\n"
           "  --help, -h           this text\n"
           "  --version            the version\n"
           "\n"
           "keys:\n"
           "  W A S D              move forward, left, back, right      Q Z   move up, down\n"
           "  I J K L              turn up, left, down, right\n"
           "  C                    camera back to the start view\n"
           "  E R T Y U            the reference demo's modes: E no SSAO, R no rotation, T random rotation,\n"
           "                       Y concentrated kernel, U hemisphere\n"
           "  1 2 3 4              presets low, medium, high, ultra     0   the plugin's defaults\n"
           "  B                    next blur: depth-aware, 4x4 box, gaussian, none\n"
           "  V                    view: lit, AO only                   O   overlay on/off\n"
           "  X                    debug view: none, normals, reconstructed normals, raw AO, blur weights\n"
           "  M                    estimator: point kernel or ray-marched visibility (interface 1.1)\n"
           "  H                    resolution: full, half, quarter\n"
           "  F12                  screenshot                           Esc quit\n";
}

}  // namespace viewer
