// Runs the phongrast executable in a test's folder and captures what it says.
#ifndef PHONGRAST_TESTS_CLI_CLI_RUN_HPP
#define PHONGRAST_TESTS_CLI_CLI_RUN_HPP

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include <sys/wait.h>

#include "io_test_files.hpp"

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

/// Runs `phongrast ARGUMENTS` in `folder` and captures its exit status and output.
inline Run run_cli(const TemporaryFolder& folder, const std::string& arguments) {
    const std::string command = "cd '" + folder.file("") + "' && '" + std::string(PHONGRAST_CLI) + "' " + arguments +
                                " > stdout.txt 2> stderr.txt";
    const int raw = std::system(command.c_str());
    Run run;
    run.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    run.out = read_text(folder.file("stdout.txt"));
    run.err = read_text(folder.file("stderr.txt"));
    return run;
}

#endif  // PHONGRAST_TESTS_CLI_CLI_RUN_HPP
