// input_file.h - the one way every tool reads an input file (a scene, a glTF
// buffer, an EXR image): only a regular file, its size judged with fstat
// before a byte is read, and never more than a stated budget. A FIFO would
// hang the read (or the open), a device such as /dev/zero never ends, and a
// directory makes some readers allocate absurd sizes; each is refused with
// one sentence that says what the path is.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace input_file {

// The budget the tools read an input file with: scenes and images past it
// are refused before they are read.
constexpr uint64_t kMaxInputBytes = uint64_t(1) << 31;  // 2 GiB

// An open regular file. open() refuses anything else; size() is what fstat
// said when it was opened.
class File {
public:
    File() = default;
    ~File();
    File(const File&) = delete;
    File& operator=(const File&) = delete;

    // On failure `error` is one sentence naming `path`: missing or
    // unreadable, or not a regular file (saying what it is instead).
    bool open(const std::string& path, std::string& error);
    uint64_t size() const { return size_; }
    // Reads the whole file. Refuses, before reading, a file larger than
    // `max_bytes` (the sentence states the budget, not the file's size), and
    // stops at the budget should the file grow while it is read.
    bool read_all(uint64_t max_bytes, std::vector<unsigned char>& bytes, std::string& error);

private:
    int fd_ = -1;
    uint64_t size_ = 0;
    std::string path_;
};

// open() then read_all(): the whole regular file at `path`, at most `max_bytes`.
bool read(const std::string& path, uint64_t max_bytes, std::vector<unsigned char>& bytes, std::string& error);

// "2 GiB", "64 MiB", "4095 bytes": a budget as the messages print it.
std::string size_text(uint64_t bytes);

// What a file of this st_mode is, for messages: "a directory", "a FIFO (named
// pipe)", "a character device", ...; "a regular file" for one.
std::string kind_text(unsigned mode);

}  // namespace input_file
