#include "image_io.h"

#include "exr_attributes.h"

#include <tinyexr.h>
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <limits>
#include <stdexcept>
#include <system_error>

namespace image_io {

namespace fs = std::filesystem;

void check_output_dir(const std::string& dir) {
    std::error_code ec;
    if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
        throw std::runtime_error("the output path '" + dir + "' exists and is not a directory");
    // The nearest folder that exists: where the first write (a file, or the
    // missing folders) will happen.
    fs::path existing = fs::absolute(dir, ec).lexically_normal();
    while (!existing.empty() && !fs::exists(existing, ec) && existing != existing.parent_path())
        existing = existing.parent_path();
    if (!fs::is_directory(existing, ec))
        throw std::runtime_error("the output directory '" + dir + "' cannot be created: '" + existing.string() +
                                 "' is not a directory");
    // Permission bits do not tell (root, read-only mounts, ACLs): try it.
    const fs::path probe = existing / (".ssao-write-test-" + std::to_string(getpid()));
    if (::mkdir(probe.c_str(), 0700) != 0) {
        const int why = errno;
        throw std::runtime_error(
            (existing == fs::absolute(dir, ec).lexically_normal() ? "the output directory '" + dir + "' is not writable"
                                                                   : "the output directory '" + dir + "' cannot be created in '" +
                                                                         existing.string() + "'") +
            " (" + std::strerror(why) + ")");
    }
    ::rmdir(probe.c_str());
}

StagedOutput::StagedOutput(const std::string& dir) : dir_(dir) {
    std::error_code ec;
    if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
        throw std::runtime_error("the output path '" + dir + "' exists and is not a directory");
    fs::create_directories(dir, ec);
    if (ec) throw std::runtime_error("cannot create the output directory '" + dir + "': " + ec.message());
}

StagedOutput::~StagedOutput() {
    if (committed_) return;
    for (const auto& s : staged_) std::remove(s.first.c_str());
}

std::string StagedOutput::temp_path(const std::string& name) const {
    return (fs::path(dir_) / ("." + name + ".tmp-" + std::to_string(getpid()))).string();
}

void StagedOutput::png(const std::string& name, int width, int height, int channels,
                       const std::vector<uint8_t>& pixels) {
    // stb_image_write sizes its buffer as (width * channels + 1) * height in int.
    if ((int64_t(width) * channels + 1) * height > int64_t(std::numeric_limits<int>::max()))
        throw std::runtime_error("'" + name + "' at " + std::to_string(width) + "x" + std::to_string(height) +
                                 " is too large for the PNG writer (2 GiB of pixel rows); use a smaller size");
    const std::string tmp = temp_path(name);
    staged_.emplace_back(tmp, (fs::path(dir_) / name).string());
    if (!stbi_write_png(tmp.c_str(), width, height, channels, pixels.data(), width * channels))
        throw std::runtime_error("cannot write '" + tmp + "' (disk full or directory not writable?)");
}

void StagedOutput::exr(const std::string& name, int width, int height, const std::vector<float>& pixels,
                       const std::vector<std::pair<std::string, std::string>>& attributes) {
    const std::string tmp = temp_path(name);
    staged_.emplace_back(tmp, (fs::path(dir_) / name).string());
    EXRHeader header;
    InitEXRHeader(&header);
    EXRImage image;
    InitEXRImage(&image);
    EXRChannelInfo channel;
    std::memset(&channel, 0, sizeof channel);
    std::strcpy(channel.name, "Y");
    int pixel_type = TINYEXR_PIXELTYPE_FLOAT;
    header.num_channels = 1;
    header.channels = &channel;
    header.pixel_types = &pixel_type;
    header.requested_pixel_types = &pixel_type;
    header.compression_type = TINYEXR_COMPRESSIONTYPE_ZIP;
    std::vector<EXRAttribute> custom = exr_attributes::strings(attributes);
    header.num_custom_attributes = static_cast<int>(custom.size());
    header.custom_attributes = custom.empty() ? nullptr : custom.data();
    float* planes[1] = {const_cast<float*>(pixels.data())};
    image.num_channels = 1;
    image.images = reinterpret_cast<unsigned char**>(planes);
    image.width = width;
    image.height = height;
    const char* err = nullptr;
    const int ret = SaveEXRImageToFile(&image, &header, tmp.c_str(), &err);
    if (ret != TINYEXR_SUCCESS) {
        const std::string why = err ? err : "unknown error";
        if (err) FreeEXRErrorMessage(err);
        throw std::runtime_error("cannot write '" + tmp + "': " + why);
    }
}

void StagedOutput::commit() {
    for (const auto& s : staged_) {
        if (std::rename(s.first.c_str(), s.second.c_str()) != 0)
            throw std::runtime_error("cannot rename '" + s.first + "' to '" + s.second + "': " + std::strerror(errno));
    }
    committed_ = true;
}

std::vector<std::string> StagedOutput::names() const {
    std::vector<std::string> out;
    for (const auto& s : staged_) out.push_back(fs::path(s.second).filename().string());
    return out;
}

namespace {

// 5x7 glyphs, one byte per row, bit 4 = leftmost column.
const uint8_t* glyph(char c) {
    static const uint8_t E[7] = {0x1F, 0x10, 0x10, 0x1E, 0x10, 0x10, 0x1F};
    static const uint8_t R[7] = {0x1E, 0x11, 0x11, 0x1E, 0x14, 0x12, 0x11};
    static const uint8_t T[7] = {0x1F, 0x04, 0x04, 0x04, 0x04, 0x04, 0x04};
    static const uint8_t Y[7] = {0x11, 0x11, 0x0A, 0x04, 0x04, 0x04, 0x04};
    static const uint8_t U[7] = {0x11, 0x11, 0x11, 0x11, 0x11, 0x11, 0x0E};
    switch (c) {
        case 'E': return E;
        case 'R': return R;
        case 'T': return T;
        case 'Y': return Y;
        case 'U': return U;
        default: return nullptr;
    }
}

}  // namespace

void draw_label(std::vector<uint8_t>& rgb, int width, int height, int x0, int y0, char letter, int scale) {
    const uint8_t* g = glyph(letter);
    if (!g || scale < 1) return;
    auto put = [&](int x, int y, uint8_t v) {
        if (x < 0 || y < 0 || x >= width || y >= height) return;
        uint8_t* p = &rgb[(static_cast<size_t>(y) * static_cast<size_t>(width) + static_cast<size_t>(x)) * 3];
        p[0] = p[1] = p[2] = v;
    };
    // A black backing box one glyph-pixel wider on each side, then the glyph in white.
    for (int y = -1; y < 8; ++y)
        for (int x = -1; x < 6; ++x)
            for (int sy = 0; sy < scale; ++sy)
                for (int sx = 0; sx < scale; ++sx) put(x0 + x * scale + sx, y0 + y * scale + sy, 0);
    for (int y = 0; y < 7; ++y)
        for (int x = 0; x < 5; ++x)
            if (g[y] & (0x10 >> x))
                for (int sy = 0; sy < scale; ++sy)
                    for (int sx = 0; sx < scale; ++sx) put(x0 + x * scale + sx, y0 + y * scale + sy, 255);
}

}  // namespace image_io
