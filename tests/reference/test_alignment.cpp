// reference.host_alignment: ssao-host (rasteriser) and ssao-reference (ray
// tracer) must see the same surface at every pixel. Runs both on the bundled
// scene for several cameras (perspective, odd size, infinite far + reverse-Z,
// orthographic) and compares ssao-host's view_depth.exr with
// reference_depth.exr. Exit 0 = pass, 1 = fail, 77 = skipped (ssao-host could
// not render here, e.g. no EGL).
#include "image_io.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

namespace fs = std::filesystem;

namespace {

int run(const std::string& cmd, std::string& out) {
    out.clear();
    FILE* p = popen((cmd + " 2>&1").c_str(), "r");
    if (!p) return -1;
    char buf[4096];
    size_t n;
    while ((n = fread(buf, 1, sizeof buf, p)) > 0) out.append(buf, n);
    const int st = pclose(p);
    return WIFEXITED(st) ? WEXITSTATUS(st) : 128;
}

}  // namespace

int main() {
    const fs::path dir = fs::temp_directory_path() / ("ssao_alignment_" + std::to_string(getpid()));
    fs::create_directories(dir);
    const std::string model = std::string(SSAO_TEST_MODELS_DIR) + "/spot-on-ground.glb";
    struct Case {
        const char* name;
        const char* flags;
    };
    const Case cases[] = {
        {"framed", "--width 96 --height 64"},
        {"close, odd size", "--width 97 --height 61 --eye 2.5,1.8,3 --target 0,0.6,0"},
        {"infinite far, reverse-Z", "--width 80 --height 80 --fov 60 --far inf --reverse-z --eye -3,2,2 --target 0,0.5,0"},
        {"orthographic", "--width 90 --height 70 --ortho 1.5 --eye 2.5,1.8,3 --target 0,0.6,0"},
    };
    int failures = 0;
    for (const auto& c : cases) {
        const std::string h = (dir / "host").string(), r = (dir / "ref").string();
        std::string out;
        const int hc = run(std::string(SSAO_HOST_EXE) + " " + model + " " + c.flags + " --out " + h, out);
        if (hc != 0) {
            std::printf("SKIP: ssao-host could not render (%s): %s\n", c.name, out.c_str());
            fs::remove_all(dir);
            return 77;
        }
        if (run(std::string(SSAO_REFERENCE_EXE) + " " + model + " " + c.flags + " --samples 1 --dump-buffers --quiet --out " + r,
                out) != 0) {
            std::printf("FAIL: ssao-reference (%s): %s\n", c.name, out.c_str());
            ++failures;
            continue;
        }
        std::vector<float> hd, rd;
        int hw = 0, hh = 0, rw = 0, rh = 0;
        std::string err;
        if (!refio::read_exr_channel(h + "/view_depth.exr", {"Y", "Z", "R"}, hd, hw, hh, err) ||
            !refio::read_exr_channel(r + "/reference_depth.exr", {"Z"}, rd, rw, rh, err) || hw != rw || hh != rh) {
            std::printf("FAIL: cannot compare the depth images (%s): %s\n", c.name, err.c_str());
            ++failures;
            continue;
        }
        // Pixels where one sees sky and the other geometry, or the depths differ by
        // more than 0.1%, may only be silhouette pixels: allow 0.5% of the image.
        size_t differ = 0, geometry = 0;
        for (size_t i = 0; i < hd.size(); ++i) {
            const bool hs = std::isfinite(hd[i]), rs = std::isfinite(rd[i]);
            if (rs) ++geometry;
            if (hs != rs || (hs && std::fabs(hd[i] - rd[i]) > 1e-3f * rd[i])) ++differ;
        }
        const bool ok = geometry > hd.size() / 10 && differ <= hd.size() / 200;
        std::printf("%s: %s, %zu geometry pixels, %zu differ\n", ok ? "ok  " : "FAIL", c.name, geometry, differ);
        if (!ok) ++failures;
        fs::remove_all(h);
        fs::remove_all(r);
    }
    fs::remove_all(dir);
    return failures ? 1 : 0;
}
