// scene.cpp - glTF 2.0 loading (.gltf and .glb) through tinygltf, flattened to
// one world-space triangle list. See scene.h.
//
// Every accessor is bounds-checked here before it is read (tinygltf does not
// check accessors against their buffers), so a malformed file gives an error
// sentence, never a crash.

#include "scene.h"

#include "gltf_files.h"
#include "input_file.h"
#include "locate.h"

#include <cstdio>

#include "tiny_gltf_quiet.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <limits>
#include <sstream>

namespace scene {
namespace {

// Images are never needed: accept anything so scenes with missing or
// undecodable textures still load.
bool ignore_image(tinygltf::Image*, const int, std::string*, std::string*, int, int,
                  const unsigned char*, int, void*) {
    return true;
}

std::string trim_tinygltf_message(std::string s) {
    while (!s.empty() && (s.back() == '\n' || s.back() == '\r' || s.back() == ' ')) s.pop_back();
    for (char& c : s)
        if (c == '\n' || c == '\r') c = ' ';
    return s;
}

bool ends_with_ci(const std::string& s, const std::string& suffix) {
    if (s.size() < suffix.size()) return false;
    for (size_t i = 0; i < suffix.size(); ++i) {
        char a = s[s.size() - suffix.size() + i];
        if (a >= 'A' && a <= 'Z') a = char(a - 'A' + 'a');
        if (a != suffix[i]) return false;
    }
    return true;
}

uint32_t read_u32le(const unsigned char* p) {
    return uint32_t(p[0]) | (uint32_t(p[1]) << 8) | (uint32_t(p[2]) << 16) | (uint32_t(p[3]) << 24);
}

// Checks the GLB container (header and chunk table) against the file size.
// Returns an empty string when it is sound.
std::string check_glb(const std::vector<unsigned char>& bytes) {
    if (bytes.size() < 12) return "is too short to be a glTF binary (" + std::to_string(bytes.size()) + " bytes)";
    if (std::memcmp(bytes.data(), "glTF", 4) != 0) return "does not start with the glTF binary magic";
    const uint32_t version = read_u32le(bytes.data() + 4);
    if (version != 2) return "is a glTF binary of version " + std::to_string(version) + ", not 2";
    const uint64_t length = read_u32le(bytes.data() + 8);
    if (length > bytes.size())
        return "is truncated: its header says " + std::to_string(length) + " bytes but the file has " +
               std::to_string(bytes.size());
    uint64_t pos = 12;
    int chunk = 0;
    while (pos < length) {
        if (pos + 8 > length) return "is truncated inside a chunk header";
        const uint64_t chunk_len = read_u32le(bytes.data() + pos);
        const uint32_t type = read_u32le(bytes.data() + pos + 4);
        if (pos + 8 + chunk_len > length) return "is truncated: a chunk runs past the end of the file";
        if (chunk == 0 && type != 0x4E4F534Au) return "does not begin with a JSON chunk";
        pos += 8 + chunk_len;
        ++chunk;
    }
    if (chunk == 0) return "has no JSON chunk";
    return {};
}

size_t component_size(int component_type) {
    switch (component_type) {
        case TINYGLTF_COMPONENT_TYPE_BYTE:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
        case TINYGLTF_COMPONENT_TYPE_SHORT:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
        case TINYGLTF_COMPONENT_TYPE_INT:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
        case TINYGLTF_COMPONENT_TYPE_DOUBLE: return 8;
        default: return 0;
    }
}

int component_count(int type) {
    switch (type) {
        case TINYGLTF_TYPE_SCALAR: return 1;
        case TINYGLTF_TYPE_VEC2: return 2;
        case TINYGLTF_TYPE_VEC3: return 3;
        case TINYGLTF_TYPE_VEC4: return 4;
        default: return 0;
    }
}

template <typename T>
T load_unaligned(const unsigned char* p) {
    T v;
    std::memcpy(&v, p, sizeof(T));
    return v;
}

double read_component(const unsigned char* p, int component_type, bool normalized) {
    switch (component_type) {
        case TINYGLTF_COMPONENT_TYPE_BYTE: {
            const double v = load_unaligned<int8_t>(p);
            return normalized ? std::max(v / 127.0, -1.0) : v;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: {
            const double v = load_unaligned<uint8_t>(p);
            return normalized ? v / 255.0 : v;
        }
        case TINYGLTF_COMPONENT_TYPE_SHORT: {
            const double v = load_unaligned<int16_t>(p);
            return normalized ? std::max(v / 32767.0, -1.0) : v;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
            const double v = load_unaligned<uint16_t>(p);
            return normalized ? v / 65535.0 : v;
        }
        case TINYGLTF_COMPONENT_TYPE_INT: return load_unaligned<int32_t>(p);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return load_unaligned<uint32_t>(p);
        case TINYGLTF_COMPONENT_TYPE_FLOAT: return load_unaligned<float>(p);
        case TINYGLTF_COMPONENT_TYPE_DOUBLE: return load_unaligned<double>(p);
        default: return 0.0;
    }
}

class Loader {
public:
    Loader(const tinygltf::Model& m, const std::string& path, const Limits& limits)
        : model_(m), path_(path), limits_(limits) {}

    std::string error;

    bool fail(const std::string& what) {
        if (error.empty()) error = path_ + ": " + what + ".";
        return false;
    }

    // Locates accessor `index`: base pointer, stride and element size, after
    // checking that every element lies inside its buffer.
    bool locate(int index, const char* what, const unsigned char*& base, size_t& stride, size_t& elem,
                const tinygltf::Accessor*& out) {
        const std::string name = std::string(what) + " accessor " + std::to_string(index);
        if (index < 0 || size_t(index) >= model_.accessors.size())
            return fail("refers to " + name + ", which does not exist");
        const tinygltf::Accessor& a = model_.accessors[size_t(index)];
        out = &a;
        if (a.sparse.isSparse) return fail(name + " is sparse, which this loader does not support");
        const size_t csize = component_size(a.componentType);
        const int ccount = component_count(a.type);
        if (csize == 0 || ccount == 0) return fail(name + " has an unsupported component type or element type");
        elem = csize * size_t(ccount);
        if (a.count == 0) {
            base = nullptr;
            stride = elem;
            return true;
        }
        if (a.bufferView < 0 || size_t(a.bufferView) >= model_.bufferViews.size())
            return fail(name + " has no valid bufferView (index " + std::to_string(a.bufferView) + ")");
        const tinygltf::BufferView& bv = model_.bufferViews[size_t(a.bufferView)];
        if (bv.buffer < 0 || size_t(bv.buffer) >= model_.buffers.size())
            return fail("bufferView " + std::to_string(a.bufferView) + " refers to buffer " +
                        std::to_string(bv.buffer) + ", which does not exist");
        const tinygltf::Buffer& buf = model_.buffers[size_t(bv.buffer)];
        const uint64_t buf_size = buf.data.size();
        if (uint64_t(bv.byteOffset) > buf_size || uint64_t(bv.byteLength) > buf_size - bv.byteOffset)
            return fail("bufferView " + std::to_string(a.bufferView) + " (offset " + std::to_string(bv.byteOffset) +
                        ", length " + std::to_string(bv.byteLength) + ") points past the end of buffer " +
                        std::to_string(bv.buffer) + " (" + std::to_string(buf_size) + " bytes)");
        stride = bv.byteStride != 0 ? bv.byteStride : elem;
        if (stride < elem) return fail("bufferView " + std::to_string(a.bufferView) + " has a byteStride smaller than its elements");
        // Last byte read: byteOffset + stride * (count - 1) + elem, in 64-bit without overflow.
        const uint64_t count = a.count;
        if (count > (uint64_t(1) << 40) / stride) return fail(name + " has an absurd count");
        const uint64_t end = uint64_t(a.byteOffset) + uint64_t(stride) * (count - 1) + elem;
        if (end > bv.byteLength)
            return fail(name + " (" + std::to_string(a.count) + " elements from offset " +
                        std::to_string(a.byteOffset) + ") points past the end of its bufferView " +
                        std::to_string(a.bufferView) + " (" + std::to_string(bv.byteLength) + " bytes)");
        base = buf.data.data() + bv.byteOffset + a.byteOffset;
        return true;
    }

    bool read_vec3(int index, const char* what, std::vector<glm::dvec3>& out) {
        const unsigned char* base = nullptr;
        size_t stride = 0, elem = 0;
        const tinygltf::Accessor* a = nullptr;
        if (!locate(index, what, base, stride, elem, a)) return false;
        if (a->type != TINYGLTF_TYPE_VEC3)
            return fail(std::string(what) + " accessor " + std::to_string(index) + " is not of type VEC3");
        const size_t csize = component_size(a->componentType);
        out.resize(a->count);
        for (size_t i = 0; i < a->count; ++i) {
            const unsigned char* p = base + i * stride;
            for (int c = 0; c < 3; ++c) out[i][c] = read_component(p + size_t(c) * csize, a->componentType, a->normalized);
        }
        return true;
    }

    bool read_indices(int index, std::vector<uint32_t>& out) {
        const unsigned char* base = nullptr;
        size_t stride = 0, elem = 0;
        const tinygltf::Accessor* a = nullptr;
        if (!locate(index, "index", base, stride, elem, a)) return false;
        if (a->type != TINYGLTF_TYPE_SCALAR)
            return fail("index accessor " + std::to_string(index) + " is not of type SCALAR");
        if (a->componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
            a->componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
            a->componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
            return fail("index accessor " + std::to_string(index) + " is not of an unsigned integer type");
        out.resize(a->count);
        for (size_t i = 0; i < a->count; ++i) out[i] = uint32_t(read_component(base + i * stride, a->componentType, false));
        return true;
    }

    bool add_primitive(const tinygltf::Primitive& prim, int mesh_index, size_t prim_index, const glm::dmat4& world) {
        const std::string where = "mesh " + std::to_string(mesh_index) + " primitive " + std::to_string(prim_index);
        const int mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
        if (mode == TINYGLTF_MODE_POINTS) return fail(where + " draws points, but only triangles can be shaded");
        if (mode == TINYGLTF_MODE_LINE || mode == TINYGLTF_MODE_LINE_LOOP || mode == TINYGLTF_MODE_LINE_STRIP)
            return fail(where + " draws lines, but only triangles can be shaded");
        if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP && mode != TINYGLTF_MODE_TRIANGLE_FAN)
            return fail(where + " has an unknown mode " + std::to_string(mode));
        if (prim.extensions.count("KHR_draco_mesh_compression"))
            return fail(where + " is Draco-compressed, which this loader does not support");
        auto pos_it = prim.attributes.find("POSITION");
        if (pos_it == prim.attributes.end()) return fail(where + " has no POSITION attribute");

        std::vector<glm::dvec3> pos;
        if (!read_vec3(pos_it->second, "POSITION", pos)) return false;
        std::vector<glm::dvec3> nrm;
        auto nrm_it = prim.attributes.find("NORMAL");
        if (nrm_it != prim.attributes.end()) {
            if (!read_vec3(nrm_it->second, "NORMAL", nrm)) return false;
            if (nrm.size() != pos.size())
                return fail(where + " has " + std::to_string(nrm.size()) + " normals for " + std::to_string(pos.size()) + " positions");
        }
        std::vector<uint32_t> idx;
        if (prim.indices >= 0) {
            if (!read_indices(prim.indices, idx)) return false;
            for (size_t i = 0; i < idx.size(); ++i)
                if (idx[i] >= pos.size())
                    return fail(where + " has index " + std::to_string(idx[i]) + " out of range (" +
                                std::to_string(pos.size()) + " vertices)");
        } else {
            idx.resize(pos.size());
            for (size_t i = 0; i < idx.size(); ++i) idx[i] = uint32_t(i);
        }

        // To a triangle list.
        std::vector<uint32_t> tri;
        if (mode == TINYGLTF_MODE_TRIANGLES) {
            tri.assign(idx.begin(), idx.begin() + std::ptrdiff_t(idx.size() - idx.size() % 3));
        } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
            for (size_t i = 2; i < idx.size(); ++i) {
                if (i % 2 == 0) tri.insert(tri.end(), {idx[i - 2], idx[i - 1], idx[i]});
                else tri.insert(tri.end(), {idx[i - 1], idx[i - 2], idx[i]});
            }
        } else {
            for (size_t i = 2; i < idx.size(); ++i) tri.insert(tri.end(), {idx[0], idx[i - 1], idx[i]});
        }
        if (tri.empty()) return true;

        // Transform.
        const glm::dmat3 normal_matrix = glm::transpose(glm::inverse(glm::dmat3(world)));
        const bool mirrored = glm::determinant(glm::dmat3(world)) < 0.0;
        const uint32_t base = uint32_t(out_.positions.size());
        if (pos.size() > size_t(std::numeric_limits<uint32_t>::max()) - base) return fail("has too many vertices");
        std::vector<glm::vec3> wpos(pos.size());
        for (size_t i = 0; i < pos.size(); ++i) {
            const glm::dvec4 w = world * glm::dvec4(pos[i], 1.0);
            const glm::dvec3 p = glm::dvec3(w) / w.w;
            if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z) ||
                std::fabs(p.x) > 1e30 || std::fabs(p.y) > 1e30 || std::fabs(p.z) > 1e30)
                return fail(where + " has a vertex position that is not finite or beyond 1e30 in world space (vertex " +
                            std::to_string(i) + ")");
            wpos[i] = glm::vec3(p);
        }
        if (mirrored)
            for (size_t t = 0; t + 2 < tri.size(); t += 3) std::swap(tri[t + 1], tri[t + 2]);

