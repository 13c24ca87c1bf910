#include "image_io.h"

#include "exr_attributes.h"

#include "input_file.h"

#include <tinyexr.h>

#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#pragma GCC diagnostic ignored "-Wshadow"
#endif
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC
#include <stb/stb_image_write.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

#include <algorithm>
#include <cmath>
#include <cstring>
#include <exception>

namespace refio {
namespace {

// What an EXR input may cost to read: the images of these tools are at most
// 16384 x 16384 float pixels, 1 GiB a channel uncompressed.
constexpr uint64_t kMaxExrBytes = input_file::kMaxInputBytes;

// tinyexr's messages end in a newline (and some hold more than one line):
// a tool's error is one line.
std::string exr_message(const char* err) {
    std::string s = err ? err : "unknown error";
    if (err) FreeEXRErrorMessage(err);
    while (!s.empty() && (s.back() == '\n' || s.back() == '\r' || s.back() == ' ' || s.back() == '.')) s.pop_back();
    for (char& c : s)
        if (c == '\n' || c == '\r') c = ' ';
    return s.empty() ? "unknown error" : s;
}

}  // namespace

bool write_exr(const std::string& path, int width, int height, std::vector<Channel> channels, std::string& error,
               const Attributes& attributes) {
    if (width <= 0 || height <= 0 || channels.empty()) {
        error = "cannot write " + path + ": empty image.";
        return false;
    }
    const size_t n = size_t(width) * size_t(height);
    for (const auto& c : channels)
        if (!c.data || c.data->size() != n || c.name.empty() || c.name.size() > 255) {
            error = "cannot write " + path + ": channel '" + c.name + "' has the wrong size.";
            return false;
        }
    std::sort(channels.begin(), channels.end(), [](const Channel& a, const Channel& b) { return a.name < b.name; });

    EXRHeader header;
    InitEXRHeader(&header);
    EXRImage image;
    InitEXRImage(&image);
    std::vector<EXRChannelInfo> info(channels.size());
    std::vector<int> types(channels.size(), TINYEXR_PIXELTYPE_FLOAT);
    std::vector<const float*> ptrs(channels.size());
    for (size_t i = 0; i < channels.size(); ++i) {
        std::memset(&info[i], 0, sizeof(EXRChannelInfo));
        std::strncpy(info[i].name, channels[i].name.c_str(), 255);
        info[i].pixel_type = TINYEXR_PIXELTYPE_FLOAT;
        info[i].x_sampling = info[i].y_sampling = 1;
        ptrs[i] = channels[i].data->data();
    }
    image.num_channels = int(channels.size());
    image.images = reinterpret_cast<unsigned char**>(const_cast<float**>(ptrs.data()));
    image.width = width;
    image.height = height;
    header.num_channels = int(channels.size());
    header.channels = info.data();
    header.pixel_types = types.data();
    header.requested_pixel_types = types.data();
    header.compression_type = TINYEXR_COMPRESSIONTYPE_ZIP;
    std::vector<EXRAttribute> custom = exr_attributes::strings(attributes);
    header.num_custom_attributes = int(custom.size());
    header.custom_attributes = custom.empty() ? nullptr : custom.data();
    const char* err = nullptr;
    const int rc = SaveEXRImageToFile(&image, &header, path.c_str(), &err);
    if (rc != TINYEXR_SUCCESS) {
        error = "cannot write " + path + ": " + exr_message(err) + ".";
        return false;
    }
    return true;
}

namespace {

// The file's bytes (read through input_file, so a FIFO or a device is
// refused and nothing past the budget is read) and what tinyexr made of them.
struct LoadedExr {
    std::vector<unsigned char> bytes;
    EXRHeader header;
    EXRImage image;
    bool header_ok = false, image_ok = false;
    LoadedExr() {
        InitEXRHeader(&header);
        InitEXRImage(&image);
    }
    ~LoadedExr() {
        if (image_ok) FreeEXRImage(&image);
        if (header_ok) FreeEXRHeader(&header);
    }
    LoadedExr(const LoadedExr&) = delete;
    LoadedExr& operator=(const LoadedExr&) = delete;
};

// The value tinyexr takes from a single-part header's "type" attribute (the
// last one with a value), or "" when there is none: the attributes from byte
// 8 on, each a NUL-terminated name and type name, a 4-byte little-endian size
// and the value, read as tinyexr reads them (at most 1024, a string value up
// to its first NUL). Where tinyexr would refuse the header itself, the scan
// stops and leaves that to it.
std::string type_attribute(const std::vector<unsigned char>& bytes) {
    constexpr int kMaxAttributes = 1024;  // tinyexr's TINYEXR_MAX_HEADER_ATTRIBUTES
    std::string type;
    size_t pos = 8;
    for (int n = 0; n < kMaxAttributes && pos < bytes.size() && bytes[pos] != 0; ++n) {
        const char* p = reinterpret_cast<const char*>(bytes.data()) + pos;
        const size_t left = bytes.size() - pos;
        const size_t name_len = strnlen(p, left);
        if (name_len == left) break;
        const size_t type_at = name_len + 1;
        const size_t type_len = strnlen(p + type_at, left - type_at);
        if (type_len == left - type_at) break;
        size_t at = type_at + type_len + 1;
        if (left - at < 4) break;
        const auto* s = reinterpret_cast<const unsigned char*>(p + at);
        const uint32_t size = uint32_t(s[0]) | uint32_t(s[1]) << 8 | uint32_t(s[2]) << 16 | uint32_t(s[3]) << 24;
        at += 4;
        if (left - at < size || (size == 0 && std::string(p + type_at, type_len) != "string")) break;
        if (size > 0 && std::string(p, name_len) == "type" && p[at] != '\0') type.assign(p + at, strnlen(p + at, size));
        pos += at + size;
    }
    return type;
}

bool parse_header(const std::string& path, LoadedExr& x, std::string& error) {
    if (!input_file::read(path, kMaxExrBytes, x.bytes, error)) return false;
    EXRVersion version;
    if (ParseEXRVersionFromMemory(&version, x.bytes.data(), x.bytes.size()) != TINYEXR_SUCCESS) {
        error = path + ": not an OpenEXR file.";
        return false;
    }
    if (version.multipart || version.non_image) {
        error = path + ": multi-part and deep EXR files are not supported.";
        return false;
    }
    // Refused before tinyexr parses the header, which asserts (aborts the
    // program) on a tiled file's "tiles" attribute of any size but 9 bytes
    // and on a "type" attribute that is not one of its four, or that
    // contradicts the version's tiled flag (found by fuzz_exr).
    if (version.tiled) {
        error = path + ": tiled EXR files are not supported.";
        return false;
    }
    const std::string type = type_attribute(x.bytes);
    if (!type.empty() && type != "scanlineimage") {
        error = path + ": only scanline EXR images are supported (the header's type attribute names another kind).";
        return false;
    }
    const char* err = nullptr;
    const int rc = ParseEXRHeaderFromMemory(&x.header, &version, x.bytes.data(), x.bytes.size(), &err);
    // Freed even when parsing failed: tinyexr fills the header (channels,
    // pixel types) before it reports a later error, and FreeEXRHeader is
    // safe on the initialised, unfilled header (leak found by fuzz_exr).
    x.header_ok = true;
    if (rc != TINYEXR_SUCCESS) {
        error = path + ": cannot parse the EXR header (" + exr_message(err) + ").";
        return false;
    }
    return true;
}

bool has_channel(const std::string& path, const std::string& name) {
    LoadedExr x;
    std::string err;
    if (!parse_header(path, x, err)) return false;
    for (int c = 0; c < x.header.num_channels; ++c)
        if (name == x.header.channels[c].name) return true;
    return false;
}

bool read_attributes(const std::string& path, const std::string& prefix, Attributes& out, std::string& error) {
    LoadedExr x;
    if (!parse_header(path, x, error)) return false;
    out.clear();
    for (int i = 0; i < x.header.num_custom_attributes; ++i) {
        const EXRAttribute& a = x.header.custom_attributes[i];
        if (std::strcmp(a.type, "string") != 0 || std::string(a.name).rfind(prefix, 0) != 0) continue;
        std::string value;
        if (a.value && a.size > 0) value.assign(reinterpret_cast<const char*>(a.value), size_t(a.size));
        // An EXR string may end in a NUL written by other programs.
        while (!value.empty() && value.back() == '\0') value.pop_back();
        out.emplace_back(a.name, value);
    }
    return true;
}

bool read_channel(const std::string& path, const std::vector<std::string>& preferred, std::vector<float>& out,
                  int& width, int& height, std::string& error, std::string* used) {
    LoadedExr x;
    if (!parse_header(path, x, error)) return false;
    // tinyexr sizes its buffers from the data window without checking it: a
    // window from INT_MIN asks for exabytes (found by fuzz_exr). Our images
    // are at most 16384 pixels a side; 65536 leaves room.
    const EXRBox2i& dw = x.header.data_window;
    const long long w = (long long)dw.max_x - dw.min_x + 1, h = (long long)dw.max_y - dw.min_y + 1;
    if (w < 1 || h < 1 || w > 65536 || h > 65536) {
        error = path + ": the EXR's data window (" + std::to_string(w) + " x " + std::to_string(h) +
                " pixels) is outside 1..65536 a side.";
        return false;
    }
    if (x.header.num_channels <= 0) {
        error = path + ": the EXR has no channels.";
        return false;
    }
    for (int c = 0; c < x.header.num_channels; ++c)
        if (x.header.pixel_types[c] == TINYEXR_PIXELTYPE_HALF) x.header.requested_pixel_types[c] = TINYEXR_PIXELTYPE_FLOAT;
    // tinyexr (1.0.1) frees a failed load with FreeEXRImage, which frees the
    // channel buffers only up to image.num_channels, set after a successful
    // decode: set it now so a truncated file leaks nothing.
    x.image.num_channels = x.header.num_channels;
    const char* err = nullptr;
    if (LoadEXRImageFromMemory(&x.image, &x.header, x.bytes.data(), x.bytes.size(), &err) != TINYEXR_SUCCESS) {
        error = path + ": cannot read the EXR pixels (" + exr_message(err) + ").";
        return false;
    }
    x.image_ok = true;
    int chosen = -1;
    for (const auto& p : preferred) {
        for (int c = 0; c < x.header.num_channels && chosen < 0; ++c)
            if (p == x.header.channels[c].name) chosen = c;
        if (chosen >= 0) break;
    }
    if (chosen < 0) chosen = 0;
    width = x.image.width;
    height = x.image.height;
    if (width <= 0 || height <= 0 || !x.image.images) {
        error = path + ": the EXR image is empty.";
        return false;
    }
    const size_t n = size_t(width) * size_t(height);
    out.resize(n);
    const unsigned char* src = x.image.images[chosen];
    if (x.header.requested_pixel_types[chosen] == TINYEXR_PIXELTYPE_UINT) {
        for (size_t i = 0; i < n; ++i) {
            unsigned int v;
            std::memcpy(&v, src + i * 4, 4);
            out[i] = float(v);
        }
    } else {
        std::memcpy(out.data(), src, n * sizeof(float));
    }
    if (used) *used = x.header.channels[chosen].name;
    return true;
}

}  // namespace

// tinyexr throws out of its C API on some malformed files (std::length_error
// from a vector sized by a corrupt header, std::bad_alloc; found by
// fuzz_exr): the readers turn that into their usual refusal.
bool exr_has_channel(const std::string& path, const std::string& name) {
    try {
        return has_channel(path, name);
    } catch (const std::exception&) {
        return false;
    }
}

bool read_exr_attributes(const std::string& path, const std::string& prefix, Attributes& out, std::string& error) {
    try {
        return read_attributes(path, prefix, out, error);
    } catch (const std::exception& e) {
        error = path + ": a malformed EXR made the reader fail (" + e.what() + ").";
        return false;
    }
}

bool read_exr_channel(const std::string& path, const std::vector<std::string>& preferred, std::vector<float>& out,
                      int& width, int& height, std::string& error, std::string* used) {
    try {
        return read_channel(path, preferred, out, width, height, error, used);
    } catch (const std::exception& e) {
        error = path + ": a malformed EXR made the reader fail (" + e.what() + ").";
        return false;
    }
}

bool write_png_grey(const std::string& path, int width, int height, const std::vector<float>& values, std::string& error) {
    const size_t n = size_t(width) * size_t(height);
    if (width <= 0 || height <= 0 || values.size() != n) {
        error = "cannot write " + path + ": wrong image size.";
        return false;
    }
    std::vector<unsigned char> px(n);
    for (size_t i = 0; i < n; ++i) {
        const float v = std::isnan(values[i]) ? 1.0f : std::min(std::max(values[i], 0.0f), 1.0f);
        px[i] = static_cast<unsigned char>(std::lround(v * 255.0f));
    }
    if (!stbi_write_png(path.c_str(), width, height, 1, px.data(), width)) {
        error = "cannot write " + path + ".";
        return false;
    }
    return true;
}

}  // namespace refio
