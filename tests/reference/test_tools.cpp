// The ssao-reference and ssao-error programs: bad input gives one message and a
// non-zero exit with no output; a tiny good run writes its files.
#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
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
        {kModel + " --eye 1,2", "--eye expects three comma-separated numbers"},
        {kModel + " --eye 1,1,1 --target 1,1,1", "same point"},
        {kModel + " --bogus", "unknown flag '--bogus'"},
        {kModel + " --width", "--width needs a value"},
        {kModel + " other.glb", "more than one scene file"},
        {kModel + " --width 16384 --height 16384 --samples 1048576", "absurdly large"},
    };
    for (const auto& c : cases) {
        const Run r = run(kRef + " --out " + out + " --quiet " + c.args);
        INFO(c.args << " -> " << r.output);
        CHECK(r.code != 0);
        CHECK(r.output.find(c.expect) != std::string::npos);
        CHECK(r.output.find("ssao-reference: ") == 0);
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
    CHECK(r.output.find("ssao-reference: out of memory") != std::string::npos);
    CHECK_FALSE(fs::exists(fs::path(out) / "reference_ao.exr"));
#endif
}

TEST_CASE("ssao-reference --help") {
    const Run r = run(kRef + " --help");
    CHECK(r.code == 0);
    CHECK(r.output.find("--samples") != std::string::npos);
    CHECK(r.output.find("--dump-buffers") != std::string::npos);
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
}

}  // TEST_SUITE