        // Area-weighted normals from the (world-space, winding-corrected) triangles.
        std::vector<glm::dvec3> computed(pos.size(), glm::dvec3(0.0));
        for (size_t t = 0; t + 2 < tri.size(); t += 3) {
            const glm::dvec3 a = wpos[tri[t]], b = wpos[tri[t + 1]], c = wpos[tri[t + 2]];
            const glm::dvec3 n = glm::cross(b - a, c - a);  // length = 2 * area
            computed[tri[t]] += n;
            computed[tri[t + 1]] += n;
            computed[tri[t + 2]] += n;
        }
        std::vector<glm::vec3> wnrm(pos.size());
        for (size_t i = 0; i < pos.size(); ++i) {
            glm::dvec3 n(0.0);
            if (!nrm.empty()) n = normal_matrix * nrm[i];
            double len = glm::length(n);
            if (!(len > 1e-20) || !std::isfinite(len)) {
                n = computed[i];
                len = glm::length(n);
            }
            wnrm[i] = (len > 1e-30 && std::isfinite(len)) ? glm::vec3(n / len) : glm::vec3(0.0f, 1.0f, 0.0f);
        }

        out_.positions.insert(out_.positions.end(), wpos.begin(), wpos.end());
        out_.normals.insert(out_.normals.end(), wnrm.begin(), wnrm.end());
        // No reserve(size + n) here: called once per node instance, an exact
        // reserve reallocates (and copies) the whole index list every time,
        // quadratic in the instances (fuzz_scene finds it); the
        // vector's own geometric growth is linear.
        for (uint32_t i : tri) out_.indices.push_back(base + i);
        return true;
    }

