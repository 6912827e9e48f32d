#include "batch_shard.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <numeric>
#include <stdexcept>

#include "command_line.hpp"
#include "phongrast/io/scene_file.hpp"

namespace phongrast::cli {
namespace {

namespace fs = std::filesystem;

/// A whole number from an environment variable; throws naming the variable.
long long environment_number(const Environment& environment, const char* name, bool required) {
    const char* text = environment(name);
    if (text == nullptr) {
        if (required) throw std::invalid_argument(std::string(name) + " is not set (a Slurm job array sets it)");
        return -1;
    }
    long long value = 0;
    char rest = 0;
    if (std::sscanf(text, "%lld%c", &value, &rest) != 1 || value < 0) {
        throw std::invalid_argument(std::string(name) + ": expected a whole number, got '" + text + "'");
    }
    return value;
}

Shard slurm_shard(const Environment& environment) {
    const long long id = environment_number(environment, "SLURM_ARRAY_TASK_ID", true);
    const long long low = environment_number(environment, "SLURM_ARRAY_TASK_MIN", true);
    const long long count = environment_number(environment, "SLURM_ARRAY_TASK_COUNT", true);
    long long step = environment_number(environment, "SLURM_ARRAY_TASK_STEP", false);
    if (step <= 0) step = 1;
    const long long offset = id - low;
    if (count < 1 || offset < 0 || offset % step != 0 || offset / step >= count) {
        throw std::invalid_argument("Slurm array task " + std::to_string(id) + " (min " + std::to_string(low) +
                                    ", step " + std::to_string(step) + ", count " + std::to_string(count) +
                                    ") is not in a range A-B[:S]; submit with --array=A-B or give --shard I/N");
    }
    return {static_cast<int>(offset / step), static_cast<int>(count)};
}

std::uint64_t file_bytes(const std::string& path) {
    std::error_code error;
    const std::uintmax_t bytes = fs::file_size(path, error);
    return error ? 0 : static_cast<std::uint64_t>(bytes);
}

}  // namespace

Shard parse_shard(const std::string& text) {
    int index = 0;
    int count = 0;
    char rest = 0;
    if (std::sscanf(text.c_str(), "%d/%d%c", &index, &count, &rest) != 2 || count < 1 || index < 0 ||
        index >= count) {
        throw std::invalid_argument("--shard: expected I/N with 0 <= I < N, e.g. 0/4; got '" + text + "'");
    }
    return {index, count};
}

Shard choose_shard(const std::string& shard_flag, int shards, const Environment& environment) {
    if (!shard_flag.empty()) {
        if (shards > 0) throw std::invalid_argument("--shards: give either --shard I/N or --shards N, not both");
        return parse_shard(shard_flag);
    }
    if (environment("SLURM_ARRAY_TASK_ID") != nullptr) {
        const Shard shard = slurm_shard(environment);
        if (shards > 0 && shards != shard.count) {
            throw std::invalid_argument("--shards " + std::to_string(shards) + " disagrees with the Slurm array's " +
                                        std::to_string(shard.count) + " tasks");
        }
        return shard;
    }
    if (environment("JOB_COMPLETION_INDEX") != nullptr) {
        if (shards < 1) {
            throw std::invalid_argument(
                "JOB_COMPLETION_INDEX is set (a Kubernetes Indexed Job): give --shards N, N being the Job's completions");
        }
        const long long index = environment_number(environment, "JOB_COMPLETION_INDEX", true);
        if (index >= shards) {
            throw std::invalid_argument("JOB_COMPLETION_INDEX " + std::to_string(index) + " is not below --shards " +
                                        std::to_string(shards));
        }
        return {static_cast<int>(index), shards};
    }
    if (shards > 0) {
        throw std::invalid_argument("--shards " + std::to_string(shards) +
                                    ": no shard index (JOB_COMPLETION_INDEX or SLURM_ARRAY_TASK_ID); give --shard I/N");
    }
    return {0, 1};
}

double expected_work(const BatchJob& job) {
    double pixels = 512.0 * 512.0;
    std::string mesh = job.kind == JobKind::mesh ? job.path : "";
    double mesh_bytes = 0.0;  // a scene of objects: each placement's file (a file placed twice is read once, but drawn twice)
    if (job.kind != JobKind::mesh) {
        try {  // Only the image size and mesh name are wanted; an unreadable scene is the job's failure, later.
            const io::SceneFile file = job.kind == JobKind::scene_file
                                           ? io::read_scene_file(job.path)
                                           : io::parse_scene_json(job.scene_json, "inline scene", job.folder);
            pixels = double(file.scene.image.rows) * double(file.scene.image.columns);
            mesh = file.mesh_path;
            for (const io::SceneFileObject& object : file.objects) mesh_bytes += double(file_bytes(object.mesh_path));
        } catch (const std::exception&) {
        }
    }
    if (!job.settings.size.empty()) {
        const auto [columns, rows] = parse_size(job.settings.size);
        pixels = double(columns) * double(rows);
    }
    const double samples = job.settings.samples.value_or(1);
    return double(job.views) * (pixels * samples * samples + (double(file_bytes(mesh)) + mesh_bytes) / 8.0);
}

std::vector<std::vector<std::size_t>> partition(const std::vector<double>& work, int count) {
    std::vector<std::size_t> heaviest_first(work.size());
    std::iota(heaviest_first.begin(), heaviest_first.end(), std::size_t{0});
    std::stable_sort(heaviest_first.begin(), heaviest_first.end(),
                     [&](std::size_t a, std::size_t b) { return work[a] > work[b]; });
    std::vector<std::vector<std::size_t>> shards(static_cast<std::size_t>(std::max(count, 1)));
    std::vector<double> load(shards.size(), 0.0);
    for (const std::size_t job : heaviest_first) {
        const std::size_t lightest =
            static_cast<std::size_t>(std::min_element(load.begin(), load.end()) - load.begin());
        shards[lightest].push_back(job);
        load[lightest] += work[job];
    }
    for (std::vector<std::size_t>& jobs : shards) std::sort(jobs.begin(), jobs.end());
    return shards;
}

std::string shard_log_name(const Shard& shard) {
    return "shard-" + std::to_string(shard.index) + "-of-" + std::to_string(shard.count) + ".jsonl";
}

}  // namespace phongrast::cli
