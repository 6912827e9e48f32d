#include "batch_test_support.hpp"

#include <catch2/catch.hpp>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include "phongrast/io/image_file.hpp"

namespace batch_test {
namespace {

namespace fs = std::filesystem;

}  // namespace

pid_t start_batch(const TemporaryFolder& folder, const std::vector<std::string>& arguments) {
    std::vector<std::string> words = {PHONGRAST_CLI, "batch", "--quiet"};
    for (const std::string& argument : arguments) words.push_back(argument);
    std::vector<char*> argv;
    for (std::string& word : words) argv.push_back(word.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, folder.file("background-stderr.txt").c_str(),
                                     O_WRONLY | O_CREAT | O_TRUNC, 0644);
    pid_t pid = -1;
    // The paths given are absolute: no chdir needed.
    const int error = posix_spawn(&pid, PHONGRAST_CLI, &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    REQUIRE(error == 0);
    return pid;
}

std::string generate_mesh(const TemporaryFolder& folder, const std::string& name, int segments, int sides) {
    const Run run = run_phongrast(folder, "generate --quiet -o " + name + " --segments " + std::to_string(segments) +
                                              " --sides " + std::to_string(sides));
    REQUIRE(run.status == 0);
    return folder.file(name);
}

std::vector<nlohmann::json> log_records(const std::string& output_folder) {
    std::vector<nlohmann::json> records;
    std::error_code error;
    for (const auto& entry : fs::directory_iterator(fs::path(output_folder) / ".phongrast-batch", error)) {
        std::ifstream in(entry.path());
        for (std::string line; std::getline(in, line);) {
            INFO(entry.path().string() << ": " << line);
            const nlohmann::json record = nlohmann::json::parse(line, nullptr, false);
            REQUIRE(record.is_object());
            records.push_back(record);
        }
    }
    return records;
}

std::map<std::string, std::string> files_under(const std::string& folder) {
    std::map<std::string, std::string> files;
    for (const auto& entry : fs::recursive_directory_iterator(folder)) {
        const std::string relative = fs::relative(entry.path(), folder).string();
        if (entry.is_regular_file() && relative.rfind(".phongrast-batch", 0) != 0) {
            files[relative] = read_text(entry.path().string());
            if (entry.path().extension() == ".exr") {
                // OpenEXR stamps each file with the time it was written: compare the pixels.
                const phongrast::Image image = phongrast::io::read_image(entry.path().string());
                files[relative].assign(reinterpret_cast<const char*>(image.pixels.data()),
                                       image.pixels.size() * sizeof(image.pixels[0]));
            }
        }
    }
    return files;
}

std::vector<std::string> temporary_files_under(const std::string& folder) {
    std::vector<std::string> found;
    for (const auto& entry : fs::recursive_directory_iterator(folder)) {
        if (entry.path().filename().string().find(".tmp-") != std::string::npos) found.push_back(entry.path().string());
    }
    return found;
}

fs::file_time_type modified(const std::string& path) { return fs::last_write_time(path); }

}  // namespace batch_test
