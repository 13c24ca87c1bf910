// scene::load against hostile files (host/scene_limits.h): JSON nested deeper
// than tinygltf's recursion survives, streams that never end, and small files
// that flatten to millions of triangles. Each fails fast with its sentence.
#include "scene.h"

#include <doctest/doctest.h>

#include <atomic>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <new>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>
#include <vector>

#ifndef SSAO_TEST_SCENES_DIR
#error SSAO_TEST_SCENES_DIR must be defined
#endif

namespace fs = std::filesystem;

// Bytes requested from operator new while `g_counting` is set: the loader's
// allocation volume, a deterministic measure of its work (a timing is not).
// Replacing the global operator new/delete pair affects only this test program.
static std::atomic<bool> g_counting{false};
static std::atomic<uint64_t> g_new_bytes{0};
void* operator new(size_t n) {
    if (g_counting.load(std::memory_order_relaxed)) g_new_bytes.fetch_add(n, std::memory_order_relaxed);
    if (void* p = std::malloc(n ? n : 1)) return p;
    throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, size_t) noexcept { std::free(p); }

namespace {

struct TempDir {
    fs::path path;
    TempDir() {
        static int counter = 0;
        path = fs::temp_directory_path() /
               ("ssao_limits_test_" + std::to_string(getpid()) + "_" + std::to_string(counter++));
        fs::create_directories(path);
    }
    ~TempDir() {
        std::error_code ec;
        fs::remove_all(path, ec);
    }
    std::string write(const std::string& name, const std::string& bytes) const {
        const std::string p = (path / name).string();
        std::ofstream(p, std::ios::binary) << bytes;
        return p;
    }
};

std::string read_text(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// corner.gltf with its root object given `"extras": <extras>`.
std::string corner_with_extras(const std::string& extras) {
    std::string json = read_text(std::string(SSAO_TEST_SCENES_DIR) + "/corner.gltf");
    REQUIRE(json.size() > 100u);
    const size_t brace = json.find('{');
    json.insert(brace + 1, "\"extras\":" + extras + ",");
    return json;
}

std::string nested_arrays(size_t depth) { return std::string(depth, '[') + std::string(depth, ']'); }

void put_u32(std::string& s, uint32_t v) {
    for (int i = 0; i < 4; ++i) s += char((v >> (8 * i)) & 0xff);
}

// A .glb: JSON chunk (padded with spaces) and BIN chunk (padded with zeros).
std::string glb(std::string json, std::string bin) {
    while (json.size() % 4) json += ' ';
    while (bin.size() % 4) bin += '\0';
    std::string out = "glTF";
    put_u32(out, 2);
    put_u32(out, uint32_t(12 + 8 + json.size() + 8 + bin.size()));
    put_u32(out, uint32_t(json.size()));
    put_u32(out, 0x4E4F534Au);  // JSON
    out += json;
    put_u32(out, uint32_t(bin.size()));
    put_u32(out, 0x004E4942u);  // BIN
    out += bin;
    return out;
}

// One triangle's three vertices and an index list that repeats it
// `triangles` times, drawn by `nodes` nodes: nodes x triangles once flattened.
std::string repeated_primitive_glb(int nodes, int triangles) {
    std::string bin;
    const float pos[9] = {0, 0, 0, 1, 0, 0, 0, 0, -1};
    bin.append(reinterpret_cast<const char*>(pos), sizeof pos);
    for (int t = 0; t < triangles; ++t)
        for (uint16_t i : {uint16_t(0), uint16_t(1), uint16_t(2)}) bin.append(reinterpret_cast<const char*>(&i), 2);
    const size_t index_bytes = size_t(triangles) * 6;
    std::string node_list, node_refs;
    for (int n = 0; n < nodes; ++n) {
        node_list += std::string(n ? "," : "") + "{\"mesh\":0,\"translation\":[" + std::to_string(n) + ",0,0]}";
        node_refs += std::string(n ? "," : "") + std::to_string(n);
    }
    const std::string json =
        "{\"asset\":{\"version\":\"2.0\"},\"scene\":0,\"scenes\":[{\"nodes\":[" + node_refs + "]}],\"nodes\":[" +
        node_list + "],\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"indices\":1}]}]," +
        "\"buffers\":[{\"byteLength\":" + std::to_string(36 + index_bytes) + "}]," +
        "\"bufferViews\":[{\"buffer\":0,\"byteOffset\":0,\"byteLength\":36},{\"buffer\":0,\"byteOffset\":36," +
        "\"byteLength\":" + std::to_string(index_bytes) + "}]," +
        "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":3,\"type\":\"VEC3\"," +
        "\"min\":[0,0,-1],\"max\":[1,0,0]},{\"bufferView\":1,\"componentType\":5123,\"count\":" +
        std::to_string(triangles * 3) + ",\"type\":\"SCALAR\"}]}";
    return glb(json, bin);
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

TEST_SUITE("scene") {

TEST_CASE("json_nesting_depth counts brackets outside strings only") {
    auto depth = [](const std::string& s, int limit = 1000) {
        return scene::json_nesting_depth(reinterpret_cast<const unsigned char*>(s.data()), s.size(), limit);
    };
    CHECK(depth("") == 0);
    CHECK(depth("{}") == 1);
    CHECK(depth("{\"a\":[1,[2,{\"b\":3}]]}") == 4);
    CHECK(depth("{\"a\":\"[[[[{{{{\"}") == 1);
    CHECK(depth("{\"a\":\"\\\"[[[[\"}") == 1);     // an escaped quote does not end the string
    CHECK(depth("{\"a\":\"\\\\\",\"b\":[[]]}") == 3);  // an escaped backslash does not escape the quote
    CHECK(depth(nested_arrays(100000), 128) == 129);  // stops once past the limit
}

TEST_CASE("extras nested 100,000 deep fail with a sentence, .gltf and .glb") {
    // Before the depth check tinygltf recursed once per level and overflowed the stack.
    TempDir dir;
    const std::string json = corner_with_extras(nested_arrays(100000));
    for (const std::string& path : {dir.write("deep.gltf", json), dir.write("deep.glb", glb(json, ""))}) {
        CAPTURE(path);
        scene::Scene sc;
        std::string err;
        CHECK_FALSE(scene::load(path, sc, err));
        CHECK(err.find(path) != std::string::npos);
        CHECK(err.find("deeper than 128 levels") != std::string::npos);
    }
}

TEST_CASE("extras nested within the limit, and brackets inside strings, still load") {
    TempDir dir;
    scene::Scene sc;
    std::string err;
    const std::string ok = corner_with_extras("{\"a\":" + nested_arrays(100) + ",\"s\":\"" + std::string(5000, '[') + "\"}");
    CHECK_MESSAGE(scene::load(dir.write("ok.gltf", ok), sc, err), err);
    CHECK(sc.mesh.triangle_count() > 0u);
}

TEST_CASE("a stream without end is refused before it is read") {
    // Before the bounded read, the whole stream was read before the size
    // check; now a device is not read at all (test_scene_files.cpp).
    scene::Limits limits;
    limits.max_bytes = uint64_t(1) << 20;
    scene::Scene sc;
    std::string err;
    const auto t0 = std::chrono::steady_clock::now();
    CHECK_FALSE(scene::load("/dev/zero", sc, err, limits));
    CHECK(seconds_since(t0) < 5.0);
    CHECK(err == "/dev/zero: not a regular file but a character device.");
}

TEST_CASE("a regular file over the size limit is refused before it is read") {
    TempDir dir;
    const std::string path = dir.write("big.gltf", std::string(4096, ' '));
    scene::Limits limits;
    limits.max_bytes = 4095;
    scene::Scene sc;
    std::string err;
    CHECK_FALSE(scene::load(path, sc, err, limits));
    CHECK(err == path + ": the file is larger than 4095 bytes.");
    limits.max_bytes = 4096;  // at the limit: read, then refused as JSON
    CHECK_FALSE(scene::load(path, sc, err, limits));
    CHECK(err.find("larger") == std::string::npos);
}

TEST_CASE("a small .glb that repeats one primitive 5,000 times hits the triangle budget fast") {
    // 5,000 nodes x 6,000 triangles = 30 million triangles from ~240 KB;
    // flattening them took over 20 s and gigabytes before the budget.
    TempDir dir;
    const std::string bytes = repeated_primitive_glb(5000, 6000);
    CHECK(bytes.size() < 500000u);  // the size of the 470 KB file or less
    const std::string path = dir.write("amplified.glb", bytes);
    scene::Scene sc;
    std::string err;
    const auto t0 = std::chrono::steady_clock::now();
    CHECK_FALSE(scene::load(path, sc, err));
    CHECK(seconds_since(t0) < 10.0);
    CHECK(err.find("more than 8000000 triangles") != std::string::npos);
    CHECK(err.find("scene budget") != std::string::npos);
}

TEST_CASE("nodes shared as children 40 levels deep (2^40 instances) hit the budget fast") {
    // Each node lists the next one twice: visiting the tree would take 2^40 steps.
    std::string nodes;
    for (int i = 0; i < 40; ++i)
        nodes += std::string(i ? "," : "") + "{\"children\":[" + std::to_string(i + 1) + "," + std::to_string(i + 1) + "]}";
    nodes += ",{\"mesh\":0}";
    std::string json = read_text(std::string(SSAO_TEST_SCENES_DIR) + "/corner.gltf");
    const std::string from = "\"nodes\": [\n    0,\n    1\n   ]";
    REQUIRE(json.find(from) != std::string::npos);
    json.replace(json.find(from), from.size(), "\"nodes\":[0]");
    const size_t list = json.find("\"nodes\": [");  // the top-level node list (the scene's has no space now)
    REQUIRE(list != std::string::npos);
    // The old list's key is renamed: it stays as an ignored extra property.
    json.replace(list, std::string("\"nodes\": ").size(), "\"nodes\":[" + nodes + "],\"unused_nodes\": ");
    TempDir dir;
    scene::Scene sc;
    std::string err;
    const auto t0 = std::chrono::steady_clock::now();
    CHECK_FALSE(scene::load(dir.write("dag.gltf", json), sc, err));
    CHECK(seconds_since(t0) < 5.0);
    CAPTURE(err);
    CHECK(err.find("node instances") != std::string::npos);
}

TEST_CASE("the triangle budget counts flattened triangles: at the budget loads, one over fails") {
    TempDir dir;
    const std::string path = dir.write("ten.glb", repeated_primitive_glb(10, 60));  // 600 triangles
    scene::Limits limits;
    limits.max_triangles = 600;
    scene::Scene sc;
    std::string err;
    REQUIRE_MESSAGE(scene::load(path, sc, err, limits), err);
    CHECK(sc.mesh.triangle_count() == 600u);
    limits.max_triangles = 599;
    CHECK_FALSE(scene::load(path, sc, err, limits));
    CHECK(err.find("more than 599 triangles") != std::string::npos);
}

TEST_CASE("the primitive and vertex budgets count flattened primitives and POSITION vertices: at each loads, one over fails") {
    TempDir dir;
    const std::string path = dir.write("ten.glb", repeated_primitive_glb(10, 60));  // 10 primitives of 3 vertices
    scene::Scene sc;
    std::string err;
    scene::Limits limits;
    limits.max_primitive_instances = 10;
    limits.max_vertices = 30;
    REQUIRE_MESSAGE(scene::load(path, sc, err, limits), err);
    limits.max_primitive_instances = 9;
    CHECK_FALSE(scene::load(path, sc, err, limits));
    CHECK(err.find("more than 9 primitive instances") != std::string::npos);
    limits.max_primitive_instances = 10;
    limits.max_vertices = 29;
    CHECK_FALSE(scene::load(path, sc, err, limits));
    CHECK(err.find("more than 29 vertices") != std::string::npos);
}

TEST_CASE("a mesh of primitives that draw no triangle, repeated by nodes, hits the primitive budget fast") {
    // 2,000 references to one node whose mesh has 2,000 primitives of two
    // vertices each: no triangle for the triangle budget to count, 4 million
    // primitive loads (fuzz_scene found a 64 KB .gltf like it: 45 s under ASan;
    // its input is corpus/scene/regress-primitive-instances.gltf).
    const float pos[6] = {0, 0, 0, 1, 0, 0};
    const std::string bin(reinterpret_cast<const char*>(pos), sizeof pos);
    std::string refs, prims;
    for (int i = 0; i < 2000; ++i) {
        refs += std::string(i ? "," : "") + "0";
        prims += std::string(i ? "," : "") + "{\"attributes\":{\"POSITION\":0}}";
    }
    const std::string json = "{\"asset\":{\"version\":\"2.0\"},\"scene\":0,\"scenes\":[{\"nodes\":[" + refs +
                             "]}],\"nodes\":[{\"mesh\":0}],\"meshes\":[{\"primitives\":[" + prims + "]}]," +
                             "\"buffers\":[{\"byteLength\":24}],\"bufferViews\":[{\"buffer\":0,\"byteLength\":24}]," +
                             "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":2,\"type\":\"VEC3\"," +
                             "\"min\":[0,0,0],\"max\":[1,0,0]}]}";
    TempDir dir;
    scene::Scene sc;
    std::string err;
    const auto t0 = std::chrono::steady_clock::now();
    CHECK_FALSE(scene::load(dir.write("prims.glb", glb(json, bin)), sc, err));
    CHECK(seconds_since(t0) < 5.0);
    CAPTURE(err);
    CHECK(err.find("more than 1000000 primitive instances") != std::string::npos);
    CHECK(err.find("scene budget") != std::string::npos);
}

TEST_CASE("flattening is linear in node instances: 20,000 nodes of one triangle allocate megabytes, not gigabytes") {
    // An exact reserve() per node instance once reallocated the whole index
    // list for every node: 12 * n^2 / 2 bytes, 2.4 GB here, and a 16 KB
    // fuzzed .glb took a minute under ASan (found by fuzz_scene).
    TempDir dir;
    const std::string path = dir.write("many.glb", repeated_primitive_glb(20000, 1));
    scene::Scene sc;
    std::string err;
    g_new_bytes = 0;
    g_counting = true;
    const bool ok = scene::load(path, sc, err);
    g_counting = false;
    REQUIRE_MESSAGE(ok, err);
    CHECK(sc.mesh.triangle_count() == 20000u);
    MESSAGE("scene::load allocated ", g_new_bytes.load() / 1e6, " MB for 20,000 node instances");
    CHECK(g_new_bytes.load() < uint64_t(300) << 20);
}

}  // TEST_SUITE
