#include "file_bytes.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "phongrast/io/error.hpp"

namespace phongrast::io {
namespace {

class Descriptor {
public:
    explicit Descriptor(int descriptor) : descriptor_(descriptor) {}
    ~Descriptor() {
        if (descriptor_ >= 0) ::close(descriptor_);
    }
    Descriptor(const Descriptor&) = delete;
    Descriptor& operator=(const Descriptor&) = delete;
    int get() const { return descriptor_; }

private:
    int descriptor_;
};

}  // namespace

FileBytes FileBytes::read(const std::string& path, const char* what) {
    std::error_code error;
    if (!std::filesystem::exists(path, error)) {
        throw FileError(path + ": " + what + " not found (no such file)");
    }
    if (std::filesystem::is_directory(path, error)) {
        throw FileError(path + ": is a folder; expected " + std::string(what) + " file");
    }
    const auto cannot_read = [&] { return FileError(path + ": cannot read " + what + ": " + std::strerror(errno)); };
    const Descriptor file(::open(path.c_str(), O_RDONLY | O_CLOEXEC));
    struct stat status {};
    if (file.get() < 0 || ::fstat(file.get(), &status) != 0) throw cannot_read();

    FileBytes bytes;
    std::size_t capacity = status.st_size > 0 ? static_cast<std::size_t>(status.st_size) : 0;
    bytes.data_.reset(new char[capacity + 1]);
    for (;;) {
        if (bytes.size_ == capacity) {  // the file grew, or is a pipe: make room
            capacity = capacity * 2 + 4096;
            std::unique_ptr<char[]> larger(new char[capacity + 1]);
            std::memcpy(larger.get(), bytes.data_.get(), bytes.size_);
            bytes.data_ = std::move(larger);
        }
        const ssize_t got = ::read(file.get(), bytes.data_.get() + bytes.size_, capacity - bytes.size_);
        if (got < 0 && errno == EINTR) continue;
        if (got < 0) throw cannot_read();
        if (got == 0) break;
        bytes.size_ += static_cast<std::size_t>(got);
    }
    bytes.data_[bytes.size_] = '\0';  // a terminator, so text parsers may look one byte ahead
    return bytes;
}

}  // namespace phongrast::io
