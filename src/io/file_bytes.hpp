// A whole file in memory: a regular file is mapped read-only (no copy, no zero
// fill), anything else read into a buffer, so the mesh readers parse at disk speed.
#ifndef PHONGRAST_IO_FILE_BYTES_HPP
#define PHONGRAST_IO_FILE_BYTES_HPP

#include <cstddef>
#include <memory>
#include <string>
#include <string_view>

namespace phongrast::io {

class FileBytes {
public:
    FileBytes() = default;
    ~FileBytes();
    FileBytes(FileBytes&& other) noexcept;
    FileBytes(const FileBytes&) = delete;
    FileBytes& operator=(const FileBytes&) = delete;
    FileBytes& operator=(FileBytes&&) = delete;

    const char* data() const { return data_; }
    std::size_t size() const { return size_; }
    std::string_view view() const { return {data_, size_}; }

    /// Reads `path`; `what` names it in errors ("mesh" -> "path: mesh not found
    /// (no such file)", "path: is a folder; expected mesh file").
    static FileBytes read(const std::string& path, const char* what);

private:
    std::unique_ptr<char[]> buffer_;
    const char* data_ = nullptr;
    std::size_t size_ = 0;
    bool mapped_ = false;
};

}  // namespace phongrast::io

#endif  // PHONGRAST_IO_FILE_BYTES_HPP
