// EXR files through OpenEXR (internal header): scanline files with ZIP
// compression (16 rows per block, what OpenImageIO's "zip" wrote), channels
// of 32-bit float or 32-bit unsigned integer.
#ifndef PHONGRAST_SRC_IO_EXR_FILE_HPP
#define PHONGRAST_SRC_IO_EXR_FILE_HPP

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace phongrast::io::detail {

/// One channel in memory: the value of pixel (row, column) is at
/// base + (row * columns + column) * stride bytes.
struct ExrChannel {
    std::string name;
    bool unsigned_int = false;  ///< false: 32-bit float
    char* base = nullptr;
    std::size_t stride = 4;
};

/// Writes `file` (the temporary file; `path` names the destination in errors). Throws FileError.
void write_exr(const std::string& file, const std::string& path, int columns, int rows,
               const std::vector<ExrChannel>& channels);

/// An open EXR file (its first part). Throws FileError naming the path.
class ExrReader {
public:
    explicit ExrReader(const std::string& path);
    ~ExrReader();
    int rows() const { return rows_; }
    int columns() const { return columns_; }
    /// The file's channel names (OpenEXR keeps them in alphabetical order).
    const std::vector<std::string>& channel_names() const { return names_; }
    bool has(const std::string& name) const;
    /// Reads the channels into memory laid out as ExrChannel says (converted
    /// to float or unsigned as asked). Throws FileError.
    void read(const std::vector<ExrChannel>& channels);

private:
    struct File;
    std::unique_ptr<File> file_;
    std::string path_;
    int rows_ = 0;
    int columns_ = 0;
    std::vector<std::string> names_;
};

}  // namespace phongrast::io::detail

#endif  // PHONGRAST_SRC_IO_EXR_FILE_HPP
