// image_io.h - the reference tools' own small EXR/PNG input and output.
// Images are row-major with row 0 at the top of the picture (as PNG and EXR
// store them).
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace refio {

struct Channel {
    std::string name;            // e.g. "Y", "A", "R"
    const std::vector<float>* data;  // width * height values
};

// (name, value) string attributes of an EXR header.
using Attributes = std::vector<std::pair<std::string, std::string>>;

// Writes a scanline EXR, 32-bit float, ZIP-compressed (channels are stored
// sorted by name, as OpenEXR requires), with `attributes` as string
// attributes in its header. Returns false with `error` set.
bool write_exr(const std::string& path, int width, int height, std::vector<Channel> channels, std::string& error,
               const Attributes& attributes = {});

// The string attributes of the EXR at `path` whose names start with `prefix`
// (in the header's order). Returns false with `error` set when the file
// cannot be read as an EXR.
bool read_exr_attributes(const std::string& path, const std::string& prefix, Attributes& out, std::string& error);

// Reads one channel of an EXR as float: the first of `preferred` the file
// has, else its first channel. `used` (optional) receives the channel's name.
bool read_exr_channel(const std::string& path, const std::vector<std::string>& preferred, std::vector<float>& out,
                      int& width, int& height, std::string& error, std::string* used = nullptr);

// True when the EXR at `path` has a channel called `name`.
bool exr_has_channel(const std::string& path, const std::string& name);

// Writes an 8-bit grey PNG of values clamped to [0,1] (NaN written as 1).
bool write_png_grey(const std::string& path, int width, int height, const std::vector<float>& values, std::string& error);

}  // namespace refio
