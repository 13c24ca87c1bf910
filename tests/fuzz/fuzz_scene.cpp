// fuzz_scene.cpp - libFuzzer target: scene::load_from_memory on arbitrary
// bytes, as .gltf and as .glb (the first byte chooses). Besides libFuzzer's
// byte mutations, a custom mutator edits the JSON as a structure: it nests a
// value in arrays and objects, repeats array elements and nodes, and inflates
// numbers and counts, the shapes that overflowed the stack and multiplied
// the work, and swaps buffer and image URIs for names of a
// scratch folder the fuzzer makes (scratch() below): a buffer file, files
// outside the scene's folder, symbolic links in and out, a FIFO, a directory,
// a sparse file far larger than declared, data URIs. Any crash, sanitizer
// report, uncaught exception, time/memory limit hit (a FIFO that blocks, a
// file read whole), a refusal without a sentence or over two lines, or
// tinygltf's size message (which discloses a file's size) is a finding.
#include "scene.h"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

extern "C" size_t LLVMFuzzerMutate(uint8_t* data, size_t size, size_t max_size);

namespace {

// Small limits keep each input fast; the checks are the same as the defaults'.
scene::Limits fuzz_limits() {
    scene::Limits l;
    l.max_bytes = 1 << 20;
    l.max_triangles = 200000;
    l.max_primitive_instances = 20000;
    l.max_vertices = 600000;
    return l;
}

// The scratch folder, made once per process under $TMPDIR and removed at
// exit: SCRATCH/scene/ is the scene's folder, SCRATCH/outside.bin lies
// beside it. Its names are what the URI mutation writes.
const std::string& scratch() {
    // Never destroyed: the atexit handler that removes the folder runs after
    // the static destructors registered later than it.
    static const std::string& dir = *new std::string([] {
        namespace fs = std::filesystem;
        std::string tmpl = (fs::temp_directory_path() / "fuzz_scene.XXXXXX").string();
        if (!::mkdtemp(tmpl.data())) std::abort();
        const fs::path root = tmpl, scene = root / "scene";
        fs::create_directories(scene / "sub");
        fs::create_directories(scene / "dir.bin");
        const float pos[9] = {0, 0, 0, 1, 0, 0, 0, 0, -1};
        for (const fs::path& p : {scene / "tri.bin", scene / "sub" / "tri.bin", root / "outside.bin"})
            std::ofstream(p, std::ios::binary).write(reinterpret_cast<const char*>(pos), sizeof pos);
        { std::ofstream(scene / "big.bin", std::ios::binary) << 'x'; }
        fs::resize_file(scene / "big.bin", uint64_t(3) << 30);  // sparse: no disk
        if (::mkfifo((scene / "pipe.bin").c_str(), 0600) != 0) std::abort();
        fs::create_symlink(root / "outside.bin", scene / "link-out.bin");
        fs::create_symlink("tri.bin", scene / "link-in.bin");
        fs::create_directory_symlink(root, scene / "up");
        std::atexit([] {
            std::error_code ec;
            std::filesystem::remove_all(scratch(), ec);
        });
        return root.string();
    }());
    return dir;
}

// URIs the mutator puts in place of a "uri" value.
const char* const kUris[] = {
    "tri.bin", "sub/tri.bin", "sub/../tri.bin", "t%72i.bin", "tri+.bin", "../outside.bin", "up/outside.bin",
    "link-out.bin", "link-in.bin", "pipe.bin", "dir.bin", "big.bin", "missing.bin", "/etc/passwd", "/dev/zero",
    "/tmp", "/", "", ".", "..", "../../../../../../etc/passwd", "%2e%2e/outside.bin", "tri.bin%00/../../x",
    "file:///etc/passwd", "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAAAAAAIC/",
    "data:application/octet-stream;base64,", "data:image/png;base64,AAAA", "data:text/plain,abc"};

// The JSON part of an input: all of it for .gltf; for .glb the JSON chunk.
struct Parts {
    bool glb = false;
    std::string json, bin;
};

uint32_t u32(const uint8_t* p) { return uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24; }
void put_u32(std::string& s, uint32_t v) {
    for (int i = 0; i < 4; ++i) s += char((v >> (8 * i)) & 0xff);
}

Parts split(const uint8_t* data, size_t size) {
    Parts p;
    if (size >= 20 && std::memcmp(data, "glTF", 4) == 0) {
        const uint32_t json_len = u32(data + 12);
        if (json_len <= size - 20) {
            p.glb = true;
            p.json.assign(reinterpret_cast<const char*>(data) + 20, json_len);
            const size_t rest = 20 + size_t(json_len);
            if (size - rest >= 8) p.bin.assign(reinterpret_cast<const char*>(data) + rest + 8, size - rest - 8);
            return p;
        }
    }
    p.json.assign(reinterpret_cast<const char*>(data), size);
    return p;
}

std::string join(const Parts& p) {
    if (!p.glb) return p.json;
    std::string json = p.json, bin = p.bin;
    while (json.size() % 4) json += ' ';
    while (bin.size() % 4) bin += '\0';
    std::string out = "glTF";
    put_u32(out, 2);
    put_u32(out, uint32_t(12 + 8 + json.size() + (bin.empty() ? 0 : 8 + bin.size())));
    put_u32(out, uint32_t(json.size()));
    put_u32(out, 0x4E4F534Au);
    out += json;
    if (!bin.empty()) {
        put_u32(out, uint32_t(bin.size()));
        put_u32(out, 0x004E4942u);
        out += bin;
    }
    return out;
}

// Positions of the opening brackets of JSON values (outside strings).
std::vector<size_t> openings(const std::string& s) {
    std::vector<size_t> at;
    bool str = false, esc = false;
    for (size_t i = 0; i < s.size(); ++i) {
        const char c = s[i];
        if (str) {
            if (esc) esc = false;
            else if (c == '\\') esc = true;
            else if (c == '"') str = false;
        } else if (c == '"') {
            str = true;
        } else if (c == '[' || c == '{') {
            at.push_back(i);
        }
    }
    return at;
}

// The index just past the value that opens at `open`, or npos.
size_t value_end(const std::string& s, size_t open) {
    int depth = 0;
    bool str = false, esc = false;
    for (size_t i = open; i < s.size(); ++i) {
        const char c = s[i];
        if (str) {
            if (esc) esc = false;
            else if (c == '\\') esc = true;
            else if (c == '"') str = false;
        } else if (c == '"') {
            str = true;
        } else if (c == '[' || c == '{') {
            ++depth;
        } else if (c == ']' || c == '}') {
            if (--depth == 0) return i + 1;
        }
    }
    return std::string::npos;
}

// One structural edit of the JSON text; false when it found nothing to edit.
bool mutate_json(std::string& json, std::mt19937& rng, size_t max_size) {
    const std::vector<size_t> opens = openings(json);
    auto pick = [&](size_t n) { return size_t(rng() % n); };
    switch (rng() % 7) {
        case 6: {  // point a URI at one of the scratch folder's files (or a data URI)
            std::vector<size_t> uris;
            for (size_t at = json.find("\"uri\""); at != std::string::npos; at = json.find("\"uri\"", at + 1))
                uris.push_back(at);
            if (uris.empty()) return false;
            const size_t key = uris[pick(uris.size())];
            const size_t open = json.find('"', key + 5);
            if (open == std::string::npos) return false;
            size_t close = open + 1;
            while (close < json.size() && json[close] != '"') close += json[close] == '\\' ? 2 : 1;
            if (close >= json.size()) return false;
            std::string uri = kUris[pick(sizeof kUris / sizeof kUris[0])];
            if (rng() % 8 == 0) uri = scratch() + "/" + (rng() % 2 ? "outside.bin" : "scene/tri.bin");  // absolute
            if (json.size() + uri.size() > max_size) return false;
            json.replace(open + 1, close - open - 1, uri);
            return true;
        }
        case 0: {  // nest a value: v -> [[...v...]] (sometimes very deep)
            if (opens.empty()) return false;
            const size_t a = opens[pick(opens.size())], b = value_end(json, a);
            if (b == std::string::npos) return false;
            const size_t depth = rng() % 4 == 0 ? 1 + rng() % 200000 : 1 + rng() % 40;
            if (json.size() + 2 * depth > max_size) return false;
            json.insert(b, std::string(depth, ']'));
            json.insert(a, std::string(depth, '['));
            return true;
        }
        case 1: {  // repeat an array element or object member: [a] -> [a,a,a,...]
            if (opens.empty()) return false;
            const size_t a = opens[pick(opens.size())], b = value_end(json, a);
            if (b == std::string::npos || b - a < 2) return false;
            const std::string inner = json.substr(a + 1, b - a - 2);
            if (inner.empty()) return false;
            const size_t times = 1 + rng() % (rng() % 8 == 0 ? 5000 : 16);
            std::string rep;
            for (size_t i = 0; i < times && rep.size() + json.size() < max_size; ++i) rep += "," + inner;
            json.insert(b - 1, rep);
            return true;
        }
        case 2: {  // wrap a whole value in "extras" of the root
            if (json.empty() || json[0] != '{' || opens.size() < 2) return false;
            const size_t a = opens[1 + pick(opens.size() - 1)], b = value_end(json, a);
            if (b == std::string::npos) return false;
            const std::string v = json.substr(a, b - a);
            if (json.size() + v.size() + 12 > max_size) return false;
            json.insert(1, "\"extras\":" + v + ",");
            return true;
        }
        case 3: {  // inflate a number: counts, offsets, indices, scales
            std::vector<size_t> digits;
            for (size_t i = 0; i < json.size(); ++i)
                if (json[i] >= '0' && json[i] <= '9' && (i == 0 || !(json[i - 1] >= '0' && json[i - 1] <= '9')))
                    digits.push_back(i);
            if (digits.empty()) return false;
            const size_t at = digits[pick(digits.size())];
            size_t end = at;
            while (end < json.size() && ((json[end] >= '0' && json[end] <= '9') || json[end] == '.')) ++end;
            const char* big[] = {"4294967295", "2147483647", "65536", "1e308", "-1", "0", "1e-320", "99999999999"};
            json.replace(at, end - at, big[pick(sizeof big / sizeof big[0])]);
            return true;
        }
        case 4: {  // repeat the node list's references (more nodes drawing the same mesh)
            const size_t n = json.find("\"nodes\":[");
            if (n == std::string::npos) return false;
            const size_t a = n + 8, b = value_end(json, a);
            if (b == std::string::npos || b - a < 3) return false;
            const std::string inner = json.substr(a + 1, b - a - 2);
            std::string rep;
            const size_t times = 1 + rng() % 2000;
            for (size_t i = 0; i < times && rep.size() + json.size() < max_size; ++i) rep += "," + inner;
            json.insert(b - 1, rep);
            return true;
        }
        default: {  // cut the text somewhere (truncated files)
            if (json.size() < 2) return false;
            json.resize(1 + pick(json.size() - 1));
            return true;
        }
    }
}

}  // namespace

