// Sharding: the scheduler's variables, and the split of the jobs being a
// deterministic partition balanced by expected work.
#include <catch2/catch.hpp>

#include <algorithm>
#include <fstream>
#include <map>
#include <numeric>
#include <random>

#include "batch_shard.hpp"
#include "io_test_files.hpp"

using namespace phongrast::cli;

namespace {

Environment environment(const std::map<std::string, std::string>& variables) {
    return [variables](const char* name) -> const char* {
        const auto it = variables.find(name);
        return it == variables.end() ? nullptr : it->second.c_str();
    };
}

bool same(const Shard& a, const Shard& b) { return a.index == b.index && a.count == b.count; }

}  // namespace

TEST_CASE("the --shard flag I/N is checked") {
    CHECK(same(parse_shard("0/1"), {0, 1}));
    CHECK(same(parse_shard("3/4"), {3, 4}));
    for (const char* bad : {"4/4", "-1/4", "1/0", "1", "1/4x", "a/b", ""}) {
        INFO(bad);
        CHECK_THROWS_WITH(parse_shard(bad), Catch::StartsWith("--shard: expected I/N"));
    }
}

TEST_CASE("the shard comes from --shard, else Slurm's array variables, else JOB_COMPLETION_INDEX") {
    const Environment none = environment({});
    CHECK(same(choose_shard("", 0, none), {0, 1}));
    CHECK(same(choose_shard("2/5", 0, none), {2, 5}));
    // --array=0-3: task 2 of 4.
    const Environment slurm = environment(
        {{"SLURM_ARRAY_TASK_ID", "2"}, {"SLURM_ARRAY_TASK_MIN", "0"}, {"SLURM_ARRAY_TASK_COUNT", "4"}});
    CHECK(same(choose_shard("", 0, slurm), {2, 4}));
    CHECK(same(choose_shard("1/3", 0, slurm), {1, 3}));  // the flag wins
    // --array=1-4 counts from 1; --array=10-16:2 has a step.
    CHECK(same(choose_shard("", 0, environment({{"SLURM_ARRAY_TASK_ID", "1"}, {"SLURM_ARRAY_TASK_MIN", "1"},
                                                {"SLURM_ARRAY_TASK_COUNT", "4"}})),
               {0, 4}));
    CHECK(same(choose_shard("", 0, environment({{"SLURM_ARRAY_TASK_ID", "14"}, {"SLURM_ARRAY_TASK_MIN", "10"},
                                                {"SLURM_ARRAY_TASK_COUNT", "4"}, {"SLURM_ARRAY_TASK_STEP", "2"}})),
               {2, 4}));
    // --array=1,5,7 is no range: task 7 would be "shard 6 of 3".
    CHECK_THROWS_WITH(choose_shard("", 0, environment({{"SLURM_ARRAY_TASK_ID", "7"}, {"SLURM_ARRAY_TASK_MIN", "1"},
                                                       {"SLURM_ARRAY_TASK_COUNT", "3"}})),
                      Catch::Contains("is not in a range A-B[:S]"));
    CHECK_THROWS_WITH(choose_shard("", 0, environment({{"SLURM_ARRAY_TASK_ID", "1"}})),
                      Catch::Contains("SLURM_ARRAY_TASK_MIN is not set"));
    CHECK_THROWS_WITH(choose_shard("", 5, slurm), Catch::Contains("--shards 5 disagrees with the Slurm array's 4"));
    // Kubernetes Indexed Job: the index from the environment, the count from --shards.
    const Environment kubernetes = environment({{"JOB_COMPLETION_INDEX", "3"}});
    CHECK(same(choose_shard("", 8, kubernetes), {3, 8}));
    CHECK_THROWS_WITH(choose_shard("", 0, kubernetes), Catch::Contains("give --shards N"));
    CHECK_THROWS_WITH(choose_shard("", 3, kubernetes), Catch::Contains("JOB_COMPLETION_INDEX 3 is not below --shards 3"));
    CHECK_THROWS_WITH(choose_shard("", 0, environment({{"JOB_COMPLETION_INDEX", "x"}})), Catch::Contains("give --shards"));
    CHECK_THROWS_WITH(choose_shard("", 2, environment({{"JOB_COMPLETION_INDEX", "x"}})),
                      Catch::Contains("JOB_COMPLETION_INDEX: expected a whole number, got 'x'"));
    CHECK_THROWS_WITH(choose_shard("", 4, none), Catch::Contains("no shard index"));
    CHECK_THROWS_WITH(choose_shard("0/4", 4, none), Catch::Contains("not both"));
}

