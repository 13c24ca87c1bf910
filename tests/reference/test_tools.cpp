// The ssao-reference and ssao-error programs: bad input gives one message and a
// non-zero exit with no output; a tiny good run writes its files.
#include "image_io.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#ifndef SSAO_REFERENCE_EXE
#error SSAO_REFERENCE_EXE must be defined
#endif

namespace fs = std::filesystem;

namespace {

struct Run {
    int code = -1;
    std::string output;  // stdout and stderr
};

Run run(const std::string& args) {
    Run r;
    const std::string cmd = args + " 2>&1";
    FILE* p = popen(cmd.c_str(), "r");
    if (!p) return r;
    std::array<char, 4096> buf;
    size_t n;
    while ((n = fread(buf.data(), 1, buf.size(), p)) > 0) r.output.append(buf.data(), n);
    const int status = pclose(p);
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : 128;
    return r;
}

struct TempDir {
    fs::path path;
    TempDir() {
        path = fs::temp_directory_path() / ("ssao_tools_test_" + std::to_string(getpid()));
        fs::remove_all(path);
        fs::create_directories(path);
    }
    ~TempDir() {
        std::error_code ec;
        fs::remove_all(path, ec);
    }
};

const std::string kRef = SSAO_REFERENCE_EXE;
const std::string kErr = SSAO_ERROR_EXE;
const std::string kModel = std::string(SSAO_TEST_MODELS_DIR) + "/spot-on-ground.glb";

}  // namespace

