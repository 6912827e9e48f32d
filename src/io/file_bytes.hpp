// A whole file in memory, read with one read() per chunk into an uninitialised
// buffer (no zero fill, no stream copies: the mesh readers parse at disk speed).
#ifndef PHONGRAST_IO_FILE_BYTES_HPP
#define PHONGRAST_IO_FILE_BYTES_HPP

#include <cstddef>
#include <memory>
#include <string>
#include <string_view>

namespace phongrast::io {

class FileBytes {
public:
    const char* data() const { return data_.get(); }
    std::size_t size() const { return size_; }
    std::string_view view() const { return {data_.get(), size_}; }

    /// Reads `path`; `what` names it in errors ("mesh" -> "path: mesh not found
    /// (no such file)", "path: is a folder; expected mesh file").
    static FileBytes read(const std::string& path, const char* what);

private:
    std::unique_ptr<char[]> data_;
    std::size_t size_ = 0;
};

}  // namespace phongrast::io

#endif  // PHONGRAST_IO_FILE_BYTES_HPP