extern "C" size_t LLVMFuzzerCustomMutator(uint8_t* data, size_t size, size_t max_size, unsigned int seed) {
    std::mt19937 rng(seed);
    if (rng() % 3 == 0 || size == 0) return LLVMFuzzerMutate(data, size, max_size);
    Parts p = split(data, size);
    if (!mutate_json(p.json, rng, max_size)) return LLVMFuzzerMutate(data, size, max_size);
    const std::string out = join(p);
    if (out.size() > max_size) return LLVMFuzzerMutate(data, size, max_size);
    std::memcpy(data, out.data(), out.size());
    return out.size();
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::vector<unsigned char> bytes(data, data + size);
    // .glb by magic; otherwise the name decides nothing more, so both loaders
    // run. The scene lies in the scratch folder, so its URIs reach its files;
    // one input in four may leave the folder.
    scene::Scene sc;
    std::string error;
    scene::Limits limits = fuzz_limits();
    limits.allow_outside_files = size % 4 == 3;
    const bool ok = scene::load_from_memory(bytes, scratch() + "/scene/fuzz.gltf", sc, error, limits);
    if (!ok && error.empty()) __builtin_trap();  // a failure must say why
    if (error.find('\n') != std::string::npos) __builtin_trap();  // in one line
    // tinygltf's size message (it gives the file's size), unless the parse
    // error only quotes the input's own text.
    const std::string size_message = "File size mismatch : ";
    if (error.find(size_message) != std::string::npos &&
        std::search(bytes.begin(), bytes.end(), size_message.begin(), size_message.end()) == bytes.end())
        __builtin_trap();
    if (ok && (sc.mesh.indices.size() % 3 != 0 || sc.mesh.positions.size() != sc.mesh.normals.size()))
        __builtin_trap();
    if (ok)
        for (uint32_t i : sc.mesh.indices)
            if (i >= sc.mesh.positions.size()) __builtin_trap();
    return 0;
}