    // The scene budget, checked before anything is flattened: nodes that
    // repeat a mesh multiply its triangles, and nodes shared as children
    // multiply whole subtrees (a chain of nodes with two children each
    // doubles per level). So each node's flattened triangles, node and
    // primitive instances and vertices are summed once (memoised over the
    // node graph, saturating), from the accessors' counts alone; visit()
    // checks everything else.
    bool within_budget(const std::vector<int>& roots) {
        memo_.assign(model_.nodes.size(), Cost{});
        Cost total;
        for (int r : roots) total.add(cost(r, 0));
        if (total.instances > limits_.max_node_instances)
            return fail("has more than " + std::to_string(limits_.max_node_instances) +
                        " node instances once flattened (nodes shared as children repeat their subtrees); "
                        "this is the scene budget");
        const struct {
            uint64_t count, limit;
            const char* what;
        } per_mesh[] = {{total.triangles, limits_.max_triangles, "triangles"},
                        {total.primitives, limits_.max_primitive_instances, "primitive instances"},
                        {total.vertices, limits_.max_vertices, "vertices"}};
        for (const auto& b : per_mesh)
            if (b.count > b.limit)
                return fail("has more than " + std::to_string(b.limit) + " " + b.what +
                            " once its nodes are flattened (meshes repeated by nodes count each time); "
                            "this is the scene budget");
        return true;
    }

