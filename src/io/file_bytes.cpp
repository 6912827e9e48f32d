#include "file_bytes.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>

#include <fcntl.h>
#include <sys/mman.h>
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

FileBytes::~FileBytes() {
    if (mapped_) ::munmap(const_cast<char*>(data_), size_);
}

FileBytes::FileBytes(FileBytes&& other) noexcept
    : buffer_(std::move(other.buffer_)), data_(other.data_), size_(other.size_), mapped_(other.mapped_) {
    other.data_ = nullptr;
    other.size_ = 0;
    other.mapped_ = false;
}

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
    if (S_ISREG(status.st_mode) && status.st_size > 0) {
        // A regular file is mapped, pages filled in advance: no copy, no zero fill.
        const auto size = static_cast<std::size_t>(status.st_size);
        void* mapping = ::mmap(nullptr, size, PROT_READ, MAP_PRIVATE | MAP_POPULATE, file.get(), 0);
        if (mapping != MAP_FAILED) {
            bytes.data_ = static_cast<const char*>(mapping);
            bytes.size_ = size;
            bytes.mapped_ = true;
            return bytes;
        }
    }
    // Pipes, empty or unmappable files: read until the end.
    std::size_t capacity = 0;
    for (;;) {
        if (bytes.size_ == capacity) {
            capacity = capacity * 2 + 65536;
            std::unique_ptr<char[]> larger(new char[capacity]);
            if (bytes.size_ > 0) std::memcpy(larger.get(), bytes.buffer_.get(), bytes.size_);
            bytes.buffer_ = std::move(larger);
        }
        const ssize_t got = ::read(file.get(), bytes.buffer_.get() + bytes.size_, capacity - bytes.size_);
        if (got < 0 && errno == EINTR) continue;
        if (got < 0) throw cannot_read();
        if (got == 0) break;
        bytes.size_ += static_cast<std::size_t>(got);
    }
    bytes.data_ = bytes.buffer_.get();
    return bytes;
}

}  // namespace phongrast::io
