// Runs the phongrast executable in a test's folder and captures what it says.
#ifndef PHONGRAST_TESTS_CLI_CLI_RUN_HPP
#define PHONGRAST_TESTS_CLI_CLI_RUN_HPP

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include <sys/wait.h>

#include "io_test_files.hpp"
#include "phongrast/io/scene_load.hpp"
#include "phongrast/render.hpp"

struct Run {
    int status = -1;
    std::string out;
    std::string err;
};

inline std::string read_text(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

/// Runs `phongrast ARGUMENTS` (a shell command line; `environment` is put in
/// front, e.g. "A=1 B=2") in `folder` and captures its exit status and output.
inline Run run_cli(const TemporaryFolder& folder, const std::string& arguments, const std::string& environment = "") {
    const std::string command = "cd '" + folder.file("") + "' && " + environment + " '" + std::string(PHONGRAST_CLI) +
                                "' " + arguments + " > stdout.txt 2> stderr.txt";
    const int raw = std::system(command.c_str());
    Run run;
    run.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    run.out = read_text(folder.file("stdout.txt"));
    run.err = read_text(folder.file("stderr.txt"));
    return run;
}

/// The scene a scene file describes, loaded by the library's scene builder
/// (io::load_scene), the one the program uses.
inline phongrast::Scene load_scene_with_library(const std::string& scene_path) {
    return phongrast::io::load_scene(scene_path).scene;
}

#endif  // PHONGRAST_TESTS_CLI_CLI_RUN_HPP