    static uint64_t saturating_add(uint64_t a, uint64_t b) {
        return a > std::numeric_limits<uint64_t>::max() - b ? std::numeric_limits<uint64_t>::max() : a + b;
    }
    // What flattening a node (or a subtree, or a mesh) makes.
    struct Cost {
        uint64_t triangles = 0, instances = 0, primitives = 0, vertices = 0;
        int state = 0;  // 0 not yet, 1 in progress (a cycle if met again), 2 done
        void add(const Cost& o) {
            triangles = saturating_add(triangles, o.triangles);
            instances = saturating_add(instances, o.instances);
            primitives = saturating_add(primitives, o.primitives);
            vertices = saturating_add(vertices, o.vertices);
        }
    };
    // A mesh's triangles, primitives and POSITION vertices, from the accessors' counts alone.
    Cost mesh_cost(int mesh_index) const {
        Cost c;
        if (mesh_index < 0 || size_t(mesh_index) >= model_.meshes.size()) return c;
        auto count_of = [&](int accessor) -> uint64_t {
            return accessor >= 0 && size_t(accessor) < model_.accessors.size() ? model_.accessors[size_t(accessor)].count
                                                                               : 0;
        };
        for (const tinygltf::Primitive& prim : model_.meshes[size_t(mesh_index)].primitives) {
            const auto pos = prim.attributes.find("POSITION");
            const uint64_t vertices = pos == prim.attributes.end() ? 0 : count_of(pos->second);
            const uint64_t drawn = prim.indices >= 0 ? count_of(prim.indices) : vertices;
            c.triangles = saturating_add(c.triangles, triangles_of(prim.mode, drawn));
            c.primitives = saturating_add(c.primitives, 1);
            c.vertices = saturating_add(c.vertices, vertices);
        }
        return c;
    }
    // Invalid nodes, cycles and overdeep trees cost nothing here: visit()
    // reports them (it stops at the first failure, so they cost it little).
    Cost cost(int node_index, int depth) {
        if (node_index < 0 || size_t(node_index) >= model_.nodes.size() || depth > 256) return Cost{};
        Cost& memo = memo_[size_t(node_index)];
        if (memo.state == 2) return memo;
        if (memo.state == 1) return Cost{};
        memo.state = 1;
        const tinygltf::Node& node = model_.nodes[size_t(node_index)];
        Cost c = mesh_cost(node.mesh);
        c.instances = 1;
        for (int child : node.children) c.add(cost(child, depth + 1));
        c.state = 2;
        memo_[size_t(node_index)] = c;  // memo_ is not resized during the walk
        return c;
    }

