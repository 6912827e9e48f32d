// phongrast batch: many images from a JSON Lines manifest, one shard of it per
// process (Slurm job arrays, Kubernetes Indexed Jobs, GNU parallel), resumable.
#include <cstdlib>
#include <filesystem>
#include <iostream>

#include "batch_shard.hpp"
#include "batch_status.hpp"
#include "batch_supervisor.hpp"
#include "commands.hpp"
#include "phongrast/io/error.hpp"
#include "phongrast/option_names.hpp"

namespace phongrast::cli {

void add_batch_command(CLI::App& app, BatchCommand& command) {
    CLI::App* batch = app.add_subcommand(
        "batch",
        "Render every job of a JSON Lines manifest (one scene, inline scene, or mesh seen from several views, per line) into "
        "OUTDIR, or one shard of it; skips jobs whose images exist. See docs/batch.md.");
    batch->add_option("manifest", command.manifest, "Manifest, one JSON job per line")->required();
    batch->add_option("-o,--output", command.output_folder, "Output folder (created if missing)")->required();
    batch->add_option("--shard", command.shard,
                      "Render shard I of N (0 <= I < N). Default: from SLURM_ARRAY_TASK_ID/_MIN/_COUNT, or "
                      "JOB_COMPLETION_INDEX with --shards, else everything");
    batch->add_option("--shards", command.shards,
                      "Number of shards, with JOB_COMPLETION_INDEX (Kubernetes Indexed Job) as the index")
        ->check(CLI::Range(1, 1000000));
    batch->add_option("--job-timeout", command.job_timeout,
                      "Stop a job running longer than this many seconds, record it as timed out, go on")
        ->check(CLI::PositiveNumber);
    batch->add_flag("--force", command.force, "Render jobs even when their images exist");
    batch->add_flag("--status", command.status,
                    "Render nothing: summarise done, failed and missing jobs over every shard's log");
    batch->add_option("--threads", command.threads, "Worker threads; 0 = all cores")
        ->check(CLI::NonNegativeNumber)
        ->capture_default_str();
    batch->add_option("--shader", command.defaults.shader, "Default shader for jobs that set none");
    batch->add_option("--lighting", command.defaults.lighting, "Default lighting for jobs that set none");
    batch->add_option("--size", command.defaults.size, "Default image size WxH for jobs that set none");
    batch->add_option("--samples", command.samples, "Default samples per pixel axis for jobs that set none")
        ->check(CLI::Range(1, 16));
    for (const NamedOption& option : named_options()) {  // --mode, --visibility, ... --texture-filter
        batch->add_option(option_flag(option), command.defaults.options[option.key],
                          "Default for jobs that set none: " + option.help)
            ->check(CLI::IsMember(accepted_names(option)));
    }
    add_png_compression_flag(*batch, command.png_compression);
    add_dataset_file_flags(*batch, command.defaults.dataset_files, command.depth_scale);
    batch->add_option("--camera-out", command.defaults.camera_out,
                      "Default per-job camera file, a name pattern with {name} and {line} ending in .json: every "
                      "view's camera as render --camera-out writes it (docs/datasets.md)");
    batch->add_option("--transforms-out", command.defaults.transforms_out,
                      "Default per-job transforms.json (instant-ngp / nerfstudio layout), a name pattern with {name} "
                      "and {line}, e.g. {name}/transforms.json");
    batch->add_flag("-q,--quiet", command.quiet, "Print nothing but errors");
}

int run_batch(const BatchCommand& command) {
    JobSettings defaults = command.defaults;
    if (command.samples > 0) defaults.samples = command.samples;
    if (command.depth_scale > 0.0) defaults.depth_scale = command.depth_scale;
    // Check the command-line defaults as a manifest line would be checked.
    parse_manifest("{\"mesh\": \"-.obj\"}", "command line", ".", defaults);
    const Manifest manifest = read_manifest(command.manifest, defaults);
    if (command.status) return print_status(manifest, command.output_folder);

    const Shard shard = choose_shard(command.shard, command.shards, [](const char* name) { return std::getenv(name); });
    std::vector<double> work;
    for (const BatchJob& job : manifest.jobs) work.push_back(expected_work(job));
    const std::vector<std::vector<std::size_t>> shards = partition(work, shard.count);
    std::vector<const BatchJob*> jobs;
    for (const std::size_t index : shards[static_cast<std::size_t>(shard.index)]) {
        jobs.push_back(&manifest.jobs[index]);
    }
    std::error_code error;
    std::filesystem::create_directories(command.output_folder, error);
    if (!std::filesystem::is_directory(command.output_folder, error)) {
        throw io::FileError(command.output_folder + ": cannot create the output folder");
    }

    ShardRun run;
    run.output_folder = command.output_folder;
    run.shard = shard;
    run.job_timeout = command.job_timeout;
    run.force = command.force;
    run.quiet = command.quiet;
    run.threads = command.threads;
    run.image_options.png_compression = io::parse_png_compression(command.png_compression);
    return run_shard(jobs, run);
}

}  // namespace phongrast::cli
