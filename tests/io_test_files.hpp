// A fresh temporary folder per test, and writing small text fixtures into it.
#ifndef PHONGRAST_TESTS_IO_TEST_FILES_HPP
#define PHONGRAST_TESTS_IO_TEST_FILES_HPP

#include <atomic>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

class TemporaryFolder {
public:
    TemporaryFolder() {
        static std::atomic<int> counter{0};
        path_ = std::filesystem::temp_directory_path() /
                ("phongrast-io-test-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
        std::filesystem::remove_all(path_);
        std::filesystem::create_directories(path_);
    }
    ~TemporaryFolder() {
        std::error_code ignored;
        std::filesystem::remove_all(path_, ignored);
    }
    TemporaryFolder(const TemporaryFolder&) = delete;
    TemporaryFolder& operator=(const TemporaryFolder&) = delete;

    std::string file(const std::string& name) const { return (path_ / name).string(); }
    std::string write(const std::string& name, const std::string& text) const {
        std::ofstream(path_ / name, std::ios::binary) << text;
        return file(name);
    }
    /// Names of the files in the folder (to check no temporary file is left behind).
    std::size_t entry_count() const {
        std::size_t count = 0;
        for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(path_)) ++count;
        return count;
    }

private:
    std::filesystem::path path_;
};

#endif  // PHONGRAST_TESTS_IO_TEST_FILES_HPP
