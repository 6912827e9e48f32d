#include "phongrast/io/text_file.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include <fcntl.h>
#include <unistd.h>

#include "phongrast/io/error.hpp"

namespace phongrast::io {
namespace {

/// Six letters or digits for a temporary name, from a generator per thread
/// seeded from the system's entropy (a name already taken is simply tried again).
std::string random_letters() {
    static const char kLetters[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789";
    thread_local std::mt19937_64 random(std::random_device{}());
    std::string letters(6, 'X');
    for (char& letter : letters) letter = kLetters[random() % (sizeof kLetters - 1)];
    return letters;
}

/// Creates an empty, uniquely named file next to `path`, ".STEM.tmp-XXXXXX.EXT"
/// (it keeps the extension, which some writers pick the format from), and
/// returns its name. Created with mode 0666 less the umask, as any new file,
/// in one call (mkstemps made it 0600, then umask was read and restored and
/// the mode changed: three more system calls per image of a batch).
std::string make_temporary_file_next_to(const std::string& path) {
    const std::filesystem::path target(path);
    const std::filesystem::path folder =
        target.has_parent_path() ? target.parent_path() : std::filesystem::path(".");
    const std::string extension = target.extension().string();
    const std::string prefix = (folder / ("." + target.stem().string() + ".tmp-")).string();
    for (int attempt = 0; attempt < 100; ++attempt) {
        const std::string name = prefix + random_letters() + extension;
        const int descriptor = ::open(name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (descriptor >= 0) {
            ::close(descriptor);
            return name;
        }
        if (errno != EEXIST) break;
    }
    throw FileError(path + ": cannot write a file in folder '" + folder.string() + "': " + std::strerror(errno));
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
