// Which part of a manifest one process renders ("shard I of N"), and how the
// jobs are split.
//
// The split is deterministic: every shard computes it from the same manifest
// and picks its own part, with no communication. Jobs are taken heaviest
// first (ties: manifest order) and each goes to the shard with the least
// expected work so far (ties: the lowest shard number): greedy longest-first
// scheduling, so no shard ends more than one job's work above the mean. A
// shard then renders its jobs in manifest order. A job (one manifest line,
// all of its views) is never split.
#ifndef PHONGRAST_APPS_BATCH_SHARD_HPP
#define PHONGRAST_APPS_BATCH_SHARD_HPP

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "batch_manifest.hpp"

namespace phongrast::cli {

struct Shard {
    int index = 0;  ///< 0-based
    int count = 1;
};

/// "I/N" with 0 <= I < N. Throws std::invalid_argument naming --shard.
Shard parse_shard(const std::string& text);

/// Reads an environment variable; nullptr when unset (std::getenv, or a map in tests).
using Environment = std::function<const char*(const char*)>;

/// The shard to render: `--shard I/N` if given; else a Slurm job array task
/// (SLURM_ARRAY_TASK_ID minus SLURM_ARRAY_TASK_MIN, divided by
/// SLURM_ARRAY_TASK_STEP when set, of SLURM_ARRAY_TASK_COUNT); else a
/// Kubernetes Indexed Job (JOB_COMPLETION_INDEX of `--shards N`); else the
/// whole manifest (0 of 1). `shards` is 0 when --shards was not given.
/// Throws std::invalid_argument for inconsistent values.
Shard choose_shard(const std::string& shard_flag, int shards, const Environment& environment);

/// Expected work of a job in sample-sized units:
/// views x (width x height x samples^2 + mesh file bytes / 8). The image size
/// is the job's "size", else the scene file's (read now), else the automatic
/// framing's 512x512; the mesh size is its file size (0 when unreadable).
/// Inputs must not change while the shards start, or they could disagree.
double expected_work(const BatchJob& job);

/// Jobs (indices into `work`) of each of `count` shards, each list in
/// increasing order. Together the lists hold every index exactly once.
std::vector<std::vector<std::size_t>> partition(const std::vector<double>& work, int count);

/// The log of one shard: OUTDIR/.phongrast-batch/shard-I-of-N.jsonl.
std::string shard_log_name(const Shard& shard);

}  // namespace phongrast::cli

#endif  // PHONGRAST_APPS_BATCH_SHARD_HPP
