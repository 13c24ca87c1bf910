// image_io.h - the host's picture files. Every file of a run is first written
// to a temporary name in the output directory; commit() renames them all at
// the end, so a failing run never leaves a partial set or overwrites earlier
// output. Images are passed top row first.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace image_io {

// Throws std::runtime_error with one sentence unless files can be written to
// `dir`: it is a writable directory, or it is missing and its nearest existing
// parent is one (then nothing is created; StagedOutput creates it). Run
// before rendering, so an unwritable --out fails at once.
void check_output_dir(const std::string& dir);

class StagedOutput {
public:
    // Creates `dir` (and its parents) if needed; throws std::runtime_error.
    explicit StagedOutput(const std::string& dir);
    ~StagedOutput();   // removes the temporary files of an uncommitted set
    StagedOutput(const StagedOutput&) = delete;
    StagedOutput& operator=(const StagedOutput&) = delete;

    // channels 1 (grey) or 3 (RGB), 8 bits. Throws std::runtime_error.
    void png(const std::string& name, int width, int height, int channels, const std::vector<uint8_t>& pixels);
    // One 32-bit float channel named "Y", with `attributes` (name, value) as
    // string attributes in the header. Throws std::runtime_error.
    void exr(const std::string& name, int width, int height, const std::vector<float>& pixels,
             const std::vector<std::pair<std::string, std::string>>& attributes = {});
    // Renames every staged file to its final name. Throws std::runtime_error.
    void commit();

    const std::string& dir() const { return dir_; }
    // Final names in the order they were staged.
    std::vector<std::string> names() const;

private:
    std::string temp_path(const std::string& name) const;
    std::string dir_;
    std::vector<std::pair<std::string, std::string>> staged_;   // temp path, final path
    bool committed_ = false;
};

// Draws one of the letters E R T Y U (5x7 glyphs, scaled) into an RGB8 image.
void draw_label(std::vector<uint8_t>& rgb, int width, int height, int x, int y, char letter, int scale);

}  // namespace image_io
