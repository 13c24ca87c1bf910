// scene_limits.h - what a scene file may cost before loading gives up with a
// sentence: file size, JSON nesting depth, what flattening makes (triangles,
// node and primitive instances, vertices) and which files its URIs may reach.
// Scenes come from anywhere; each limit stops one way a small hostile file
// turns into a crash or an unbounded amount of work.
#pragma once

#include "input_file.h"

#include <cstddef>
#include <cstdint>

namespace scene {

struct Limits {
    // Bytes of the scene file, judged by its size before it is read
    // (input_file.h), and of all the buffer files it names together.
    uint64_t max_bytes = input_file::kMaxInputBytes;  // 2 GiB
    // Characters of all its data URIs together: tinygltf decodes each into
    // memory, a few times its size at the peak.
    uint64_t max_data_uri_bytes = uint64_t(1) << 28;  // 256 MiB
    // Buffer URIs may name files outside the scene's folder (absolute
    // paths, "..", symbolic links that lead out). Off: a scene from
    // anywhere reads nothing but its own folder (gltf_files.h).
    bool allow_outside_files = false;
    // Nesting of JSON arrays and objects: tinygltf converts JSON (extras
    // included) recursively, so 100,000 nested brackets overflow the stack.
    // glTF itself needs fewer than 10 levels.
    int max_json_depth = 128;
    // Triangles once every node's meshes are flattened: 5,000 nodes that
    // repeat one 6,000-triangle primitive make 30 million triangles from a
    // 470 KB file. 8 million is ~300 MB flattened and seconds to render on llvmpipe.
    uint64_t max_triangles = 8'000'000;
    // Node instances once flattened: nodes shared as children repeat their
    // subtrees, so 30 levels of two children each are 2^30 instances even
    // without a single triangle.
    uint64_t max_node_instances = 1'000'000;
    // Primitive instances once flattened: each one reads its accessors and
    // allocates whether it draws a triangle or not, so 1,900 nodes that
    // repeat a mesh of 1,900 primitives of two vertices (no triangle) make
    // 3.6 million primitive loads from a 64 KB file.
    uint64_t max_primitive_instances = 1'000'000;
    // Vertices read once flattened (each primitive instance's POSITION
    // count): a primitive may read a large POSITION accessor and index two of
    // its vertices. 24 million is the unindexed vertices of max_triangles,
    // ~600 MB of positions and normals.
    uint64_t max_vertices = 24'000'000;
};

// The deepest nesting of [ ] and { } in the JSON text (brackets inside
// strings do not count). Stops scanning once `limit` is exceeded and returns
// limit + 1 then, so the scan is cheap even on hostile input.
int json_nesting_depth(const unsigned char* text, size_t size, int limit);

// Triangles a primitive of `mode` (a glTF mode, -1 = triangles) draws with
// `count` vertices or indices: count / 3 for a list, count - 2 for a strip or
// fan (and an upper bound for the modes loading refuses).
uint64_t triangles_of(int mode, uint64_t count);

}  // namespace scene
