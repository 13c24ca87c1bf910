// scene.h - glTF scene loading shared by ssao-host and ssao-reference.
// The scene is flattened: every triangle of the default scene in world space,
// so the rasteriser (host) and the ray tracer (reference) see the same geometry.
#pragma once

#include "scene_limits.h"

#include <glm/glm.hpp>

#include <optional>
#include <string>
#include <vector>

namespace scene {

// One flattened triangle list in world space (node transforms applied).
struct Mesh {
    std::vector<glm::vec3> positions;   // world space
    std::vector<glm::vec3> normals;     // world space, unit; computed where the primitive has none
    std::vector<uint32_t> indices;      // 3 per triangle
    size_t triangle_count() const { return indices.size() / 3; }
};

// A camera found in the glTF (the first one reachable from the default scene).
struct GltfCamera {
    glm::mat4 world_from_camera{1.0f};  // node transform; camera looks down its -Z
    bool orthographic = false;
    float yfov = 0.0f;                  // radians (perspective)
    float xmag = 0.0f, ymag = 0.0f;     // half extents (orthographic)
    float znear = 0.0f;
    float zfar = 0.0f;                  // 0 = infinite (perspective)
    float aspect = 0.0f;                // 0 = not given
};

// AO settings a scene may carry in the extras of its scene or of its root
// glTF object: {"ssao": {"radius": 0.3, "samples": 32, "blur": "depth-aware", ...}}
// (also "fade_start", "fade_end", "radius_pixels": the ssao_settings fields).
// As the JSON holds them (any finite number): the tools check their ranges.
struct AoHints {
    std::optional<double> radius;       // scene units
    std::optional<double> samples;
    std::optional<std::string> blur;    // names as the host's --blur flag takes
    std::optional<double> bias;
    std::optional<double> power;
    std::optional<double> fade_start, fade_end;  // view depth (scene units)
    std::optional<double> radius_pixels;         // viewport pixels, 0 = off
};

struct Scene {
    Mesh mesh;
    glm::vec3 bounds_min{0.0f}, bounds_max{0.0f};
    std::optional<GltfCamera> camera;
    AoHints hints;
};

// The AO radius a scene calls for, one rule for every tool: its hint
// extras.ssao.radius, else 0.05 x its bounding-box diagonal (so a scene in
// millimetres looks like one in metres). Empty when the scene has neither (no
// extent). `source` says which, for printing ("scene hint", "0.05 x scene
// diagonal 11.48"). A radius hint that radius_hint_problem refuses is not used.
struct AoRadius {
    float radius = 0.0f;
    std::string source;
};
constexpr float kAoRadiusPerDiagonal = 0.05f;
std::optional<AoRadius> ao_radius(const Scene& s);
// Why the scene's radius hint cannot be a radius (not a normal 32-bit float
// > 0), or "" when it can or there is none.
std::string radius_hint_problem(const AoHints& h);

// The scene every tool uses when none is given: the bundled
// models/spot-on-ground.glb (locate::bundled). With it and no camera flags the
// tools start from camera::kBundledEye (camera::initial).
std::string default_path();

// Loads .gltf or .glb. On failure returns false and sets `error` to one
// sentence naming the problem (missing file, malformed JSON, truncated glb,
// accessor past its buffer, non-triangle primitive, nothing to draw, ...).
// `limits` (scene_limits.h) bounds the file size, the JSON nesting and the
// flattened triangles, each failing with its own sentence. The file and the
// buffer files its URIs name are read through input_file.h (regular files
// only); which URIs may be read is gltf_files.h's plan.
bool load(const std::string& path, Scene& out, std::string& error, const Limits& limits = Limits{});

// The same on bytes already in memory; `path` names them in messages and
// decides .glb by extension, as for a file.
bool load_from_memory(const std::vector<unsigned char>& bytes, const std::string& path, Scene& out,
                      std::string& error, const Limits& limits = Limits{});

}  // namespace scene
