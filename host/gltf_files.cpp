// gltf_files.cpp - see gltf_files.h.
#include "gltf_files.h"

#include "flags.h"
#include "input_file.h"

#include "tiny_gltf_quiet.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <system_error>

namespace scene {

namespace fs = std::filesystem;

namespace {

// A URI for a one-line message: escaped and cut short.
std::string quote_uri(const std::string& s) { return "'" + flags::printable(s, 160) + "'"; }

unsigned char from_hex(unsigned char c) {
    if (c >= '0' && c <= '9') return static_cast<unsigned char>(c - '0');
    if (c >= 'a' && c <= 'f') return static_cast<unsigned char>(c - 'a' + 10);
    if (c >= 'A' && c <= 'F') return static_cast<unsigned char>(c - 'A' + 10);
    return 0;
}

// True when `path` is `folder` or lies under it (both absolute and canonical).
bool inside(const fs::path& folder, const fs::path& path) {
    auto f = folder.begin(), p = path.begin();
    for (; f != folder.end(); ++f, ++p)
        if (p == path.end() || *f != *p) return false;
    return true;
}

}  // namespace

std::string decode_uri(const std::string& uri) {
    std::string out;
    for (size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] == '+') {
            out += ' ';
        } else if (uri[i] == '%' && uri.size() > i + 2) {
            out += static_cast<char>((from_hex(static_cast<unsigned char>(uri[i + 1])) << 4) |
                                     from_hex(static_cast<unsigned char>(uri[i + 2])));
            i += 2;
        } else {
            out += uri[i];
        }
    }
    return out;
}

bool GltfFiles::plan(const unsigned char* json, size_t size, const std::string& scene_path, const Limits& limits,
                     std::string& error) {
    scene_path_ = scene_path;
    budget_ = budget_left_ = limits.max_bytes;
    buffers_.clear();
    error_.clear();
    const nlohmann::json doc = nlohmann::json::parse(json, json + size, nullptr, /*allow_exceptions=*/false);
    if (!doc.is_object()) return true;  // tinygltf says what is wrong; no file is readable

    std::error_code ec;
    fs::path folder = fs::path(scene_path).parent_path();
    folder = fs::absolute(folder.empty() ? fs::path(".") : folder, ec);
    if (!ec) folder = fs::weakly_canonical(folder, ec);
    // An empty folder would hold every path (inside() compares components).
    if (!ec && folder.empty()) ec = std::make_error_code(std::errc::no_such_file_or_directory);
    if (ec) {
        error = scene_path + ": cannot resolve the scene's folder (" + ec.message() + ").";
        return false;
    }

    uint64_t data_uri_bytes = 0;
    auto check_data_uri = [&](const std::string& what, const std::string& uri) {
        data_uri_bytes += uri.size();
        if (data_uri_bytes <= limits.max_data_uri_bytes) return true;
        error = scene_path + ": " + what + "'s data URI takes the scene's data URIs past their budget of " +
                input_file::size_text(limits.max_data_uri_bytes) + ".";
        return false;
    };

    // Images: only data URIs cost anything (tinygltf decodes them); files
    // named by images are never read.
    if (doc.contains("images") && doc["images"].is_array()) {
        const auto& images = doc["images"];
        for (size_t i = 0; i < images.size(); ++i) {
            if (!images[i].is_object() || !images[i].contains("uri") || !images[i]["uri"].is_string()) continue;
            const std::string& uri = images[i]["uri"].get_ref<const std::string&>();
            if (tinygltf::IsDataURI(uri) && !check_data_uri("image " + std::to_string(i), uri)) return false;
        }
    }

    if (!doc.contains("buffers") || !doc["buffers"].is_array()) return true;
    const auto& buffers = doc["buffers"];
    for (size_t i = 0; i < buffers.size(); ++i) {
        const auto& b = buffers[i];
        if (!b.is_object() || !b.contains("uri") || !b["uri"].is_string()) continue;
        const std::string& uri = b["uri"].get_ref<const std::string&>();
        const std::string what = "buffer " + std::to_string(i);
        if (uri.empty()) continue;
        if (tinygltf::IsDataURI(uri)) {
            if (!check_data_uri(what, uri)) return false;
            continue;
        }
        // A byteLength tinygltf would refuse: it says so itself, and the
        // file is never read.
        if (!b.contains("byteLength") || !b["byteLength"].is_number()) continue;
        const double declared = b["byteLength"].get<double>();
        if (!(declared >= 0.0 && declared <= 9007199254740992.0) || declared != std::floor(declared)) continue;
        const uint64_t length = b["byteLength"].is_number_unsigned() ? b["byteLength"].get<uint64_t>() : uint64_t(declared);
        const std::string name = decode_uri(uri);
        if (name.find('\0') != std::string::npos) {
            error = scene_path + ": " + what + "'s URI " + quote_uri(uri) + " contains a NUL byte.";
            return false;
        }
        fs::path target = fs::path(name).is_absolute() ? fs::path(name) : folder / name;
        target = fs::weakly_canonical(target, ec);
        if (ec) {
            error = scene_path + ": " + what + "'s URI " + quote_uri(uri) + " cannot be resolved (" + ec.message() + ").";
            return false;
        }
        if (!limits.allow_outside_files && !inside(folder, target)) {
            error = scene_path + ": " + what + "'s URI " + quote_uri(uri) +
                    " names a file outside the scene's folder; --allow-outside-files allows it.";
            return false;
        }
        if (length > limits.max_bytes) {
            error = scene_path + ": " + what + " declares a byteLength larger than the " +
                    input_file::size_text(limits.max_bytes) + " budget of a buffer.";
            return false;
        }
        Buffer& entry = buffers_[name];
        entry.uri = uri;
        entry.path = target.string();
        entry.lengths.push_back(length);
    }
    return true;
}

