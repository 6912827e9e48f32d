#include "phongrast/io/text_file.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <vector>

#include <sys/stat.h>
#include <unistd.h>

#include "phongrast/io/error.hpp"

namespace phongrast::io {
namespace {

/// Creates an empty, uniquely named file next to `path` that keeps its
/// extension (OpenImageIO picks the format from it) and returns its name.
std::string make_temporary_file_next_to(const std::string& path) {
    const std::filesystem::path target(path);
    const std::filesystem::path folder =
        target.has_parent_path() ? target.parent_path() : std::filesystem::path(".");
    const std::string extension = target.extension().string();
    std::string pattern =
        (folder / ("." + target.stem().string() + ".tmp-XXXXXX" + extension)).string();
    std::vector<char> buffer(pattern.begin(), pattern.end());
    buffer.push_back('\0');
    const int descriptor = mkstemps(buffer.data(), static_cast<int>(extension.size()));
    if (descriptor < 0) {
        throw FileError(path + ": cannot write a file in folder '" + folder.string() +
                        "': " + std::strerror(errno));
    }
    // mkstemps makes the file private (0600); give it the permissions a plain
    // new file would have, so the renamed result is not surprisingly private.
    const mode_t mask = umask(0);
    umask(mask);
    fchmod(descriptor, static_cast<mode_t>(0666 & ~mask));
    close(descriptor);
    return std::string(buffer.data());
}

}  // namespace

void replace_file_atomically(const std::string& path,
                             const std::function<void(const std::string&)>& write) {
    const std::string temporary = make_temporary_file_next_to(path);
    try {
        write(temporary);
        if (std::rename(temporary.c_str(), path.c_str()) != 0) {
            throw FileError(path + ": cannot replace the file: " + std::strerror(errno));
        }
    } catch (...) {
        std::remove(temporary.c_str());
        throw;
    }
}

void write_text_file(const std::string& path, const std::string& text) {
    replace_file_atomically(path, [&](const std::string& temporary) {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        out << text;
        out.flush();
        if (!out) throw FileError(path + ": write failed: " + std::strerror(errno));
    });
}

}  // namespace phongrast::io
