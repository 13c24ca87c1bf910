// scene::load on small glTF files written by the test (embedded base64 buffers)
// and on damaged copies of the bundled models.
#include "camera.h"
#include "scene.h"

#include <doctest/doctest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <unistd.h>

#ifndef SSAO_TEST_MODELS_DIR
#error SSAO_TEST_MODELS_DIR must be defined
#endif

namespace fs = std::filesystem;

namespace {

struct TempDir {
    fs::path path;
    TempDir() {
        static int counter = 0;
        path = fs::temp_directory_path() / ("ssao_scene_test_" + std::to_string(getpid()) + "_" + std::to_string(counter++));
        fs::create_directories(path);
    }
    ~TempDir() {
        std::error_code ec;
        fs::remove_all(path, ec);
    }
    std::string write(const std::string& name, const std::string& text) const {
        const std::string p = (path / name).string();
        std::ofstream(p, std::ios::binary) << text;
        return p;
    }
};

std::string base64(const std::vector<unsigned char>& in) {
    static const char* t = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    size_t i = 0;
    for (; i + 2 < in.size(); i += 3) {
        const uint32_t v = (uint32_t(in[i]) << 16) | (uint32_t(in[i + 1]) << 8) | in[i + 2];
        out += t[v >> 18];
        out += t[(v >> 12) & 63];
        out += t[(v >> 6) & 63];
        out += t[v & 63];
    }
    if (i + 1 == in.size()) {
        const uint32_t v = uint32_t(in[i]) << 16;
        out += t[v >> 18];
        out += t[(v >> 12) & 63];
        out += "==";
    } else if (i + 2 == in.size()) {
        const uint32_t v = (uint32_t(in[i]) << 16) | (uint32_t(in[i + 1]) << 8);
        out += t[v >> 18];
        out += t[(v >> 12) & 63];
        out += t[(v >> 6) & 63];
        out += '=';
    }
    return out;
}

struct Bytes {
    std::vector<unsigned char> data;
    template <typename T>
    size_t add(const std::vector<T>& v) {
        while (data.size() % 4) data.push_back(0);
        const size_t off = data.size();
        data.resize(off + v.size() * sizeof(T));
        std::memcpy(data.data() + off, v.data(), v.size() * sizeof(T));
        return off;
    }
    std::string uri() const { return "data:application/octet-stream;base64," + base64(data); }
};

// One triangle (0,0,0), (1,0,0), (0,0,-1) (counter-clockwise seen from +y), as
// float positions; indices in the three component types.
struct TriangleBuffer {
    Bytes b;
    size_t pos, idx8, idx16, idx32;
    TriangleBuffer() {
        pos = b.add(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 0, -1});
        idx8 = b.add(std::vector<uint8_t>{0, 1, 2, 0});
        idx16 = b.add(std::vector<uint16_t>{0, 1, 2, 0});
        idx32 = b.add(std::vector<uint32_t>{0, 1, 2});
    }
    std::string buffer_json() const {
        return "\"buffers\":[{\"byteLength\":" + std::to_string(b.data.size()) + ",\"uri\":\"" + b.uri() + "\"}]";
    }
    std::string views_json() const {
        return "\"bufferViews\":[{\"buffer\":0,\"byteOffset\":" + std::to_string(pos) +
               ",\"byteLength\":36},{\"buffer\":0,\"byteOffset\":" + std::to_string(idx8) +
               ",\"byteLength\":3},{\"buffer\":0,\"byteOffset\":" + std::to_string(idx16) +
               ",\"byteLength\":6},{\"buffer\":0,\"byteOffset\":" + std::to_string(idx32) + ",\"byteLength\":12}]";
    }
};

const char* kAccessors =
    "\"accessors\":["
    "{\"bufferView\":0,\"componentType\":5126,\"count\":3,\"type\":\"VEC3\"},"
    "{\"bufferView\":1,\"componentType\":5121,\"count\":3,\"type\":\"SCALAR\"},"
    "{\"bufferView\":2,\"componentType\":5123,\"count\":3,\"type\":\"SCALAR\"},"
    "{\"bufferView\":3,\"componentType\":5125,\"count\":3,\"type\":\"SCALAR\"}]";

