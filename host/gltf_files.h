// gltf_files.h - the files a glTF may make the loader read, and the tinygltf
// file-system callbacks that read them. A scene comes from anywhere, so its
// URIs are checked before tinygltf sees them:
//   - an external buffer resolves inside the scene's folder (symbolic links
//     followed), unless Limits::allow_outside_files; "/etc/passwd" and
//     "../../x" are refused with one sentence naming the URI;
//   - its file is read through input_file (a regular file only), and only
//     when its size is the byteLength the buffer declares: a 3 GiB file
//     behind {"byteLength": 36} is refused without reading a byte, and the
//     sentence does not say how large the file is;
//   - data URIs together stay within Limits::max_data_uri_bytes;
//   - images are never read (the tools draw no textures).
#pragma once

#include "scene_limits.h"

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace tinygltf {
struct FsCallbacks;
}

namespace scene {

class GltfFiles {
public:
    // Reads the buffers and images of the glTF JSON text `json` (of the
    // scene at `scene_path`) and decides which files may be read. Returns
    // false with `error` (one sentence naming the scene and the URI) when a
    // URI is refused. JSON that does not parse is left to tinygltf to report
    // (and then no file may be read at all).
    bool plan(const unsigned char* json, size_t size, const std::string& scene_path, const Limits& limits,
              std::string& error);

    // Callbacks for tinygltf, to be used with an empty base directory: they
    // receive each URI as tinygltf decodes it. This object must outlive the load.
    tinygltf::FsCallbacks callbacks();

    // The sentence of the first read the callbacks refused (empty if none):
    // it replaces tinygltf's own, which may quote a file's size.
    const std::string& error() const { return error_; }

private:
    struct Buffer {
        std::string uri;                // as the JSON writes it, for messages
        std::string path;               // resolved (absolute, symbolic links followed)
        std::vector<uint64_t> lengths;  // byteLength of each buffer with this URI, in order
        size_t reads = 0;               // reads so far (tinygltf reads the buffers in order)
    };
    static bool file_exists(const std::string& uri, void* self);
    static std::string expand_path(const std::string& uri, void* self);
    static bool read_whole_file(std::vector<unsigned char>* out, std::string* err, const std::string& uri, void* self);
    static bool write_whole_file(std::string* err, const std::string& path, const std::vector<unsigned char>& bytes,
                                 void* self);
    bool read(const std::string& uri, std::vector<unsigned char>& out);

    std::string scene_path_;
    uint64_t budget_ = 0;               // bytes all buffer files may take together
    uint64_t budget_left_ = 0;          // what they may still take
    std::map<std::string, Buffer> buffers_;  // by decoded URI
    std::string error_;
};

// tinygltf's decoding of a URI into a file name ('+' is a space, %XX a byte),
// mirrored so that the plan sees the names tinygltf will ask for.
std::string decode_uri(const std::string& uri);

}  // namespace scene
