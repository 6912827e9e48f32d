#include "batch_status.hpp"

#include <filesystem>
#include <iostream>
#include <map>

#include "batch_log.hpp"

namespace phongrast::cli {
namespace {

namespace fs = std::filesystem;

constexpr std::size_t lines_listed = 20;  // of each kind; the rest are counted

/// The latest record of each job (by its "time"), keyed by manifest line and
/// outputs, so that records of an older manifest with other names do not count.
std::map<std::pair<int, std::string>, nlohmann::json> latest_records(const std::string& output_folder,
                                                                     int* unreadable) {
    std::map<std::pair<int, std::string>, nlohmann::json> latest;
    for (nlohmann::json& record : read_logs(output_folder, unreadable)) {
        const std::pair<int, std::string> key{record.value("job", 0), record.value("outputs", nlohmann::json()).dump()};
        const auto it = latest.find(key);
        if (it == latest.end() || it->second.value("time", 0.0) <= record.value("time", 0.0)) {
            latest[key] = std::move(record);
        }
    }
    return latest;
}

}  // namespace

int print_status(const Manifest& manifest, const std::string& output_folder) {
    int unreadable = 0;
    const auto latest = latest_records(output_folder, &unreadable);
    std::size_t done = 0;
    std::size_t images = 0;
    std::vector<std::string> failed;
    std::vector<int> missing;
    for (const BatchJob& job : manifest.jobs) {
        images += job.outputs.size();
        if (outputs_exist(job, output_folder)) {
            ++done;
            continue;
        }
        const auto it = latest.find({job.line, nlohmann::json(job.outputs).dump()});
        const std::string status = it == latest.end() ? "" : it->second.value("status", "");
        if (status == "failed" || status == "timeout") {
            failed.push_back("line " + std::to_string(job.line) + ": " + status + ": " +
                             it->second.value("error", std::string()));
        } else {
            missing.push_back(job.line);
        }
    }
    std::cout << manifest.path << ": " << manifest.jobs.size() << " jobs (" << images << " images): " << done
              << " done, " << failed.size() << " failed, " << missing.size() << " missing\n";
    for (std::size_t i = 0; i < failed.size() && i < lines_listed; ++i) std::cout << "  failed " << failed[i] << '\n';
    if (failed.size() > lines_listed) std::cout << "  ... and " << failed.size() - lines_listed << " more failed\n";
    if (!missing.empty()) {
        std::cout << "  missing lines:";
        for (std::size_t i = 0; i < missing.size() && i < lines_listed; ++i) std::cout << ' ' << missing[i];
        if (missing.size() > lines_listed) std::cout << " ... and " << missing.size() - lines_listed << " more";
        std::cout << '\n';
    }
    if (unreadable > 0) std::cout << "  " << unreadable << " unreadable log lines ignored\n";
    std::cout.flush();
    return done == manifest.jobs.size() ? 0 : 1;
}

}  // namespace phongrast::cli
