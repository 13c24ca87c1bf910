// input_file.cpp - see input_file.h.
#include "input_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <new>

namespace input_file {

std::string size_text(uint64_t bytes) {
    if (bytes != 0 && bytes % (uint64_t(1) << 30) == 0) return std::to_string(bytes >> 30) + " GiB";
    if (bytes != 0 && bytes % (uint64_t(1) << 20) == 0) return std::to_string(bytes >> 20) + " MiB";
    return std::to_string(bytes) + " bytes";
}

std::string kind_text(unsigned mode) {
    switch (mode & S_IFMT) {
        case S_IFREG: return "a regular file";
        case S_IFDIR: return "a directory";
        case S_IFIFO: return "a FIFO (named pipe)";
        case S_IFCHR: return "a character device";
        case S_IFBLK: return "a block device";
        case S_IFSOCK: return "a socket";
        case S_IFLNK: return "a symbolic link";
        default: return "not a file";
    }
}

File::~File() {
    if (fd_ >= 0) ::close(fd_);
}

bool File::open(const std::string& path, std::string& error) {
    path_ = path;
    // Judged before opening: opening a device can have effects of its own,
    // and a socket cannot be opened at all.
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) {
        error = path + ": cannot open the file (" + std::strerror(errno) + ").";
        return false;
    }
    if (!S_ISREG(st.st_mode)) {
        error = path + ": not a regular file but " + kind_text(st.st_mode) + ".";
        return false;
    }
    // O_NONBLOCK: should the path have become a FIFO since stat, the open
    // returns at once instead of waiting for a writer; fstat then refuses it.
    fd_ = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
    if (fd_ < 0) {
        error = path + ": cannot open the file (" + std::strerror(errno) + ").";
        return false;
    }
    if (::fstat(fd_, &st) != 0 || !S_ISREG(st.st_mode)) {
        error = path + ": not a regular file but " + kind_text(st.st_mode) + ".";
        return false;
    }
    // A regular file now: reads block as usual (some file systems answer
    // EAGAIN to a non-blocking read).
    const int flags = ::fcntl(fd_, F_GETFL);
    if (flags < 0 || ::fcntl(fd_, F_SETFL, flags & ~O_NONBLOCK) != 0) {
        error = path + ": cannot read the file (" + std::strerror(errno) + ").";
        return false;
    }
    size_ = st.st_size > 0 ? uint64_t(st.st_size) : 0;
    return true;
}

bool File::read_all(uint64_t max_bytes, std::vector<unsigned char>& bytes, std::string& error) {
    const std::string too_large = path_ + ": the file is larger than " + size_text(max_bytes) + ".";
    bytes.clear();
    if (fd_ < 0) {
        error = path_ + ": the file is not open.";
        return false;
    }
    if (size_ > max_bytes) {
        error = too_large;
        return false;
    }
    try {
        bytes.resize(size_t(size_));
        size_t got = 0;
        // The file may shrink or grow while it is read: read what is there,
        // up to one byte past the budget to notice growth beyond it.
        for (;;) {
            if (got == bytes.size()) {
                if (uint64_t(got) > max_bytes) break;
                const uint64_t room = max_bytes - uint64_t(got);
                bytes.resize(got + size_t(std::min<uint64_t>(room, (uint64_t(1) << 16) - 1) + 1));
            }
            const ssize_t n = ::read(fd_, bytes.data() + got, bytes.size() - got);
            if (n < 0) {
                if (errno == EINTR) continue;
                error = path_ + ": cannot read the file (" + std::strerror(errno) + ").";
                bytes.clear();
                return false;
            }
            if (n == 0) break;
            got += size_t(n);
        }
        bytes.resize(got);
    } catch (const std::bad_alloc&) {
        error = path_ + ": out of memory while reading the file.";
        bytes.clear();
        return false;
    }
    if (uint64_t(bytes.size()) > max_bytes) {
        error = too_large;
        bytes.clear();
        return false;
    }
    return true;
}

bool read(const std::string& path, uint64_t max_bytes, std::vector<unsigned char>& bytes, std::string& error) {
    File f;
    return f.open(path, error) && f.read_all(max_bytes, bytes, error);
}

}  // namespace input_file
