// Small text files (stats JSON, scene JSON) written atomically.
#ifndef PHONGRAST_IO_TEXT_FILE_HPP
#define PHONGRAST_IO_TEXT_FILE_HPP

#include <functional>
#include <string>

namespace phongrast::io {

/// Calls `write(temporary_path)`, then renames the temporary file (in the same
/// folder as `path`) onto `path`; on any exception the temporary file is
/// removed and the exception passes on. Throws FileError when the rename fails.
void replace_file_atomically(const std::string& path,
                             const std::function<void(const std::string& temporary_path)>& write);

/// Writes `text` to `path` through replace_file_atomically. Throws FileError.
void write_text_file(const std::string& path, const std::string& text);

}  // namespace phongrast::io

#endif  // PHONGRAST_IO_TEXT_FILE_HPP
