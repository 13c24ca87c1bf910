// exr_same_image A.exr B.exr: exit 0 when the two EXR files hold the same
// image (size, data window, channels, pixel types, compression and every
// pixel's bits), whatever other attributes their headers carry; 1 with one
// line saying what differs; 2 when a file cannot be read. run.sh uses it so
// that the record ssao-host writes into ao.exr's header (provenance.h) is not
// counted as a different frame.
#include <tinyexr.h>

#include <cstdio>
#include <cstring>
#include <string>

namespace {

struct Exr {
    EXRVersion version{};
    EXRHeader header;
    EXRImage image;
    bool header_ok = false, image_ok = false;
    Exr() {
        InitEXRHeader(&header);
        InitEXRImage(&image);
    }
    ~Exr() {
        if (image_ok) FreeEXRImage(&image);
        if (header_ok) FreeEXRHeader(&header);
    }
    bool load(const char* path) {
        const char* err = nullptr;
        if (ParseEXRVersionFromFile(&version, path) != TINYEXR_SUCCESS) return false;
        header_ok = ParseEXRHeaderFromFile(&header, &version, path, &err) == TINYEXR_SUCCESS;
        if (err) FreeEXRErrorMessage(err);
        if (!header_ok || header.tiled) return false;
        err = nullptr;
        image_ok = LoadEXRImageFromFile(&image, &header, path, &err) == TINYEXR_SUCCESS;
        if (err) FreeEXRErrorMessage(err);
        return image_ok;
    }
};

int differ(const char* what) {
    std::printf("exr_same_image: the images differ in %s\n", what);
    return 1;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: exr_same_image A.exr B.exr\n");
        return 2;
    }
    Exr a, b;
    if (!a.load(argv[1]) || !b.load(argv[2])) {
        std::fprintf(stderr, "exr_same_image: cannot read %s\n", a.image_ok ? argv[2] : argv[1]);
        return 2;
    }
    if (a.image.width != b.image.width || a.image.height != b.image.height) return differ("size");
    if (std::memcmp(&a.header.data_window, &b.header.data_window, sizeof a.header.data_window) != 0)
        return differ("data window");
    if (a.header.compression_type != b.header.compression_type) return differ("compression");
    if (a.header.num_channels != b.header.num_channels) return differ("channel count");
    const size_t pixels = size_t(a.image.width) * size_t(a.image.height);
    for (int c = 0; c < a.header.num_channels; ++c) {
        if (std::strcmp(a.header.channels[c].name, b.header.channels[c].name) != 0) return differ("channel names");
        if (a.header.pixel_types[c] != b.header.pixel_types[c]) return differ("pixel types");
        const size_t bytes = pixels * (a.header.pixel_types[c] == TINYEXR_PIXELTYPE_HALF ? 2 : 4);
        if (std::memcmp(a.image.images[c], b.image.images[c], bytes) != 0) return differ("pixels");
    }
    return 0;
}