tinygltf::FsCallbacks GltfFiles::callbacks() {
    tinygltf::FsCallbacks cb{};
    cb.FileExists = &GltfFiles::file_exists;
    cb.ExpandFilePath = &GltfFiles::expand_path;
    cb.ReadWholeFile = &GltfFiles::read_whole_file;
    cb.WriteWholeFile = &GltfFiles::write_whole_file;
    cb.user_data = this;
    return cb;
}

// Only planned buffers exist: tinygltf's second guess (the URI under the
// current directory) and every image are "not found".
bool GltfFiles::file_exists(const std::string& uri, void* self) {
    return static_cast<GltfFiles*>(self)->buffers_.count(uri) != 0;
}

// No expansion (tinygltf's own runs wordexp on the name).
std::string GltfFiles::expand_path(const std::string& uri, void*) { return uri; }

bool GltfFiles::read_whole_file(std::vector<unsigned char>* out, std::string* err, const std::string& uri, void* self) {
    GltfFiles& files = *static_cast<GltfFiles*>(self);
    bool ok = false;
    try {
        ok = files.read(uri, *out);
    } catch (const std::bad_alloc&) {
        if (files.error_.empty()) files.error_ = files.scene_path_ + ": out of memory while reading its buffers.";
    }
    if (!ok && err) *err += "refused";
    return ok;
}

bool GltfFiles::write_whole_file(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
    if (err) *err += "the scene loader writes no files";
    return false;
}

bool GltfFiles::read(const std::string& uri, std::vector<unsigned char>& out) {
    auto refuse = [&](const std::string& why) {
        if (error_.empty()) error_ = why;
        return false;
    };
    auto it = buffers_.find(uri);
    if (it == buffers_.end()) return refuse(scene_path_ + ": " + quote_uri(uri) + " is not a buffer of the scene.");
    Buffer& b = it->second;
    const std::string which = scene_path_ + ": buffer URI " + quote_uri(b.uri);
    if (b.reads >= b.lengths.size()) return refuse(which + " is read more often than the scene names it.");
    const uint64_t length = b.lengths[b.reads++];
    input_file::File file;
    std::string why;
    if (!file.open(b.path, why)) return refuse(which + " -> " + flags::printable(why, 8192));
    // tinygltf takes a buffer file only at exactly its byteLength: anything
    // else is refused before it is read, without saying the file's size.
    if (file.size() != length)
        return refuse(which + " names a file whose size is not the " + std::to_string(length) +
                      " bytes its byteLength declares.");
    if (length > budget_left_)
        return refuse(which + " takes the scene's buffer files past their budget of " + input_file::size_text(budget_) + ".");
    if (!file.read_all(length, out, why)) return refuse(which + " -> " + flags::printable(why, 8192));
    if (out.size() != length)
        return refuse(which + " names a file whose size is not the " + std::to_string(length) +
                      " bytes its byteLength declares.");
    budget_left_ -= length;
    return true;
}

}  // namespace scene
