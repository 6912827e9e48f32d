#include "batch_log.hpp"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>

#include <fcntl.h>
#include <unistd.h>

#include "phongrast/io/error.hpp"

namespace phongrast::cli {
namespace {

namespace fs = std::filesystem;

void write_all(int descriptor, const std::string& text, const std::string& path) {
    std::size_t sent = 0;
    while (sent < text.size()) {
        const ssize_t written = ::write(descriptor, text.data() + sent, text.size() - sent);
        if (written < 0 && errno == EINTR) continue;
        if (written <= 0) throw io::FileError(path + ": cannot append to the log: " + std::strerror(errno));
        sent += static_cast<std::size_t>(written);
    }
}

/// True when the file is empty or ends with a newline.
bool ends_with_newline(int descriptor) {
    const off_t size = ::lseek(descriptor, 0, SEEK_END);
    if (size <= 0) return true;
    char last = '\n';
    return ::pread(descriptor, &last, 1, size - 1) == 1 && last == '\n';
}

}  // namespace

std::string log_folder(const std::string& output_folder) {
    return (fs::path(output_folder) / ".phongrast-batch").string();
}

BatchLog::BatchLog(const std::string& path) : path_(path) {
    descriptor_ = ::open(path.c_str(), O_RDWR | O_APPEND | O_CREAT | O_CLOEXEC, 0644);
    if (descriptor_ < 0) throw io::FileError(path + ": cannot open the log: " + std::strerror(errno));
    // A line cut short (disk full, power loss) must not swallow the next record.
    if (!ends_with_newline(descriptor_)) write_all(descriptor_, "\n", path_);
}

BatchLog::~BatchLog() {
    if (descriptor_ >= 0) ::close(descriptor_);
}

void BatchLog::append(nlohmann::json record) {
    const auto now = std::chrono::system_clock::now().time_since_epoch();
    record["time"] = std::chrono::duration<double>(now).count();
    write_all(descriptor_, record.dump() + "\n", path_);
}

std::vector<nlohmann::json> read_logs(const std::string& output_folder, int* unreadable) {
    std::vector<nlohmann::json> records;
    *unreadable = 0;
    std::error_code error;
    std::vector<fs::path> logs;
    for (const fs::directory_entry& entry : fs::directory_iterator(log_folder(output_folder), error)) {
        if (entry.path().extension() == ".jsonl") logs.push_back(entry.path());
    }
    std::sort(logs.begin(), logs.end());
    for (const fs::path& log : logs) {
        std::ifstream in(log);
        for (std::string line; std::getline(in, line);) {
            if (line.empty()) continue;
            nlohmann::json record = nlohmann::json::parse(line, nullptr, false);
            if (record.is_object() && record.contains("job")) {
                records.push_back(std::move(record));
            } else {
                ++*unreadable;
            }
        }
    }
    return records;
}

}  // namespace phongrast::cli