TEST_SUITE("tools") {

TEST_CASE("ssao-reference: bad input fails with one message and writes nothing") {
    TempDir dir;
    const std::string out = (dir.path / "out").string();
    struct Case {
        std::string args, expect;
    };
    const Case cases[] = {
        {"/nonexistent/scene.glb", "cannot open"},
        {kModel + " --width 0", "--width 0 is out of range"},
        {kModel + " --width abc", "--width expects a whole number"},
        {kModel + " --height 99999", "--height 99999 is out of range"},
        {kModel + " --samples 0", "--samples 0 is out of range"},
        {kModel + " --radius -1", "--radius -1 must be greater than 0"},
        {kModel + " --radius nan", "--radius expects a finite number"},
        {kModel + " --fov 200", "--fov 200 is out of range"},
        {kModel + " --ortho 2 --fov 40", "exclude each other"},
        {kModel + " --near 5 --far 1", "--far must be greater than --near"},
        {kModel + " --far 0.001", "--far 0.001 is not beyond the near plane fitted to the scene"},
        {kModel + " --near 1000", "--near 1000 is not in front of the far plane fitted to the scene"},
        {kModel + " --radius 1e39", "--radius 1e39 is out of range (0, 1e+30]"},
        {kModel + " --eye 1,2", "--eye expects three comma-separated numbers"},
        {kModel + " --eye 1,1,1 --target 1,1,1", "same point"},
        {kModel + " --bogus", "unknown flag '--bogus'"},
        {kModel + " --radus 0.3", "unknown flag '--radus'; did you mean --radius? (see --help)"},
        {kModel + " --thick 0.3", "unknown flag '--thick'; did you mean --thickness? (see --help)"},
        {std::string(SSAO_TEST_MODELS_DIR), "not a regular file but a directory"},
        {kModel + " --width", "--width needs a value"},
        {kModel + " other.glb", "more than one scene file"},
        {kModel + " --width 16384 --height 16384 --samples 1048576", "absurdly large"},
        {kModel + " --limit --thickness 0", "--thickness 0 must be greater than 0"},
        {kModel + " --limit --thickness -0.5", "--thickness -0.5 must be greater than 0"},
        {kModel + " --limit --thickness abc", "--thickness expects a finite number or 'inf'"},
        {kModel + " --limit --thickness nan", "--thickness expects a finite number or 'inf'"},
        {kModel + " --limit --thickness", "--thickness needs a value"},
        {kModel + " --thickness 0.1", "--thickness applies only with --limit"},
        {kModel + " --limit --limit-directions 12", "--limit-directions 12 must be a multiple of 8"},
        {kModel + " --limit --limit-directions 0", "--limit-directions 0 is out of range"},
        {kModel + " --limit-directions 64", "--limit-directions applies only with --limit"},
    };
    for (const auto& c : cases) {
        const Run r = run(kRef + " --out " + out + " --quiet " + c.args);
        INFO(c.args << " -> " << r.output);
        CHECK(r.code != 0);
        CHECK(r.output.find(c.expect) != std::string::npos);
        CHECK(r.output.find("ssao-reference: error: ") == 0);
        CHECK(std::count(r.output.begin(), r.output.end(), '\n') == 1);
        CHECK_FALSE(fs::exists(out));
    }
    // A damaged scene.
    const std::string bad = (dir.path / "bad.gltf").string();
    std::ofstream(bad) << "{ not json";
    const Run r = run(kRef + " " + bad + " --out " + out);
    CHECK(r.code != 0);
    CHECK(r.output.find("bad.gltf") != std::string::npos);
    CHECK_FALSE(fs::exists(out));
    // An output path that is a file.
    const std::string file = (dir.path / "file").string();
    std::ofstream(file) << "x";
    const Run f = run(kRef + " " + kModel + " --width 4 --height 4 --samples 1 --quiet --out " + file);
    CHECK(f.code != 0);
    CHECK(f.output.find("not a folder") != std::string::npos);
}

// ASan and TSan reserve terabytes of address space, so `ulimit -v` cannot
// be used under them; the sanitizer build skips the memory-limit test.
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define SSAO_TEST_SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
#define SSAO_TEST_SANITIZED 1
#endif
#endif

TEST_CASE("ssao-reference: an image too large for the memory limit is one message, not an abort") {
#ifdef SSAO_TEST_SANITIZED
    MESSAGE("skipped: ulimit -v does not work under a sanitizer");
#else
    // 16384 x 16384 needs several 1 GiB images; under a 2 GiB limit the
    // allocation fails. Before main caught std::bad_alloc this aborted (SIGABRT).
    TempDir dir;
    const std::string out = (dir.path / "out").string();
    const Run r = run("ulimit -v 2097152; " + kRef + " " + kModel +
                      " --width 16384 --height 16384 --samples 1 --quiet --out " + out);
    INFO(r.output);
    CHECK(r.code == 1);
    CHECK(r.output.find("ssao-reference: error: out of memory") != std::string::npos);
    CHECK_FALSE(fs::exists(fs::path(out) / "reference_ao.exr"));
#endif
}

TEST_CASE("ssao-reference --help") {
    const Run r = run(kRef + " --help");
    CHECK(r.code == 0);
    CHECK(r.output.find("--samples") != std::string::npos);
    CHECK(r.output.find("--dump-buffers") != std::string::npos);
    CHECK(r.output.find("--limit") != std::string::npos);
    CHECK(r.output.find("--thickness") != std::string::npos);
}

TEST_CASE("ssao-reference --limit: limit_ao.exr laid out as reference_ao.exr, sky 1, deterministic, ssao-error splits") {
    TempDir dir;
    const std::string a = (dir.path / "a").string(), b = (dir.path / "b").string();
    const std::string args = " " + kModel + " --width 40 --height 24 --samples 16 --limit --limit-directions 64 --quiet";
    const Run r = run(kRef + args + " --out " + a);
    INFO(r.output);
    REQUIRE(r.code == 0);
    CHECK(r.output.find("limit     depth-only, thickness") != std::string::npos);
    CHECK(r.output.find("(0.5 x R)") != std::string::npos);
    CHECK(r.output.find("limit     vs V_R over all geometry: RMSE") != std::string::npos);
    for (const char* f : {"limit_ao.exr", "limit_stderr.exr", "limit_ao.png"}) CHECK(fs::exists(fs::path(a) / f));
    // Same layout: the same size, Y and A, the same coverage; sky is 1 with 0 noise.
    std::vector<float> ref, cover, lim, lim_cover, lim_se;
    int w = 0, h = 0, lw = 0, lh = 0;
    std::string err;
    REQUIRE(refio::read_exr_channel(a + "/reference_ao.exr", {"Y"}, ref, w, h, err));
    REQUIRE(refio::read_exr_channel(a + "/reference_ao.exr", {"A"}, cover, w, h, err));
    REQUIRE(refio::read_exr_channel(a + "/limit_ao.exr", {"Y"}, lim, lw, lh, err));
    REQUIRE(refio::read_exr_channel(a + "/limit_ao.exr", {"A"}, lim_cover, lw, lh, err));
    REQUIRE(refio::read_exr_channel(a + "/limit_stderr.exr", {"Y"}, lim_se, lw, lh, err));
    CHECK(lw == w);
    CHECK(lh == h);
    CHECK(lim_cover == cover);
    size_t sky = 0, geo = 0;
    for (size_t i = 0; i < lim.size(); ++i) {
        if (cover[i] < 0.5f) {
            ++sky;
            CHECK(lim[i] == 1.0f);
            CHECK(lim_se[i] == 0.0f);
        } else {
            ++geo;
            CHECK(lim[i] >= 0.0f);
            CHECK(lim[i] <= 1.0f);
        }
    }
    CHECK(sky > 0);
    CHECK(geo > 0);
    // Deterministic for a seed, whatever the thread count.
    REQUIRE(run(kRef + args + " --threads 1 --out " + b).code == 0);
    std::vector<float> again;
    REQUIRE(refio::read_exr_channel(b + "/limit_ao.exr", {"Y"}, again, lw, lh, err));
    CHECK(again == lim);
    // --thickness changes it: a height field (inf) blocks at least as much as T = R/2.
    const std::string c = (dir.path / "c").string();
    REQUIRE(run(kRef + args + " --thickness inf --out " + c).code == 0);
    std::vector<float> field;
    REQUIRE(refio::read_exr_channel(c + "/limit_ao.exr", {"Y"}, field, lw, lh, err));
    double sum_lim = 0.0, sum_field = 0.0;
    for (size_t i = 0; i < lim.size(); ++i) {
        sum_lim += lim[i];
        sum_field += field[i];
    }
    CHECK(sum_field < sum_lim);

    // ssao-error picks the limit up from the folder and splits the error.
    const Run e = run(kErr + " " + a + "/reference_ao.exr " + a);
    INFO(e.output);
    REQUIRE(e.code == 0);
    CHECK(e.output.find("limit      " + a + "/limit_ao.exr") != std::string::npos);
    CHECK(e.output.find("limit vs V_R (unavoidable)") != std::string::npos);
    CHECK(e.output.find("ours vs limit (estimator)") != std::string::npos);
    // The limit tested against the limit: ours vs limit is exact (PSNR inf) on every mask.
    const Run self = run(kErr + " " + a + "/limit_ao.exr " + a + "/reference_ao.exr --limit " + a + "/limit_ao.exr");
    REQUIRE(self.code == 0);
    CHECK(self.output.find("inf   0.0000\n") != std::string::npos);
    // A limit from another camera (other coverage) or of another size is refused.
    const std::string other = (dir.path / "other").string();
    REQUIRE(run(kRef + args + " --eye 3,2,3 --target 0,0.5,0 --out " + other).code == 0);
    const Run wrong = run(kErr + " " + a + "/reference_ao.exr " + a + "/reference_ao.exr --limit " + other + "/limit_ao.exr");
    CHECK(wrong.code != 0);
    CHECK(wrong.output.find("not from the same scene and camera") != std::string::npos);
    const std::string small = (dir.path / "small").string();
    REQUIRE(run(kRef + " " + kModel + " --width 8 --height 8 --samples 1 --limit --limit-directions 8 --quiet --out " +
                small).code == 0);
    const Run size = run(kErr + " " + a + "/reference_ao.exr " + a + "/reference_ao.exr --limit " + small + "/limit_ao.exr");
    CHECK(size.code != 0);
    CHECK(size.output.find("8x8") != std::string::npos);
    const Run missing = run(kErr + " " + a + "/reference_ao.exr " + a + " --limit " + a + "/nope.exr");
    CHECK(missing.code != 0);
    CHECK(missing.output.find("nope.exr") != std::string::npos);
}

TEST_CASE("a tiny reference run, compared with itself by ssao-error") {
    TempDir dir;
    const std::string out = (dir.path / "ref").string();
    const Run r = run(kRef + " " + kModel + " --width 24 --height 16 --samples 16 --quiet --dump-buffers --out " + out);
    INFO(r.output);
    REQUIRE(r.code == 0);
    for (const char* f : {"reference_ao.exr", "reference_stderr.exr", "reference_ao.png", "reference_depth.exr",
                          "reference_normal.exr"})
        CHECK(fs::exists(fs::path(out) / f));
    const std::string csv = (dir.path / "e.csv").string();
    const Run e = run(kErr + " " + out + "/reference_ao.exr " + out + " --csv " + csv + " --label self");
    INFO(e.output);
    REQUIRE(e.code == 0);
    CHECK(e.output.find("interior") != std::string::npos);
    CHECK(e.output.find("inf") != std::string::npos);  // PSNR of identical images
    std::ifstream in(csv);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    CHECK(text.rfind("label,mask,", 0) == 0);
    CHECK(text.find("self,all,") != std::string::npos);

    // ssao-error: bad input.
    const Run missing = run(kErr + " " + out + "/nope.exr " + out);
    CHECK(missing.code != 0);
    CHECK(missing.output.find("nope.exr") != std::string::npos);
    const Run one = run(kErr + " " + out + "/reference_ao.exr");
    CHECK(one.code != 0);
    CHECK(one.output.find("expected two images") != std::string::npos);
    const std::string small = (dir.path / "small").string();
    REQUIRE(run(kRef + " " + kModel + " --width 8 --height 8 --samples 1 --quiet --out " + small).code == 0);
    const Run mismatch = run(kErr + " " + small + "/reference_ao.exr " + out);
    CHECK(mismatch.code != 0);
    CHECK(mismatch.output.find("8x8") != std::string::npos);
    const Run band = run(kErr + " a.exr b.exr --band x");
    CHECK(band.code != 0);
    CHECK(band.output.find("--band") != std::string::npos);
    // A CSV it cannot write fails before the table, with the reason; an empty path is a usage error.
    const Run unwritable = run(kErr + " " + out + "/reference_ao.exr " + out + " --csv " + out + "/no/such/dir/e.csv");
    CHECK(unwritable.code == 1);
    CHECK(unwritable.output.find("ssao-error: error: cannot write") == 0);
    CHECK(unwritable.output.find("No such file or directory") != std::string::npos);
    CHECK(std::count(unwritable.output.begin(), unwritable.output.end(), '\n') == 1);
    const Run empty_csv = run(kErr + " " + out + "/reference_ao.exr " + out + " --csv ''");
    CHECK(empty_csv.code == 2);
    CHECK(empty_csv.output.find("--csv expects a file") != std::string::npos);
    // A failed comparison leaves the CSV it opened empty; the next run still writes the header.
    const std::string after_failure = (dir.path / "after.csv").string();
    CHECK(run(kErr + " " + small + "/reference_ao.exr " + out + " --csv " + after_failure).code == 1);
    REQUIRE(run(kErr + " " + out + "/reference_ao.exr " + out + " --csv " + after_failure + " --label self").code == 0);
    std::ifstream again(after_failure);
    const std::string rows((std::istreambuf_iterator<char>(again)), std::istreambuf_iterator<char>());
    CHECK(rows.rfind("label,mask,", 0) == 0);
}

TEST_CASE("ssao-error refuses images that are not AO, and a reference with nothing to compare") {
    TempDir dir;
    const int w = 8, h = 4;
    const size_t n = size_t(w * h);
    auto write = [&](const std::string& name, std::vector<float> y, std::vector<float> a = {}) {
        const std::string p = (dir.path / name).string();
        std::string err;
        std::vector<refio::Channel> ch = {{"Y", &y}};
        if (!a.empty()) ch.push_back({"A", &a});
        REQUIRE_MESSAGE(refio::write_exr(p, w, h, ch, err), err);
        return p;
    };
    const std::vector<float> half(n, 0.5f), ones(n, 1.0f), zeros(n, 0.0f);
    const std::string good_ref = write("ref.exr", half, ones);
    const std::string good_test = write("test.exr", half);
    REQUIRE(run(kErr + " " + good_test + " " + good_ref).code == 0);
    // Within the tolerance of 0.001: still AO.
    std::vector<float> edge(n, 1.0005f);
    edge[0] = -0.0005f;
    CHECK(run(kErr + " " + write("edge.exr", edge) + " " + good_ref).code == 0);

    struct Case {
        std::string test, ref, expect;
    };
    std::vector<float> nan_ref(n, std::nanf("")), inf_ref(n, INFINITY), big_test(n, 0.5f), neg_test(n, 0.5f),
        nan_test(n, 0.5f);
    big_test[n - 1] = 1.5f;
    neg_test[9] = -1e38f;
    nan_test[3] = std::nanf("");
    const Case cases[] = {
        // Before: exit 0 with "0 pixels" compared and no warning.
        {good_test, write("nan_ref.exr", nan_ref, ones), "32 of 32 compared pixels are NaN or infinite (the first at x 0, y 0)"},
        {good_test, write("inf_ref.exr", inf_ref, ones), "32 of 32 compared pixels are NaN or infinite"},
        {good_test, write("nan_ref_no_a.exr", nan_ref), "32 of 32 compared pixels are NaN or infinite"},
        // Before: RMSE 1e38 with exit 0.
        {write("neg.exr", neg_test), good_ref, "1 of 32 compared pixels are outside [0, 1] by more than 0.001 (the first, -1e+38, at x 1, y 1)"},
        {write("big.exr", big_test), good_ref, "(the first, 1.5, at x 7, y 3)"},
        {write("nan_test.exr", nan_test), good_ref, "1 of 32 compared pixels are NaN or infinite (the first at x 3, y 0)"},
        {good_test, write("sky_ref.exr", half, zeros), "has no pixel to compare: all of it is sky"},
    };
    for (const Case& c : cases) {
        const Run r = run(kErr + " " + c.test + " " + c.ref);
        INFO(r.output);
        CHECK(r.code == 1);
        CHECK(r.output.find(c.expect) != std::string::npos);
        CHECK(r.output.rfind("ssao-error: error: ", 0) == 0);
        CHECK(std::count(r.output.begin(), r.output.end(), '\n') == 1);
    }
    // Sky pixels of the test are not compared, so not judged.
    std::vector<float> sky_a(ones), sky_test(half);
    sky_a[0] = 0.0f;
    sky_test[0] = std::nanf("");
    CHECK(run(kErr + " " + write("sky_nan_test.exr", sky_test) + " " + write("ref_sky0.exr", half, sky_a)).code == 0);
}

TEST_CASE("ssao-error on a FIFO, a directory or a damaged EXR: one line, exit 1, no hang") {
    TempDir dir;
    const std::string fifo = (dir.path / "fifo.exr").string();
    REQUIRE(mkfifo(fifo.c_str(), 0600) == 0);
    const std::vector<float> y(16, 0.5f);
    const std::string ref = (dir.path / "ref.exr").string();
    std::string err;
    REQUIRE(refio::write_exr(ref, 4, 4, {{"Y", &y}}, err));
    std::string bytes;
    {
        std::ifstream in(ref, std::ios::binary);
        bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    }
    const std::string truncated = (dir.path / "truncated.exr").string();
    std::ofstream(truncated, std::ios::binary) << bytes.substr(0, bytes.size() - 20);
    const std::string text = (dir.path / "text.exr").string();
    std::ofstream(text) << "not an image\n";
    struct Case {
        std::string args, expect;
    };
    const Case cases[] = {
        {fifo + " " + ref, fifo + ": not a regular file but a FIFO (named pipe)."},  // before: waited forever
        {ref + " " + fifo, fifo + ": not a regular file but a FIFO (named pipe)."},
        {"/dev/zero " + ref, "/dev/zero: not a regular file but a character device."},
        {text + " " + ref, text + ": not an OpenEXR file."},
        // Missing and not EXR are told apart.
        {text + ".missing " + ref, text + ".missing: cannot open the file (No such file or directory)."},
        {truncated + " " + ref, truncated + ": "},
    };
    for (const Case& c : cases) {
        const Run r = run("timeout -s KILL 20 " + kErr + " " + c.args);
        INFO(c.args << " -> " << r.output);
        CHECK(r.code == 1);
        CHECK(r.output.find("ssao-error: error: " + c.expect) == 0);
        CHECK(std::count(r.output.begin(), r.output.end(), '\n') == 1);
    }
}

TEST_CASE("ssao-reference: a scene that is a FIFO, or whose buffer leaves its folder, is one line") {
    TempDir dir;
    const std::string fifo = (dir.path / "x.gltf").string();
    REQUIRE(mkfifo(fifo.c_str(), 0600) == 0);
    const std::string out = (dir.path / "out").string();
    Run r = run("timeout -s KILL 20 " + kRef + " " + fifo + " --quiet --out " + out);
    CHECK(r.code == 1);
    CHECK(r.output == "ssao-reference: error: " + fifo + ": not a regular file but a FIFO (named pipe).\n");
    // One triangle whose 36-byte buffer lies beside the scene's folder.
    fs::create_directories(dir.path / "scene");
    const float pos[9] = {0, 0, 0, 1, 0, 0, 0, 0, -1};
    std::ofstream((dir.path / "tri.bin").string(), std::ios::binary).write(reinterpret_cast<const char*>(pos), sizeof pos);
    const std::string scene = (dir.path / "scene" / "s.gltf").string();
    std::ofstream(scene) << "{\"asset\":{\"version\":\"2.0\"},\"scene\":0,\"scenes\":[{\"nodes\":[0]}],\"nodes\":[{\"mesh\":0}],"
                            "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0}}]}],"
                            "\"buffers\":[{\"uri\":\"../tri.bin\",\"byteLength\":36}],"
                            "\"bufferViews\":[{\"buffer\":0,\"byteLength\":36}],"
                            "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":3,\"type\":\"VEC3\","
                            "\"min\":[0,0,-1],\"max\":[1,0,0]}]}";
    r = run(kRef + " " + scene + " --quiet --width 4 --height 4 --samples 1 --out " + out);
    CHECK(r.code == 1);
    CHECK(r.output == "ssao-reference: error: " + scene +
                          ": buffer 0's URI '../tri.bin' names a file outside the scene's folder; "
                          "--allow-outside-files allows it.\n");
    CHECK_FALSE(fs::exists(out));
    r = run(kRef + " " + scene + " --allow-outside-files --quiet --width 4 --height 4 --samples 1 --out " + out);
    INFO(r.output);
    CHECK(r.code == 0);
    CHECK(fs::exists(fs::path(out) / "reference_ao.exr"));
}

TEST_CASE("ssao-reference: a file that is not glTF is named as such, not as a JSON parse error") {
    TempDir dir;
    const std::string obj = (dir.path / "model.obj").string();
    std::ofstream(obj) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    const std::string png = (dir.path / "picture.gltf").string();
    std::ofstream(png, std::ios::binary) << "\x89PNG\r\n\x1a\n";
    for (const std::string& path : {obj, png}) {
        const Run r = run(kRef + " " + path + " --quiet --out " + (dir.path / "out").string());
        INFO(r.output);
        CHECK(r.code == 1);
        CHECK(r.output.rfind("ssao-reference: error: " + path + ": not a glTF scene; the tools read glTF 2.0 only", 0) == 0);
        CHECK(r.output.find("json") == std::string::npos);
        CHECK(std::count(r.output.begin(), r.output.end(), '\n') == 1);
    }
}

TEST_CASE("ssao-error refuses images made with another camera, radius or size, naming the field, --allow-mismatch compares") {
    TempDir dir;
    auto reference = [&](const std::string& name, const std::string& flags) {
        const std::string out = (dir.path / name).string();
        const Run r = run(kRef + " --width 24 --height 16 --samples 4 --quiet --out " + out + " " + flags);
        INFO(r.output);
        REQUIRE(r.code == 0);
        return out;
    };
    const std::string base = reference("base", "");
    const std::string again = reference("again", "--seed 7");   // another seed: the same view
    const std::string eye = reference("eye", "--eye 3,2,-3");
    const std::string radius = reference("radius", "--radius 0.25");
    const std::string ortho = reference("ortho", "--ortho 1.5");
    const std::string test = base + "/reference_ao.exr";

    // What the header records (scene by file name, camera, radius).
    refio::Attributes made;
    std::string err;
    REQUIRE(refio::read_exr_attributes(test, "ssao:", made, err));
    auto field = [&](const std::string& name) {
        for (const auto& a : made)
            if (a.first == "ssao:" + name) return a.second;
        return std::string("(none)");
    };
    CHECK(field("scene") == "spot-on-ground.glb");
    CHECK(field("size") == "24x16");
    CHECK(field("eye") == "2.3,1.6,-2.6");        // the bundled view, as ssao-host's default
    CHECK(field("target") == "0,0.65,0");
    CHECK(field("projection") == "perspective fov 45 deg");
    CHECK(field("depth") == "[-1,1]");
    CHECK(field("thickness") == "(none)");

    const Run same = run(kErr + " " + test + " " + again);
    INFO(same.output);
    CHECK(same.code == 0);
    CHECK(same.output.find("note") == std::string::npos);

    struct Case {
        std::string ref, line;
    };
    const Case cases[] = {
        // Before: compared, PSNR printed, exit 0.
        {eye, "ssao-error: error: " + test + " and " + eye + "/reference_ao.exr were made with a different eye: "
              "2.3,1.6,-2.6 vs 3,2,-3 (--allow-mismatch compares them anyway).\n"},
        {radius, "ssao-error: error: " + test + " and " + radius + "/reference_ao.exr were made with a different "
                 "radius: 0.57418 vs 0.25 (--allow-mismatch compares them anyway).\n"},
        {ortho, "ssao-error: error: " + test + " and " + ortho + "/reference_ao.exr were made with a different "
                "projection: perspective fov 45 deg vs orthographic half-height 1.5 (--allow-mismatch compares them anyway).\n"},
    };
    for (const Case& c : cases) {
        const Run r = run(kErr + " " + test + " " + c.ref);
        CHECK(r.code == 1);
        CHECK(r.output == c.line);
        const Run allowed = run(kErr + " " + test + " " + c.ref + " --allow-mismatch");
        INFO(allowed.output);
        CHECK(allowed.code == 0);
        CHECK(allowed.output.rfind("mismatch   ", 0) == 0);
        CHECK(allowed.output.find("all ") != std::string::npos);
    }

    // An image without the record (another program, an older file): compared, with a note.
    std::vector<float> y;
    int w = 0, h = 0;
    REQUIRE(refio::read_exr_channel(test, {"Y"}, y, w, h, err));
    const std::string bare = (dir.path / "bare.exr").string();
    REQUIRE(refio::write_exr(bare, w, h, {{"Y", &y}}, err));
    const Run note = run(kErr + " " + bare + " " + eye);
    INFO(note.output);
    CHECK(note.code == 0);
    CHECK(note.output.find("note       " + bare + " records no scene and camera") != std::string::npos);
}

}  // TEST_SUITE
