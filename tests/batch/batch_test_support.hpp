// Running `phongrast batch` as a user does, for the command's end-to-end tests:
// generated meshes, manifests, runs in the foreground or background, logs and
// the files of an output folder.
#ifndef PHONGRAST_TESTS_BATCH_TEST_SUPPORT_HPP
#define PHONGRAST_TESTS_BATCH_TEST_SUPPORT_HPP

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <sys/types.h>

#include "cli/cli_run.hpp"
#include "io_test_files.hpp"

namespace batch_test {

using ::Run;

/// run_cli() of tests/cli/cli_run.hpp: `phongrast ARGUMENTS` in `folder`, `environment` put in front.
inline Run run_phongrast(const TemporaryFolder& folder, const std::string& arguments,
                         const std::string& environment = "") {
    return run_cli(folder, arguments, environment);
}

/// Starts `phongrast batch MANIFEST -o OUTDIR EXTRA...` in the background in `folder`; returns its pid.
pid_t start_batch(const TemporaryFolder& folder, const std::vector<std::string>& arguments);

/// The default knot with `segments` rings, written by `phongrast generate`.
std::string generate_mesh(const TemporaryFolder& folder, const std::string& name, int segments, int sides);

/// Every record of every shard log in OUTDIR; fails the test on a line that is not a JSON object.
std::vector<nlohmann::json> log_records(const std::string& output_folder);

/// Relative path -> contents of every file under `folder`, the log folder
/// excluded; for EXR files the pixels (the file holds the time it was written).
std::map<std::string, std::string> files_under(const std::string& folder);

/// Relative paths of temporary files (".NAME.tmp-XXXXXX.EXT") anywhere under `folder`.
std::vector<std::string> temporary_files_under(const std::string& folder);

std::filesystem::file_time_type modified(const std::string& path);

}  // namespace batch_test

#endif  // PHONGRAST_TESTS_BATCH_TEST_SUPPORT_HPP