    static glm::dmat4 local_matrix(const tinygltf::Node& n) {
        if (n.matrix.size() == 16) {
            glm::dmat4 m;
            for (int c = 0; c < 4; ++c)
                for (int r = 0; r < 4; ++r) m[c][r] = n.matrix[size_t(c * 4 + r)];
            return m;
        }
        glm::dmat4 t(1.0), r(1.0), s(1.0);
        if (n.translation.size() == 3) t = glm::translate(glm::dmat4(1.0), glm::dvec3(n.translation[0], n.translation[1], n.translation[2]));
        if (n.rotation.size() == 4) {
            glm::dquat q(n.rotation[3], n.rotation[0], n.rotation[1], n.rotation[2]);  // w, x, y, z
            const double len = glm::length(q);
            if (len > 0.0 && std::isfinite(len)) r = glm::mat4_cast(q / len);
        }
        if (n.scale.size() == 3) s = glm::scale(glm::dmat4(1.0), glm::dvec3(n.scale[0], n.scale[1], n.scale[2]));
        return t * r * s;
    }

    bool visit(int node_index, const glm::dmat4& parent, int depth) {
        if (node_index < 0 || size_t(node_index) >= model_.nodes.size())
            return fail("refers to node " + std::to_string(node_index) + ", which does not exist");
        if (depth > 256) return fail("has a node hierarchy deeper than 256 levels (a cycle?)");
        const tinygltf::Node& node = model_.nodes[size_t(node_index)];
        const glm::dmat4 world = parent * local_matrix(node);
        if (node.mesh >= 0) {
            if (size_t(node.mesh) >= model_.meshes.size())
                return fail("node " + std::to_string(node_index) + " refers to mesh " + std::to_string(node.mesh) + ", which does not exist");
            const tinygltf::Mesh& mesh = model_.meshes[size_t(node.mesh)];
            for (size_t p = 0; p < mesh.primitives.size(); ++p)
                if (!add_primitive(mesh.primitives[p], node.mesh, p, world)) return false;
        }
        if (node.camera >= 0 && !camera_) {
            if (size_t(node.camera) >= model_.cameras.size())
                return fail("node " + std::to_string(node_index) + " refers to camera " + std::to_string(node.camera) + ", which does not exist");
            const tinygltf::Camera& c = model_.cameras[size_t(node.camera)];
            GltfCamera gc;
            gc.world_from_camera = glm::mat4(world);
            if (c.type == "orthographic") {
                gc.orthographic = true;
                gc.xmag = float(c.orthographic.xmag);
                gc.ymag = float(c.orthographic.ymag);
                gc.znear = float(c.orthographic.znear);
                gc.zfar = float(c.orthographic.zfar);
            } else {
                gc.yfov = float(c.perspective.yfov);
                gc.znear = float(c.perspective.znear);
                gc.zfar = float(c.perspective.zfar);
                gc.aspect = float(c.perspective.aspectRatio);
            }
            camera_ = gc;
        }
        for (int child : node.children)
            if (!visit(child, world, depth + 1)) return false;
        return true;
    }