TEST_CASE("the shards are a partition of the jobs, the same for every call, balanced by expected work") {
    std::mt19937 random(14);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    for (const std::size_t jobs : {0, 1, 7, 40, 1000}) {
        std::vector<double> work(jobs);
        // Mostly small jobs, some 100x larger, as turntables of many views among single images are.
        for (double& w : work) w = uniform(random) < 0.1 ? 100.0 * (1.0 + uniform(random)) : 1.0 + uniform(random);
        for (const int count : {1, 2, 3, 4, 7, 16}) {
            INFO(jobs << " jobs, " << count << " shards");
            const auto shards = partition(work, count);
            REQUIRE(shards.size() == static_cast<std::size_t>(count));
            CHECK(partition(work, count) == shards);
            std::vector<int> times_taken(jobs, 0);
            const double total = std::accumulate(work.begin(), work.end(), 0.0);
            const double heaviest = jobs == 0 ? 0.0 : *std::max_element(work.begin(), work.end());
            for (const auto& shard : shards) {
                CHECK(std::is_sorted(shard.begin(), shard.end()));
                double load = 0.0;
                for (const std::size_t job : shard) {
                    ++times_taken.at(job);
                    load += work[job];
                }
                // Greedy longest-first: no shard is more than one job above the mean.
                CHECK(load <= total / count + heaviest + 1e-9);
            }
            CHECK(std::all_of(times_taken.begin(), times_taken.end(), [](int taken) { return taken == 1; }));
        }
    }
}

TEST_CASE("balance follows the work, not the job count") {
    // One 24-view turntable and 24 single images: 2 shards of equal work, not of equal job counts.
    std::vector<double> work(25, 1.0);
    work[0] = 24.0;
    const auto shards = partition(work, 2);
    CHECK(shards[0] == std::vector<std::size_t>{0});
    CHECK(shards[1].size() == 24);
}

TEST_CASE("expected work: views x pixels x samples^2, plus the mesh file's size") {
    TemporaryFolder folder;
    const std::string mesh = folder.write("m.obj", std::string(8000, '#'));
    BatchJob job;
    job.kind = JobKind::mesh;
    job.path = mesh;
    job.settings.size = "100x50";
    CHECK(expected_work(job) == Approx(100.0 * 50.0 + 1000.0));
    job.views = 10;
    job.settings.samples = 2;
    CHECK(expected_work(job) == Approx(10.0 * (100.0 * 50.0 * 4.0 + 1000.0)));
    job.path = folder.file("missing.obj");
    job.settings.size.clear();
    CHECK(expected_work(job) == Approx(10.0 * 512.0 * 512.0 * 4.0));  // the framing's default size
    // A scene file's own image size counts when the line sets none.
    folder.write("s.json", R"({"mesh": "m.obj", "camera": {"eye": [0,0,5], "lookat": [0,0,0], "focal": 1,
                               "sensor": [1,1]}, "image": {"height": 20, "width": 30}})");
    BatchJob scene;
    scene.path = folder.file("s.json");
    CHECK(expected_work(scene) == Approx(600.0 + 1000.0));
    CHECK(shard_log_name({2, 5}) == "shard-2-of-5.jsonl");
}