std::string gltf(const std::string& meshes, const std::string& nodes, const std::string& scenes,
                 const std::string& extra = "", const std::string& accessors = kAccessors) {
    TriangleBuffer tb;
    return "{\"asset\":{\"version\":\"2.0\"}," + tb.buffer_json() + "," + tb.views_json() + "," + accessors +
           ",\"meshes\":" + meshes + ",\"nodes\":" + nodes + ",\"scenes\":" + scenes + ",\"scene\":0" + extra + "}";
}

const std::string kOneMesh = "[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"indices\":2}]}]";

bool near3(glm::vec3 a, glm::vec3 b, float eps = 1e-5f) { return glm::length(a - b) <= eps; }

bool has_position(const scene::Mesh& m, glm::vec3 p) {
    for (const auto& q : m.positions)
        if (near3(p, q)) return true;
    return false;
}

}  // namespace

TEST_SUITE("scene") {

TEST_CASE("the bundled models load") {
    for (const char* name : {"spot-on-ground.glb", "teapot-on-ground.glb"}) {
        scene::Scene s;
        std::string err;
        INFO(name);
        REQUIRE(scene::load(std::string(SSAO_TEST_MODELS_DIR) + "/" + name, s, err));
        CHECK(err.empty());
        CHECK(s.mesh.triangle_count() > 5000u);
        CHECK(s.mesh.normals.size() == s.mesh.positions.size());
        CHECK(s.bounds_min.y == doctest::Approx(0.0f));
        CHECK(s.bounds_min.x == doctest::Approx(-4.0f));
        CHECK(s.bounds_max.x == doctest::Approx(4.0f));
        CHECK_FALSE(s.camera.has_value());
        for (const auto& n : s.mesh.normals) REQUIRE(std::fabs(glm::length(n) - 1.0f) < 1e-3f);
    }
}

TEST_CASE("nested node hierarchy: TRS and matrix, any index type, camera, hints") {
    TempDir dir;
    // node 0: translate (10,0,0), child 1. node 1: rotate 90 deg about +y, scale 2,
    // children 2 and 3. node 2: matrix translate (0,1,0), mesh 0 (u16 indices).
    // node 3: mesh 1 (u8) and mesh 2 (u32) via node 4, and the camera.
    const double s = std::sqrt(0.5);
    std::ostringstream nodes;
    nodes << "[{\"translation\":[10,0,0],\"children\":[1]},"
          << "{\"rotation\":[0," << s << ",0," << s << "],\"scale\":[2,2,2],\"children\":[2,3]},"
          << "{\"matrix\":[1,0,0,0, 0,1,0,0, 0,0,1,0, 0,1,0,1],\"mesh\":0},"
          << "{\"mesh\":1,\"camera\":0,\"children\":[4]},"
          << "{\"mesh\":2,\"translation\":[0,0,5]}]";
    const std::string meshes =
        "[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"indices\":2}]},"
        "{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"indices\":1,\"mode\":4}]},"
        "{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"indices\":3},{\"attributes\":{\"POSITION\":0}}]}]";
    const std::string extra =
        ",\"cameras\":[{\"type\":\"perspective\",\"perspective\":{\"yfov\":0.5,\"znear\":0.25,\"zfar\":50}}]";
    const std::string scenes = "[{\"nodes\":[0],\"extras\":{\"ssao\":{\"radius\":0.3,\"samples\":24,\"blur\":\"box\",\"power\":2}}}]";
    const std::string path = dir.write("nested.gltf", gltf(meshes, nodes.str(), scenes, extra));
    scene::Scene sc;
    std::string err;
    REQUIRE_MESSAGE(scene::load(path, sc, err), err);
    REQUIRE(sc.mesh.triangle_count() == 4u);
    // Rotation by +90 deg about y maps (x,y,z) -> (z, y, -x); then scale 2, then +10 in x.
    const glm::mat4 parent = glm::translate(glm::mat4(1), {10, 0, 0}) *
                             glm::rotate(glm::mat4(1), glm::radians(90.0f), {0, 1, 0}) *
                             glm::scale(glm::mat4(1), {2, 2, 2});
    auto world = [&](glm::mat4 local, glm::vec3 p) { return glm::vec3(parent * local * glm::vec4(p, 1)); };
    const glm::mat4 up1 = glm::translate(glm::mat4(1), {0, 1, 0});
    const glm::mat4 fwd5 = glm::translate(glm::mat4(1), {0, 0, 5});
    CHECK(has_position(sc.mesh, world(up1, {1, 0, 0})));
    CHECK(near3(world(up1, {1, 0, 0}), {10, 2, -2}));
    CHECK(has_position(sc.mesh, world(glm::mat4(1), {0, 0, -1})));
    CHECK(has_position(sc.mesh, world(fwd5, {1, 0, 0})));
    // Computed normals: the triangle faces +y, and so does every world copy.
    for (const auto& n : sc.mesh.normals) CHECK(near3(n, {0, 1, 0}, 1e-5f));
    // Camera on node 3 with its world transform.
    REQUIRE(sc.camera.has_value());
    CHECK(sc.camera->yfov == doctest::Approx(0.5f));
    CHECK(sc.camera->znear == doctest::Approx(0.25f));
    CHECK(sc.camera->zfar == doctest::Approx(50.0f));
    CHECK(near3(glm::vec3(sc.camera->world_from_camera[3]), {10, 0, 0}));
    const camera::Camera c = camera::choose(sc, 1.5f);
    CHECK(near3(c.eye, {10, 0, 0}));
    CHECK(near3(glm::normalize(c.target - c.eye), {-1, 0, 0}, 1e-4f));  // local -z turned +90 deg about y
    CHECK(c.znear == doctest::Approx(0.25f));
    // Hints.
    REQUIRE(sc.hints.radius.has_value());
    CHECK(*sc.hints.radius == doctest::Approx(0.3f));
    CHECK(sc.hints.samples.value_or(0) == 24);
    CHECK(sc.hints.blur.value_or("") == "box");
    CHECK(sc.hints.power.value_or(0.0f) == doctest::Approx(2.0f));
    CHECK_FALSE(sc.hints.bias.has_value());
}

TEST_CASE("given normals are transformed with the inverse transpose, mirroring keeps faces outward") {
    TempDir dir;
    TriangleBuffer tb;
    Bytes b = tb.b;
    const size_t nrm = b.add(std::vector<float>{0, 1, 0, 0, 1, 0, 0, 1, 0});
    const std::string json =
        "{\"asset\":{\"version\":\"2.0\"},\"buffers\":[{\"byteLength\":" + std::to_string(b.data.size()) + ",\"uri\":\"" +
        b.uri() + "\"}],\"bufferViews\":[{\"buffer\":0,\"byteOffset\":" + std::to_string(tb.pos) +
        ",\"byteLength\":36},{\"buffer\":0,\"byteOffset\":" + std::to_string(nrm) + ",\"byteLength\":36}],"
        "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":3,\"type\":\"VEC3\"},"
        "{\"bufferView\":1,\"componentType\":5126,\"count\":3,\"type\":\"VEC3\"}],"
        "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0,\"NORMAL\":1}}]},{\"primitives\":[{\"attributes\":{\"POSITION\":0}}]}],"
        "\"nodes\":[{\"mesh\":0,\"scale\":[1,4,1],\"rotation\":[0,0,0.38268343,0.92387953]},{\"mesh\":1,\"scale\":[1,-1,1]}],"
        "\"scenes\":[{\"nodes\":[0,1]}]}";
    scene::Scene sc;
    std::string err;
    REQUIRE_MESSAGE(scene::load(dir.write("n.gltf", json), sc, err), err);
    REQUIRE(sc.mesh.normals.size() == 6u);
    // Non-uniform scale along y leaves a +y normal along y; then 45 deg about z.
    const glm::vec3 expected = glm::normalize(glm::vec3(-1, 1, 0));
    CHECK(near3(sc.mesh.normals[0], expected, 1e-4f));
    // Mirrored copy (scale y by -1): the triangle still lies in y = 0, but its
    // winding is flipped back so the computed normal is the mirror image of +y.
    CHECK(near3(sc.mesh.normals[3], {0, -1, 0}, 1e-5f));
    const glm::vec3 a = sc.mesh.positions[sc.mesh.indices[3]], bb = sc.mesh.positions[sc.mesh.indices[4]],
                    cc = sc.mesh.positions[sc.mesh.indices[5]];
    CHECK(near3(glm::normalize(glm::cross(bb - a, cc - a)), {0, -1, 0}, 1e-5f));
}

TEST_CASE("a missing file") {
    scene::Scene sc;
    std::string err;
    CHECK_FALSE(scene::load("/nonexistent/dir/scene.glb", sc, err));
    CHECK(err.find("/nonexistent/dir/scene.glb") != std::string::npos);
    CHECK(err.find("cannot open") != std::string::npos);
}

TEST_CASE("malformed JSON") {
    TempDir dir;
    scene::Scene sc;
    std::string err;
    CHECK_FALSE(scene::load(dir.write("bad.gltf", "{\"asset\":{\"version\":\"2.0\"},\"nodes\":[{]"), sc, err));
    CHECK(err.find("bad.gltf") != std::string::npos);
    CHECK(err.find("parse") != std::string::npos);
    CHECK_FALSE(scene::load(dir.write("empty.gltf", ""), sc, err));
    CHECK(err.find("empty") != std::string::npos);
}

TEST_CASE("truncated .glb") {
    TempDir dir;
    std::ifstream in(std::string(SSAO_TEST_MODELS_DIR) + "/spot-on-ground.glb", std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    REQUIRE(bytes.size() > 1000u);
    for (size_t keep : {size_t(0), size_t(7), size_t(12), size_t(20), size_t(100), bytes.size() / 2, bytes.size() - 1}) {
        const std::string path = dir.write("cut" + std::to_string(keep) + ".glb", bytes.substr(0, keep));
        scene::Scene sc;
        std::string err;
        INFO("kept " << keep << " bytes");
        CHECK_FALSE(scene::load(path, sc, err));
        CHECK(err.find(path) != std::string::npos);
    }
    // A header that lies about the length (longer than the file).
    std::string lie = bytes;
    lie[8] = char(0xff);
    lie[9] = char(0xff);
    lie[10] = char(0xff);
    scene::Scene sc;
    std::string err;
    CHECK_FALSE(scene::load(dir.write("lie.glb", lie), sc, err));
    CHECK(err.find("truncated") != std::string::npos);
}

TEST_CASE("an accessor past its buffer") {
    TempDir dir;
    const std::string acc =
        "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":300,\"type\":\"VEC3\"},"
        "{\"bufferView\":1,\"componentType\":5121,\"count\":3,\"type\":\"SCALAR\"},"
        "{\"bufferView\":2,\"componentType\":5123,\"count\":3,\"type\":\"SCALAR\"},"
        "{\"bufferView\":3,\"componentType\":5125,\"count\":3,\"type\":\"SCALAR\"}]";
    scene::Scene sc;
    std::string err;
    CHECK_FALSE(scene::load(dir.write("past.gltf", gltf(kOneMesh, "[{\"mesh\":0}]", "[{\"nodes\":[0]}]", "", acc)), sc, err));
    CHECK(err.find("past the end") != std::string::npos);
    CHECK(err.find("past.gltf") != std::string::npos);
    // A bufferView past its buffer.
    TriangleBuffer tb;
    std::string json = gltf(kOneMesh, "[{\"mesh\":0}]", "[{\"nodes\":[0]}]");
    const std::string from = "\"byteLength\":36}";
    json.replace(json.find(from), from.size(), "\"byteLength\":3600}");
    CHECK_FALSE(scene::load(dir.write("view.gltf", json), sc, err));
    CHECK(err.find("past the end") != std::string::npos);
}

TEST_CASE("indices out of range") {
    TempDir dir;
    Bytes b;
    b.add(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 0, -1});
    b.add(std::vector<uint16_t>{0, 1, 7, 0});
    const std::string json =
        "{\"asset\":{\"version\":\"2.0\"},\"buffers\":[{\"byteLength\":" + std::to_string(b.data.size()) + ",\"uri\":\"" +
        b.uri() + "\"}],\"bufferViews\":[{\"buffer\":0,\"byteLength\":36},{\"buffer\":0,\"byteOffset\":36,\"byteLength\":6}],"
        "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":3,\"type\":\"VEC3\"},"
        "{\"bufferView\":1,\"componentType\":5123,\"count\":3,\"type\":\"SCALAR\"}],"
        "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"indices\":1}]}],"
        "\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}]}";
    scene::Scene sc;
    std::string err;
    CHECK_FALSE(scene::load(dir.write("idx.gltf", json), sc, err));
    CHECK(err.find("index 7 out of range") != std::string::npos);
}

TEST_CASE("points and lines are errors, strips and fans become triangles") {
    TempDir dir;
    for (int mode : {0, 1, 2, 3}) {
        const std::string mesh = "[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"mode\":" + std::to_string(mode) + "}]}]";
        scene::Scene sc;
        std::string err;
        INFO("mode " << mode);
        CHECK_FALSE(scene::load(dir.write("m.gltf", gltf(mesh, "[{\"mesh\":0}]", "[{\"nodes\":[0]}]")), sc, err));
        CHECK(err.find(mode == 0 ? "points" : "lines") != std::string::npos);
    }
    for (int mode : {5, 6}) {
        const std::string mesh = "[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"mode\":" + std::to_string(mode) + "}]}]";
        scene::Scene sc;
        std::string err;
        REQUIRE(scene::load(dir.write("s.gltf", gltf(mesh, "[{\"mesh\":0}]", "[{\"nodes\":[0]}]")), sc, err));
        CHECK(sc.mesh.triangle_count() == 1u);
    }
}

TEST_CASE("missing POSITION, empty scene, non-finite positions") {
    TempDir dir;
    scene::Scene sc;
    std::string err;
    const std::string nopos = "[{\"primitives\":[{\"attributes\":{\"NORMAL\":0}}]}]";
    CHECK_FALSE(scene::load(dir.write("np.gltf", gltf(nopos, "[{\"mesh\":0}]", "[{\"nodes\":[0]}]")), sc, err));
    CHECK(err.find("POSITION") != std::string::npos);

    CHECK_FALSE(scene::load(dir.write("e1.gltf", gltf(kOneMesh, "[{\"mesh\":0}]", "[{\"nodes\":[]}]")), sc, err));
    CHECK(err.find("nothing to draw") != std::string::npos);
    CHECK_FALSE(scene::load(dir.write("e2.gltf", "{\"asset\":{\"version\":\"2.0\"}}"), sc, err));
    CHECK(err.find("nothing to draw") != std::string::npos);

    Bytes b;
    b.add(std::vector<float>{0, 0, 0, std::numeric_limits<float>::quiet_NaN(), 0, 0, 0, 0, -1});
    const std::string json =
        "{\"asset\":{\"version\":\"2.0\"},\"buffers\":[{\"byteLength\":36,\"uri\":\"" + b.uri() +
        "\"}],\"bufferViews\":[{\"buffer\":0,\"byteLength\":36}],"
        "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":3,\"type\":\"VEC3\"}],"
        "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0}}]}],\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}]}";
    CHECK_FALSE(scene::load(dir.write("nan.gltf", json), sc, err));
    CHECK(err.find("not finite") != std::string::npos);
}

TEST_CASE("missing textures do not stop a scene from loading") {
    TempDir dir;
    const std::string extra =
        ",\"images\":[{\"uri\":\"does-not-exist.png\"},{\"uri\":\"data:image/png;base64,AAAA\"}],"
        "\"textures\":[{\"source\":0}],\"materials\":[{\"pbrMetallicRoughness\":{\"baseColorTexture\":{\"index\":0}}}]";
    scene::Scene sc;
    std::string err;
    CHECK_MESSAGE(scene::load(dir.write("tex.gltf", gltf(kOneMesh, "[{\"mesh\":0}]", "[{\"nodes\":[0]}]", extra)), sc, err), err);
}

TEST_CASE("a node cycle is an error, not a crash") {
    TempDir dir;
    scene::Scene sc;
    std::string err;
    CHECK_FALSE(scene::load(dir.write("cyc.gltf", gltf(kOneMesh, "[{\"mesh\":0,\"children\":[1]},{\"children\":[0]}]",
                                                        "[{\"nodes\":[0]}]")),
                            sc, err));
    CHECK_FALSE(err.empty());
}

}  // TEST_SUITE