    const tinygltf::Model& model_;
    std::string path_;
    Limits limits_;
    std::vector<Cost> memo_;  // within_budget's per-node cost
    Mesh out_;
    std::optional<GltfCamera> camera_;
};

void read_hints(const tinygltf::Value& extras, AoHints& h) {
    if (!extras.IsObject() || !extras.Has("ssao")) return;
    const tinygltf::Value& s = extras.Get("ssao");
    if (!s.IsObject()) return;
    auto number = [&](const char* key) -> std::optional<double> {
        if (!s.Has(key)) return std::nullopt;
        const tinygltf::Value& v = s.Get(key);
        if (!v.IsNumber()) return std::nullopt;
        const double d = v.GetNumberAsDouble();
        if (!std::isfinite(d)) return std::nullopt;
        return d;
    };
    if (auto v = number("radius"); v && !h.radius) h.radius = v;
    if (auto v = number("samples"); v && !h.samples) h.samples = v;
    if (auto v = number("bias"); v && !h.bias) h.bias = v;
    if (auto v = number("power"); v && !h.power) h.power = v;
    if (auto v = number("fade_start"); v && !h.fade_start) h.fade_start = v;
    if (auto v = number("fade_end"); v && !h.fade_end) h.fade_end = v;
    if (auto v = number("radius_pixels"); v && !h.radius_pixels) h.radius_pixels = v;
    if (!h.blur && s.Has("blur") && s.Get("blur").IsString()) h.blur = s.Get("blur").Get<std::string>();
}

// A JSON object: its first byte after an optional UTF-8 byte order mark and
// white space is '{'.
bool looks_like_json(const std::vector<unsigned char>& bytes) {
    size_t i = 0;
    if (bytes.size() >= 3 && bytes[0] == 0xEF && bytes[1] == 0xBB && bytes[2] == 0xBF) i = 3;
    while (i < bytes.size() && (bytes[i] == ' ' || bytes[i] == '\t' || bytes[i] == '\n' || bytes[i] == '\r')) ++i;
    return i < bytes.size() && bytes[i] == '{';
}

}  // namespace

