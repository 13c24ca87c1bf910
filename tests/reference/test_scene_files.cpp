// scene::load and the files a scene names (host/input_file.h,
// host/gltf_files.h): only regular files are read, never past their budget or
// their declared byteLength, and buffer URIs stay inside the scene's folder
// unless Limits::allow_outside_files. Each refusal is one sentence that names
// the URI and never the size of a refused file.
#include "input_file.h"
#include "scene.h"

#include <doctest/doctest.h>

#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

struct Folder {
    fs::path path;
    explicit Folder(const std::string& tag) {
        static int counter = 0;
        path = fs::temp_directory_path() /
               ("ssao_scene_files_" + tag + "_" + std::to_string(getpid()) + "_" + std::to_string(counter++));
        fs::remove_all(path);
        fs::create_directories(path);
    }
    ~Folder() {
        std::error_code ec;
        fs::remove_all(path, ec);
    }
    std::string write(const std::string& name, const std::string& bytes) const {
        const fs::path p = path / name;
        fs::create_directories(p.parent_path());
        std::ofstream(p, std::ios::binary) << bytes;
        return p.string();
    }
    std::string at(const std::string& name) const { return (path / name).string(); }
};

// One triangle: 36 bytes of positions, in the buffer file `uri`.
std::string triangle_bytes() {
    const float pos[9] = {0, 0, 0, 1, 0, 0, 0, 0, -1};
    return std::string(reinterpret_cast<const char*>(pos), sizeof pos);
}
std::string triangle_gltf(const std::string& uri, const std::string& extra = "") {
    return "{\"asset\":{\"version\":\"2.0\"},\"scene\":0,\"scenes\":[{\"nodes\":[0]}],\"nodes\":[{\"mesh\":0}],"
           "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0}}]}],"
           "\"buffers\":[{\"uri\":\"" + uri + "\",\"byteLength\":36}],"
           "\"bufferViews\":[{\"buffer\":0,\"byteLength\":36}],"
           "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":3,\"type\":\"VEC3\","
           "\"min\":[0,0,-1],\"max\":[1,0,0]}]" + extra + "}";
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

struct Result {
    bool ok = false;
    std::string error;
    double seconds = 0.0;
};
Result load(const std::string& path, const scene::Limits& limits = scene::Limits{}) {
    Result r;
    scene::Scene sc;
    const auto t0 = std::chrono::steady_clock::now();
    r.ok = scene::load(path, sc, r.error, limits);
    r.seconds = seconds_since(t0);
    if (r.ok) CHECK(sc.mesh.triangle_count() == 1u);
    CHECK(r.error.find('\n') == std::string::npos);
    return r;
}
scene::Limits outside_allowed() {
    scene::Limits l;
    l.allow_outside_files = true;
    return l;
}
bool has(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

}  // namespace

TEST_SUITE("scene") {

TEST_CASE("input_file refuses what is not a regular file, saying what it is") {
    Folder dir("kinds");
    const std::string fifo = dir.at("pipe");
    REQUIRE(mkfifo(fifo.c_str(), 0600) == 0);
    std::vector<unsigned char> bytes;
    std::string err;
    const auto t0 = std::chrono::steady_clock::now();
    CHECK_FALSE(input_file::read(fifo, 1024, bytes, err));  // before: the open waited for a writer forever
    CHECK(seconds_since(t0) < 5.0);
    CHECK(err == fifo + ": not a regular file but a FIFO (named pipe).");
    CHECK_FALSE(input_file::read("/dev/zero", 1024, bytes, err));
    CHECK(err == "/dev/zero: not a regular file but a character device.");
    CHECK_FALSE(input_file::read(dir.path.string(), 1024, bytes, err));
    CHECK(err == dir.path.string() + ": not a regular file but a directory.");
    // A socket cannot be opened at all: judged by stat before any open.
    const std::string sock_path = dir.at("sock");
    const int s = socket(AF_UNIX, SOCK_STREAM, 0);
    REQUIRE(s >= 0);
    sockaddr_un addr{};
    addr.sun_family = AF_UNIX;
    std::strncpy(addr.sun_path, sock_path.c_str(), sizeof addr.sun_path - 1);
    REQUIRE(bind(s, reinterpret_cast<const sockaddr*>(&addr), sizeof addr) == 0);
    CHECK_FALSE(input_file::read(sock_path, 1024, bytes, err));
    CHECK(err == sock_path + ": not a regular file but a socket.");
    close(s);
    CHECK_FALSE(input_file::read(dir.at("missing"), 1024, bytes, err));
    CHECK(err == dir.at("missing") + ": cannot open the file (No such file or directory).");
    // A regular file: read whole within the budget, refused past it.
    const std::string ten = dir.write("ten", "0123456789");
    CHECK(input_file::read(ten, 10, bytes, err));
    CHECK(bytes.size() == 10u);
    CHECK_FALSE(input_file::read(ten, 9, bytes, err));
    CHECK(err == ten + ": the file is larger than 9 bytes.");
    CHECK(bytes.empty());
}

TEST_CASE("a FIFO, a device or a directory as the scene fails at once with one sentence") {
    Folder dir("scene_kinds");
    const std::string fifo = dir.at("x.gltf");
    REQUIRE(mkfifo(fifo.c_str(), 0600) == 0);
    Result r = load(fifo);  // before: waited forever for a writer
    CHECK_FALSE(r.ok);
    CHECK(r.seconds < 5.0);
    CHECK(r.error == fifo + ": not a regular file but a FIFO (named pipe).");
    r = load("/dev/zero");  // before: read up to the 2 GiB limit first (82 s)
    CHECK_FALSE(r.ok);
    CHECK(r.seconds < 5.0);
    CHECK(r.error == "/dev/zero: not a regular file but a character device.");
    r = load(dir.path.string());
    CHECK_FALSE(r.ok);
    CHECK(r.error == dir.path.string() + ": not a regular file but a directory.");
}

TEST_CASE("a buffer file in the scene's folder loads, a missing one is one sentence") {
    Folder dir("inside");
    dir.write("tri.bin", triangle_bytes());
    dir.write("sub/tri.bin", triangle_bytes());
    CHECK(load(dir.write("a.gltf", triangle_gltf("tri.bin"))).ok);
    CHECK(load(dir.write("b.gltf", triangle_gltf("sub/tri.bin"))).ok);
    CHECK(load(dir.write("c.gltf", triangle_gltf("sub/../tri.bin"))).ok);  // ".." that stays inside
    CHECK(load(dir.write("d.gltf", triangle_gltf("t%72i.bin"))).ok);       // percent-decoded as tinygltf does
    const std::string path = dir.write("e.gltf", triangle_gltf("nope.bin"));
    const Result r = load(path);
    CHECK_FALSE(r.ok);
    CHECK(has(r.error, path + ": buffer URI 'nope.bin' -> "));
    CHECK(has(r.error, "No such file or directory"));
}

TEST_CASE("a buffer URI naming a FIFO, a device or a directory is refused without a hang") {
    Folder dir("buffer_kinds");
    REQUIRE(mkfifo(dir.at("pipe.bin").c_str(), 0600) == 0);
    const std::string path = dir.write("s.gltf", triangle_gltf("pipe.bin"));
    Result r = load(path);  // before: waited forever
    CHECK_FALSE(r.ok);
    CHECK(r.seconds < 5.0);
    CHECK(has(r.error, path + ": buffer URI 'pipe.bin' -> "));
    CHECK(has(r.error, "not a regular file but a FIFO"));
    fs::create_directories(dir.path / "d.bin");
    r = load(dir.write("d.gltf", triangle_gltf("d.bin")));
    CHECK_FALSE(r.ok);
    CHECK(has(r.error, "not a regular file but a directory"));
    // An absolute directory, allowed outside: tinygltf's own reader asked
    // for 0x7fffffffffffffff bytes (std::bad_alloc, an ASan abort).
    r = load(dir.write("abs.gltf", triangle_gltf("/tmp")), outside_allowed());
    CHECK_FALSE(r.ok);
    CHECK(has(r.error, "buffer URI '/tmp' -> /tmp: not a regular file but a directory."));
    r = load(dir.write("zero.gltf", triangle_gltf("/dev/zero")), outside_allowed());
    CHECK_FALSE(r.ok);
    CHECK(has(r.error, "not a regular file but a character device"));
}

TEST_CASE("a buffer file larger than its byteLength is refused before it is read, its size unsaid") {
    Folder dir("big");
    // 3 GiB, sparse: costs no disk. Before: read whole (3.1 GB peak, 250 s).
    const std::string big = dir.at("big.bin");
    { std::ofstream(big, std::ios::binary) << "x"; }
    fs::resize_file(big, uint64_t(3) << 30);
    const std::string path = dir.write("s.gltf", triangle_gltf("big.bin"));
    const Result r = load(path);
    CHECK_FALSE(r.ok);
    CHECK(r.seconds < 5.0);
    CHECK(r.error == path + ": buffer URI 'big.bin' names a file whose size is not the 36 bytes its byteLength declares.");
    CHECK_FALSE(has(r.error, "3221225472"));
    // A few bytes off: the same sentence, not tinygltf's "requestedBytes 36, but got 40".
    dir.write("forty.bin", triangle_bytes() + "pad!");
    const std::string forty = dir.write("f.gltf", triangle_gltf("forty.bin"));
    const Result f = load(forty);
    CHECK_FALSE(f.ok);
    CHECK(has(f.error, "names a file whose size is not the 36 bytes its byteLength declares."));
    CHECK_FALSE(has(f.error, "requestedBytes"));
    // The size is not said: no "40" after the scene's path (the temporary
    // folder's name, which the sentence starts with, may hold those digits).
    REQUIRE(f.error.compare(0, forty.size(), forty) == 0);
    CHECK_FALSE(has(f.error.substr(forty.size()), "40"));
}

TEST_CASE("buffer URIs that leave the scene's folder are refused, naming the URI, unless allowed") {
    Folder dir("outside");
    dir.write("outside.bin", triangle_bytes());
    const std::string scene_dir = (dir.path / "scene").string();
    fs::create_directories(scene_dir);
    const std::string outside = dir.at("outside.bin");
    const std::string cases[] = {"../outside.bin", "/etc/passwd", "../../../../../../etc/passwd", outside,
                                 "sub/../../outside.bin", "%2e%2e/outside.bin"};
    int n = 0;
    for (const std::string& uri : cases) {
        CAPTURE(uri);
        const std::string path = dir.write("scene/s" + std::to_string(n++) + ".gltf", triangle_gltf(uri));
        const Result r = load(path);
        CHECK_FALSE(r.ok);
        CHECK(r.error == path + ": buffer 0's URI '" + uri +
                             "' names a file outside the scene's folder; --allow-outside-files allows it.");
        // Nothing about /etc/passwd's size (before: "requestedBytes 36, but got 1221").
        CHECK_FALSE(has(r.error, "requested"));
        CHECK_FALSE(has(r.error, "got"));
    }
    // A URI with a line break (JSON "\n") and a long one: still one line, cut short.
    const std::string broken = dir.write("scene/nl.gltf", triangle_gltf("../x\\ny.bin"));
    Result r = load(broken);
    CHECK_FALSE(r.ok);
    CHECK(has(r.error, "buffer 0's URI '../x\\x0ay.bin' names a file outside"));
    const std::string long_uri = "../" + std::string(5000, 'a');
    r = load(dir.write("scene/long.gltf", triangle_gltf(long_uri)));
    CHECK_FALSE(r.ok);
    CHECK(r.error.size() < 500u);
    CHECK(has(r.error, "buffer 0's URI '../aaaa"));
    CHECK(has(r.error, "aaa...' "));
    // Allowed: the file outside is read like one inside.
    CHECK(load(dir.write("scene/ok1.gltf", triangle_gltf("../outside.bin")), outside_allowed()).ok);
    CHECK(load(dir.write("scene/ok2.gltf", triangle_gltf(outside)), outside_allowed()).ok);
}

TEST_CASE("a symbolic link in the folder that leads out is refused, one that stays in loads") {
    Folder dir("links");
    dir.write("outside.bin", triangle_bytes());
    dir.write("scene/real.bin", triangle_bytes());
    fs::create_symlink(dir.at("outside.bin"), dir.at("scene/out.bin"));
    fs::create_symlink("real.bin", dir.at("scene/in.bin"));
    fs::create_directory_symlink(dir.path, dir.at("scene/up"));
    Result r = load(dir.write("scene/a.gltf", triangle_gltf("out.bin")));
    CHECK_FALSE(r.ok);
    CHECK(has(r.error, "buffer 0's URI 'out.bin' names a file outside the scene's folder"));
    r = load(dir.write("scene/b.gltf", triangle_gltf("up/outside.bin")));
    CHECK_FALSE(r.ok);
    CHECK(has(r.error, "buffer 0's URI 'up/outside.bin' names a file outside the scene's folder"));
    CHECK(load(dir.write("scene/c.gltf", triangle_gltf("in.bin"))).ok);
    CHECK(load(dir.write("scene/d.gltf", triangle_gltf("out.bin")), outside_allowed()).ok);
}

TEST_CASE("images are never read: an image URI naming a FIFO or a file outside costs nothing") {
    Folder dir("images");
    dir.write("tri.bin", triangle_bytes());
    REQUIRE(mkfifo(dir.at("tex.png").c_str(), 0600) == 0);
    const Result r = load(dir.write("s.gltf", triangle_gltf("tri.bin", ",\"images\":[{\"uri\":\"tex.png\"},"
                                                                    "{\"uri\":\"/etc/passwd\"},{\"uri\":\"/dev/zero\"}]")));
    CHECK_MESSAGE(r.ok, r.error);
    CHECK(r.seconds < 5.0);
}

TEST_CASE("data URIs beyond their budget are refused with one sentence") {
    Folder dir("data");
    // The triangle as a data URI: 36 bytes are 48 characters of base64.
    const std::string uri = "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAAAAAAIC/";
    const std::string path = dir.write("s.gltf", triangle_gltf(uri));
    CHECK(load(path).ok);
    scene::Limits small;
    small.max_data_uri_bytes = uri.size() - 1;
    const Result r = load(path, small);
    CHECK_FALSE(r.ok);
    CHECK(r.error == path + ": buffer 0's data URI takes the scene's data URIs past their budget of " +
                         std::to_string(uri.size() - 1) + " bytes.");
    // Image data URIs count too (tinygltf decodes them).
    dir.write("tri.bin", triangle_bytes());
    const std::string img = dir.write("i.gltf", triangle_gltf("tri.bin", ",\"images\":[{\"uri\":\"data:image/png;base64," +
                                                                          std::string(400, 'A') + "\"}]"));
    small.max_data_uri_bytes = 100;
    const Result ri = load(img, small);
    CHECK_FALSE(ri.ok);
    CHECK(has(ri.error, "image 0's data URI takes the scene's data URIs past their budget of 100 bytes."));
}

TEST_CASE("a byteLength past the byte budget is refused before any file is opened") {
    Folder dir("budget");
    REQUIRE(mkfifo(dir.at("tri.bin").c_str(), 0600) == 0);  // would be refused as a FIFO, were it opened
    std::string json = triangle_gltf("tri.bin");
    json.replace(json.find("\"byteLength\":36}"), 16, "\"byteLength\":3000000000}");
    const std::string path = dir.write("s.gltf", json);
    const Result r = load(path);
    CHECK_FALSE(r.ok);
    CHECK(r.error == path + ": buffer 0 declares a byteLength larger than the 2 GiB budget of a buffer.");
}

}  // TEST_SUITE