std::string default_path() { return locate::bundled("models/spot-on-ground.glb"); }

bool load(const std::string& path, Scene& out, std::string& error, const Limits& limits) {
    error.clear();
    std::vector<unsigned char> bytes;
    if (!input_file::read(path, limits.max_bytes, bytes, error)) return false;
    return load_from_memory(bytes, path, out, error, limits);
}

namespace {

// The checks before any parsing: size, a well-formed GLB container, JSON at
// all (an .obj or a PNG would come back from tinygltf's JSON parser as a raw
// parse error: say what the tools read instead), nesting depth. Sets `json`
// to the JSON text: all of a .gltf, the first chunk of a .glb.
bool precheck(const std::vector<unsigned char>& bytes, const std::string& path, const Limits& limits, bool binary,
              const unsigned char*& json, size_t& json_size, std::string& error) {
    if (bytes.empty()) {
        error = path + ": the file is empty.";
        return false;
    }
    if (bytes.size() > limits.max_bytes) {
        error = path + ": the file is larger than " + input_file::size_text(limits.max_bytes) + ".";
        return false;
    }
    if (binary) {
        const std::string why = check_glb(bytes);
        if (!why.empty()) {
            error = path + ": the file " + why + ".";
            return false;
        }
    }
    if (!binary && !looks_like_json(bytes)) {
        error = path + ": not a glTF scene; the tools read glTF 2.0 only (a .gltf JSON file or a .glb binary)" +
                (ends_with_ci(path, ".gltf") ? std::string() : ", converted with e.g. Blender or obj2gltf") + ".";
        return false;
    }
    json = bytes.data();
    json_size = bytes.size();
    if (binary) {  // check_glb has checked the chunk's length against the file
        json = bytes.data() + 20;
        json_size = read_u32le(bytes.data() + 12);
    }
    if (json_nesting_depth(json, json_size, limits.max_json_depth) > limits.max_json_depth) {
        error = path + ": the JSON nests arrays or objects deeper than " + std::to_string(limits.max_json_depth) +
                " levels, which no glTF needs.";
        return false;
    }
    return true;
}

// tinygltf's parse, reading only the files the plan allows (it gets no base
// directory, so its callbacks see the URIs as written).
bool parse_gltf(const std::vector<unsigned char>& bytes, const std::string& path, bool binary, GltfFiles& files,
                tinygltf::Model& model, std::string& error) {
    tinygltf::TinyGLTF gltf;
    gltf.SetImageLoader(ignore_image, nullptr);
    gltf.SetFsCallbacks(files.callbacks());
    std::string err, warn;
    bool ok = false;
    try {
        if (binary)
            ok = gltf.LoadBinaryFromMemory(&model, &err, &warn, bytes.data(), unsigned(bytes.size()), "");
        else
            ok = gltf.LoadASCIIFromString(&model, &err, &warn, reinterpret_cast<const char*>(bytes.data()),
                                          unsigned(bytes.size()), "");
    } catch (const std::exception& e) {
        ok = false;
        err = e.what();
    }
    if (!ok && !files.error().empty()) {
        error = files.error();
        return false;
    }
    if (!ok) {
        err = trim_tinygltf_message(err);
        error = path + ": tinygltf could not load it" + (err.empty() ? std::string() : " (" + err + ")") + ".";
        return false;
    }
    return true;
}

// The nodes to draw: the default scene's, or with no scene at all every root
// node (those that are nobody's child). -1 as scene_index: no scene.
bool root_nodes(const tinygltf::Model& model, const std::string& path, std::vector<int>& roots, int& scene_index,
                std::string& error) {
    scene_index = model.defaultScene >= 0 ? model.defaultScene : 0;
    if (!model.scenes.empty()) {
        if (size_t(scene_index) >= model.scenes.size()) {
            error = path + ": the default scene " + std::to_string(scene_index) + " does not exist.";
            return false;
        }
        roots = model.scenes[size_t(scene_index)].nodes;
        return true;
    }
    scene_index = -1;
    std::vector<bool> is_child(model.nodes.size(), false);
    for (const auto& n : model.nodes)
        for (int c : n.children)
            if (c >= 0 && size_t(c) < is_child.size()) is_child[size_t(c)] = true;
    for (size_t i = 0; i < model.nodes.size(); ++i)
        if (!is_child[i]) roots.push_back(int(i));
    return true;
}

// The model flattened into one mesh, with its bounds, camera and AO hints.
bool flatten(const tinygltf::Model& model, const std::string& path, const Limits& limits, Scene& out,
             std::string& error) {
    Loader loader(model, path, limits);
    std::vector<int> roots;
    int scene_index = -1;
    if (!root_nodes(model, path, roots, scene_index, error)) return false;
    if (!loader.within_budget(roots)) {
        error = loader.error;
        return false;
    }
    for (int r : roots)
        if (!loader.visit(r, glm::dmat4(1.0), 0)) {
            error = loader.error;
            return false;
        }
    Scene s;
    s.mesh = std::move(loader.out_);
    if (s.mesh.indices.empty()) {
        error = path + ": the scene has nothing to draw (no triangles reachable from the default scene).";
        return false;
    }
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    for (uint32_t i : s.mesh.indices) {
        lo = glm::min(lo, s.mesh.positions[i]);
        hi = glm::max(hi, s.mesh.positions[i]);
    }
    s.bounds_min = lo;
    s.bounds_max = hi;
    s.camera = loader.camera_;
    if (scene_index >= 0) read_hints(model.scenes[size_t(scene_index)].extras, s.hints);
    read_hints(model.extras, s.hints);
    read_hints(model.asset.extras, s.hints);
    out = std::move(s);
    return true;
}

}  // namespace

bool load_from_memory(const std::vector<unsigned char>& bytes, const std::string& path, Scene& out,
                      std::string& error, const Limits& limits) {
    error.clear();
    // Binary when it says so, by magic or by extension; JSON otherwise.
    const bool binary = (bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0) || ends_with_ci(path, ".glb");
    const unsigned char* json = nullptr;
    size_t json_size = 0;
    if (!precheck(bytes, path, limits, binary, json, json_size, error)) return false;
    // Which files the URIs may reach, decided before tinygltf reads any.
    GltfFiles files;
    if (!files.plan(json, json_size, path, limits, error)) return false;
    tinygltf::Model model;
    if (!parse_gltf(bytes, path, binary, files, model, error)) return false;
    try {
        return flatten(model, path, limits, out, error);
    } catch (const std::bad_alloc&) {
        error = path + ": out of memory while flattening the scene.";
    } catch (const std::exception& e) {
        error = path + ": unexpected failure while flattening the scene (" + std::string(e.what()) + ").";
    }
    return false;
}

std::string radius_hint_problem(const AoHints& h) {
    // A normal 32-bit float: below that it would become 0 ("default") or a
    // denormal, beyond it inf.
    if (!h.radius || (*h.radius >= double(std::numeric_limits<float>::min()) &&
                      *h.radius <= double(std::numeric_limits<float>::max())))
        return "";
    char text[112];
    std::snprintf(text, sizeof text, "the scene's hint ssao.radius = %g is not a number in [1.2e-38, 3.4e38]",
                  *h.radius);
    return text;
}

std::optional<AoRadius> ao_radius(const Scene& s) {
    if (s.hints.radius && radius_hint_problem(s.hints).empty())
        return AoRadius{static_cast<float>(*s.hints.radius), "scene hint"};
    const float diagonal = glm::length(s.bounds_max - s.bounds_min);
    if (!(std::isfinite(diagonal) && diagonal > 0.0f)) return std::nullopt;
    char note[64];
    std::snprintf(note, sizeof note, "%g x scene diagonal %.4g", static_cast<double>(kAoRadiusPerDiagonal),
                  static_cast<double>(diagonal));
    return AoRadius{kAoRadiusPerDiagonal * diagonal, note};
}

}  // namespace scene
