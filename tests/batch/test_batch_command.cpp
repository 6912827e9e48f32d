// `phongrast batch` as a user runs it: images equal to `render`'s, bad lines,
// bad meshes, resuming, a shard killed with SIGKILL, --job-timeout, shards
// that together render every job once, the scheduler's variables, --status.
#include <catch2/catch.hpp>

#include <chrono>
#include <csignal>
#include <fstream>
#include <set>
#include <thread>

#include <sys/wait.h>

#include "batch_test_support.hpp"

using namespace batch_test;
namespace fs = std::filesystem;

namespace {

/// Jobs rendered ("done") per manifest line, over every log in OUTDIR.
std::map<int, int> done_per_line(const std::string& output_folder) {
    std::map<int, int> done;
    for (const nlohmann::json& record : log_records(output_folder)) {
        if (record["status"] == "done") ++done[record["job"].get<int>()];
    }
    return done;
}

/// A manifest of `jobs` small turntables and scenes of the generated knot.
std::string small_manifest(const TemporaryFolder& folder, int jobs) {
    generate_mesh(folder, "knot.obj", 40, 6);
    folder.write("scene.json", R"({"mesh": "knot.obj", "camera": {"eye": [0, 0, 12], "lookat": [0, 0, 0],
        "focal": 4, "sensor": [8, 8]}, "image": {"height": 24, "width": 32},
        "lights": [{"position": [5, 5, 10], "intensity": [1, 1, 1]}], "shader": "gouraud"})");
    std::string text;
    for (int job = 0; job < jobs; ++job) {
        const std::string n = std::to_string(job);
        if (job % 3 == 0) {
            text += "{\"mesh\": \"knot.obj\", \"views\": " + std::to_string(1 + job % 4) +
                    ", \"size\": \"24x16\", \"output\": \"turn" + n + "-{view}.png\"}\n";
        } else if (job % 3 == 1) {
            text += "{\"scene\": \"scene.json\", \"lighting\": \"diffuse\", \"output\": \"s/scene" + n + ".png\"}\n";
        } else {
            text += "{\"mesh\": \"knot.obj\", \"elevation\": 30, \"size\": \"16x16\", \"samples\": 2, \"output\": \"e" + n +
                    ".exr\"}\n";
        }
    }
    return folder.write("jobs.jsonl", text);
}

}  // namespace

TEST_CASE("batch writes each image byte for byte as `phongrast render` does") {
    TemporaryFolder folder;
    generate_mesh(folder, "knot.obj", 60, 8);
    folder.write("jobs.jsonl", "{\"mesh\": \"knot.obj\", \"size\": \"40x30\", \"shader\": \"flat\"}\n"
                               "{\"mesh\": \"knot.obj\", \"views\": 3, \"size\": \"40x30\", \"output\": \"t/{view}.png\"}\n");
    const Run batch = run_phongrast(folder, "batch jobs.jsonl -o out");
    INFO(batch.err);
    REQUIRE(batch.status == 0);
    CHECK_THAT(batch.out, Catch::Contains("shard 0/1: 2 jobs: 2 rendered, 0 already done, 0 failed"));
    REQUIRE(run_phongrast(folder, "render knot.obj --size 40x30 --shader flat -q -o single.png").status == 0);
    const auto files = files_under(folder.file("out"));
    CHECK(files.size() == 4);
    CHECK(files.at("knot.png") == files_under(folder.file("")).at("single.png"));
    // Views of a turntable differ; its scale fits every view, so even view 0 is not the single framing.
    REQUIRE(run_phongrast(folder, "render knot.obj --size 40x30 -q -o phong.png").status == 0);
    CHECK(files.at("t/0.png") != files_under(folder.file("")).at("phong.png"));
    CHECK(files.at("t/1.png") != files.at("t/0.png"));
}

TEST_CASE("batch writes dataset files (aov_files) as `render --aov-files` does, a missing one makes the job run again") {
    TemporaryFolder folder;
    generate_mesh(folder, "knot.obj", 60, 8);
    folder.write("jobs.jsonl",
                 "{\"mesh\": \"knot.obj\", \"size\": \"40x30\", \"samples\": 2, \"aov_files\": \"mask,id,depth16\", "
                 "\"depth_scale\": 0.01}\n"
                 "{\"mesh\": \"knot.obj\", \"layout\": \"sphere\", \"views\": 3, \"size\": \"24x24\", \"output\": \"s/{view}.png\"}\n");
    const Run batch = run_phongrast(folder, "batch jobs.jsonl -o out --aov-files normal");
    INFO(batch.err);
    REQUIRE(batch.status == 0);
    REQUIRE(run_phongrast(folder, "render knot.obj --size 40x30 --samples 2 --aov-files mask,id,depth16 --depth-scale 0.01 "
                                  "-q -o single.png").status == 0);
    const auto files = files_under(folder.file("out"));
    const auto alone = files_under(folder.file(""));
    for (const char* name : {"knot.png", "knot.mask.png", "knot.id.png", "knot.depth.png"}) {
        INFO(name);
        const std::string single = std::string("single") + (std::string(name).substr(4));
        REQUIRE(files.count(name) == 1);
        CHECK(files.at(name) == alone.at(single));
    }
    CHECK(files.count("knot.normal.png") == 0);  // the line's own aov_files win over the command line's
    for (const char* name : {"s/0.normal.png", "s/1.normal.png", "s/2.normal.png", "s/2.png"}) CHECK(files.count(name) == 1);
    // A view whose dataset file is missing is not done: the job runs again.
    fs::remove(folder.file("out/knot.id.png"));
    const Run again = run_phongrast(folder, "batch jobs.jsonl -o out --aov-files normal");
    CHECK_THAT(again.out, Catch::Contains("2 jobs: 1 rendered, 1 already done"));
    CHECK(files_under(folder.file("out")).at("knot.id.png") == alone.at("single.id.png"));
    // Names that would collide, and bad values, stop the batch before it starts.
    folder.write("bad.jsonl", "{\"mesh\": \"knot.obj\", \"aov_files\": \"mask,hue\"}\n");
    CHECK_THAT(run_phongrast(folder, "batch bad.jsonl -o out2").err, Catch::Contains("bad.jsonl:1: /aov_files: aov-files: unknown 'hue'"));
    folder.write("clash.jsonl", "{\"mesh\": \"knot.obj\", \"aov_files\": \"mask\"}\n{\"mesh\": \"knot.obj\", \"output\": \"knot.mask.png\"}\n");
    const Run clash = run_phongrast(folder, "batch clash.jsonl -o out2");
    CHECK(clash.status == 2);
    CHECK_THAT(clash.err, Catch::Contains("clash.jsonl:2: /output: 'knot.mask.png' is also written by line 1"));
    CHECK_FALSE(fs::exists(folder.file("out2")));
}

TEST_CASE("a malformed manifest line stops the batch before anything is written, exit status 2") {
    TemporaryFolder folder;
    folder.write("jobs.jsonl", "{\"mesh\": \"a.obj\"}\n{\"mesh\": \"b.obj\", \"views\": \"four\"}\n");
    const Run run = run_phongrast(folder, "batch jobs.jsonl -o out");
    CHECK(run.status == 2);
    CHECK(run.err == "phongrast: error: jobs.jsonl:2: /views: expected a whole number from 1 to 100000, got the "
                     "string \"four\"\n");
    CHECK_FALSE(fs::exists(folder.file("out")));
    const Run missing = run_phongrast(folder, "batch nowhere.jsonl -o out");
    CHECK(missing.status == 2);
    CHECK_THAT(missing.err, Catch::Contains("nowhere.jsonl: manifest not found"));
    folder.write("good.jsonl", "{\"mesh\": \"a.obj\"}\n");
    const Run bad_shard = run_phongrast(folder, "batch good.jsonl -o out --shard 4/4");
    CHECK(bad_shard.status == 2);
    CHECK_THAT(bad_shard.err, Catch::Contains("--shard: expected I/N"));
}

TEST_CASE("a bad mesh fails its own job only, the log, stderr and --status name it, exit status 1") {
    TemporaryFolder folder;
    generate_mesh(folder, "knot.obj", 40, 6);
    folder.write("broken.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 0\n");
    folder.write("jobs.jsonl", "{\"mesh\": \"knot.obj\", \"size\": \"16x16\"}\n"
                               "{\"mesh\": \"broken.obj\", \"size\": \"16x16\"}\n"
                               "{\"mesh\": \"knot.obj\", \"size\": \"16x16\", \"output\": \"again.png\"}\n");
    const Run run = run_phongrast(folder, "batch jobs.jsonl -o out");
    CHECK(run.status == 1);
    CHECK_THAT(run.err, Catch::Contains("manifest line 2: failed: ") && Catch::Contains("broken.obj:4: face vertex index 0"));
    CHECK(fs::exists(folder.file("out/knot.png")));
    CHECK(fs::exists(folder.file("out/again.png")));
    CHECK_FALSE(fs::exists(folder.file("out/broken.png")));
    const std::vector<nlohmann::json> records = log_records(folder.file("out"));
    REQUIRE(records.size() == 3);
    CHECK(records[1]["job"] == 2);
    CHECK(records[1]["status"] == "failed");
    CHECK_THAT(records[1]["error"].get<std::string>(), Catch::Contains("broken.obj:4"));
    const Run status = run_phongrast(folder, "batch --status jobs.jsonl -o out");
    CHECK(status.status == 1);
    CHECK_THAT(status.out, Catch::Contains("3 jobs (3 images): 2 done, 1 failed, 0 missing") &&
                               Catch::Contains("failed line 2: failed: ") && Catch::Contains("broken.obj:4"));
}

TEST_CASE("a re-run skips the jobs whose images exist, --force renders them again") {
    TemporaryFolder folder;
    const std::string manifest = small_manifest(folder, 6);
    REQUIRE(run_phongrast(folder, "batch jobs.jsonl -o out -q").status == 0);
    const auto first_time = modified(folder.file("out/s/scene1.png"));
    fs::remove(folder.file("out/e2.exr"));
    const Run again = run_phongrast(folder, "batch jobs.jsonl -o out");
    REQUIRE(again.status == 0);
    CHECK_THAT(again.out, Catch::Contains("6 jobs: 1 rendered, 5 already done, 0 failed"));
    CHECK(modified(folder.file("out/s/scene1.png")) == first_time);
    CHECK(fs::exists(folder.file("out/e2.exr")));
    const Run forced = run_phongrast(folder, "batch jobs.jsonl -o out --force");
    CHECK_THAT(forced.out, Catch::Contains("6 jobs: 6 rendered, 0 already done"));
    CHECK(done_per_line(folder.file("out")) == std::map<int, int>{{1, 2}, {2, 2}, {3, 3}, {4, 2}, {5, 2}, {6, 2}});
}

TEST_CASE("a shard killed with SIGKILL mid-run and run again completes, without re-rendering or leftovers") {
    TemporaryFolder folder;
    generate_mesh(folder, "knot.obj", 240, 20);
    std::string text;
    for (int job = 1; job <= 16; ++job) {
        text += "{\"mesh\": \"knot.obj\", \"views\": 4, \"size\": \"256x256\", \"samples\": 3, \"output\": \"k" +
                std::to_string(job) + "-{view}.png\"}\n";
    }
    folder.write("jobs.jsonl", text);
    const std::string out = folder.file("out");
    const pid_t shard = start_batch(folder, {folder.file("jobs.jsonl"), "-o", out});
    // Kill it once a few jobs are logged, in the middle of the others.
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    while (log_records(out).size() < 3 && std::chrono::steady_clock::now() < give_up) {
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    REQUIRE(::kill(shard, SIGKILL) == 0);
    int status = 0;
    REQUIRE(::waitpid(shard, &status, 0) == shard);
    const std::vector<nlohmann::json> before = log_records(out);  // every line whole
    REQUIRE(before.size() >= 3);
    REQUIRE(before.size() < 16);
    // The worker died with the shard: nothing is written any more.
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
    const auto files_after_kill = files_under(out);
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
    CHECK(files_under(out) == files_after_kill);
    std::map<std::string, fs::file_time_type> finished;
    for (const nlohmann::json& record : before) {
        for (const std::string image : record["outputs"]) finished[image] = modified(out + "/" + image);
    }

    const Run resumed = run_phongrast(folder, "batch jobs.jsonl -o out");
    INFO(resumed.err);
    REQUIRE(resumed.status == 0);
    CHECK(temporary_files_under(out).empty());
    for (const auto& [image, time] : finished) CHECK(modified(out + "/" + image) == time);
    const std::vector<nlohmann::json> after = log_records(out);
    std::set<int> skipped;
    for (std::size_t i = before.size(); i < after.size(); ++i) {
        if (after[i]["status"] == "skipped") skipped.insert(after[i]["job"].get<int>());
    }
    for (const nlohmann::json& record : before) CHECK(skipped.count(record["job"].get<int>()) == 1);
    // And the images are those of an uninterrupted run.
    REQUIRE(run_phongrast(folder, "batch jobs.jsonl -o clean -q").status == 0);
    CHECK(files_under(out) == files_under(folder.file("clean")));
    CHECK(run_phongrast(folder, "batch --status jobs.jsonl -o out").status == 0);
}

TEST_CASE("the job timeout (--job-timeout) stops a runaway job, records it and goes on with the next") {
    TemporaryFolder folder;
    generate_mesh(folder, "knot.obj", 40, 6);
    // 100,000 copies of a triangle covering a 2048x2048 image: about 4e11 samples
    // to fill, a minute or more of rendering; the timeout ends it after one second.
    std::ofstream runaway(folder.file("runaway.obj"));
    runaway << "v -10 -10 0\nv 10 -10 0\nv 0 10 0\n";
    for (int i = 0; i < 100000; ++i) runaway << "f 1 2 3\n";
    runaway.close();
    folder.write("runaway.json", R"({"mesh": "runaway.obj", "camera": {"eye": [0, 0, 5], "lookat": [0, 0, 0],
        "focal": 1, "sensor": [1, 1]}, "image": {"height": 2048, "width": 2048}})");
    folder.write("jobs.jsonl", "{\"mesh\": \"knot.obj\", \"size\": \"16x16\"}\n{\"scene\": \"runaway.json\"}\n"
                               "{\"mesh\": \"knot.obj\", \"size\": \"16x16\", \"output\": \"after.png\"}\n");
    const auto start = std::chrono::steady_clock::now();
    const Run run = run_phongrast(folder, "batch jobs.jsonl -o out --job-timeout 1");
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    CHECK(run.status == 1);
    CHECK(seconds < 30.0);
    CHECK_THAT(run.err, Catch::Contains("manifest line 2: timeout: stopped after the job timeout of 1 s"));
    const std::vector<nlohmann::json> records = log_records(folder.file("out"));
    REQUIRE(records.size() == 3);
    CHECK(records[1]["status"] == "timeout");
    CHECK(records[1]["seconds"].get<double>() >= 1.0);
    CHECK(records[2]["status"] == "done");
    CHECK(fs::exists(folder.file("out/after.png")));
    CHECK_FALSE(fs::exists(folder.file("out/runaway.png")));
    CHECK(temporary_files_under(folder.file("out")).empty());
}

TEST_CASE("for several N, N shards into one folder render every job exactly once, as one process does") {
    TemporaryFolder folder;
    small_manifest(folder, 14);
    REQUIRE(run_phongrast(folder, "batch jobs.jsonl -o single -q").status == 0);
    const auto expected = files_under(folder.file("single"));
    CHECK(expected.size() == 20);  // 5 turntables of 1-4 views (1+4+3+2+1) + 9 single images
    for (const int count : {1, 2, 3, 5}) {
        INFO(count << " shards");
        const std::string out = "out" + std::to_string(count);
        for (int index = 0; index < count; ++index) {
            const Run run = run_phongrast(folder, "batch jobs.jsonl -q -o " + out + " --shard " +
                                                      std::to_string(index) + "/" + std::to_string(count));
            REQUIRE(run.status == 0);
        }
        std::map<int, int> expected_once;
        for (int line = 1; line <= 14; ++line) expected_once[line] = 1;
        CHECK(done_per_line(folder.file(out)) == expected_once);
        CHECK(files_under(folder.file(out)) == expected);
    }
}

TEST_CASE("render lanes (the default) and one lane (--threads 1) write the same files, jobs logged in manifest order") {
    // Small jobs (meshes and a scene file) render side by side on one thread
    // each; a 9-view turntable and a 600x600 image between them render alone.
    TemporaryFolder folder;
    small_manifest(folder, 0);
    std::string text;
    for (int job = 0; job < 24; ++job) {
        const std::string n = std::to_string(job);
        if (job == 5) {
            text += "{\"mesh\": \"knot.obj\", \"views\": 9, \"size\": \"20x20\", \"output\": \"nine/{view}.png\"}\n";
        } else if (job == 11) {
            text += "{\"mesh\": \"knot.obj\", \"size\": \"600x600\", \"output\": \"big.png\"}\n";
        } else if (job % 4 == 3) {
            text += "{\"scene\": \"scene.json\", \"output\": \"s" + n + ".png\"}\n";
        } else {
            text += "{\"mesh\": \"knot.obj\", \"elevation\": " + std::to_string(3 * job) +
                    ", \"size\": \"32x24\", \"output\": \"k" + n + ".png\"}\n";
        }
    }
    folder.write("lanes.jsonl", text);
    REQUIRE(run_phongrast(folder, "batch lanes.jsonl -q -o lanes").status == 0);
    REQUIRE(run_phongrast(folder, "batch lanes.jsonl -q -o one --threads 1").status == 0);
    const auto lanes = files_under(folder.file("lanes"));
    CHECK(lanes.size() == 23 + 9);
    CHECK(lanes == files_under(folder.file("one")));
    std::vector<int> order;
    for (const nlohmann::json& record : log_records(folder.file("lanes"))) {
        CHECK(record["status"] == "done");
        order.push_back(record["job"].get<int>());
    }
    std::vector<int> expected(24);
    for (int line = 1; line <= 24; ++line) expected[static_cast<std::size_t>(line - 1)] = line;
    CHECK(order == expected);
}

TEST_CASE("the shard comes from Slurm's or Kubernetes' variables") {
    TemporaryFolder folder;
    small_manifest(folder, 4);
    CHECK(run_phongrast(folder, "batch jobs.jsonl -q -o out",
                        "SLURM_ARRAY_TASK_ID=3 SLURM_ARRAY_TASK_MIN=2 SLURM_ARRAY_TASK_COUNT=2")
              .status == 0);
    CHECK(fs::exists(folder.file("out/.phongrast-batch/shard-1-of-2.jsonl")));
    CHECK(run_phongrast(folder, "batch jobs.jsonl -q -o out --shards 2", "JOB_COMPLETION_INDEX=0").status == 0);
    CHECK(fs::exists(folder.file("out/.phongrast-batch/shard-0-of-2.jsonl")));
    CHECK(run_phongrast(folder, "batch --status jobs.jsonl -o out").status == 0);
    const Run no_count = run_phongrast(folder, "batch jobs.jsonl -q -o out", "JOB_COMPLETION_INDEX=0");
    CHECK(no_count.status == 2);
    CHECK_THAT(no_count.err, Catch::Contains("give --shards N"));
}

TEST_CASE("the status summary (--status) counts done, failed and missing jobs without rendering") {
    TemporaryFolder folder;
    small_manifest(folder, 5);
    const Run before = run_phongrast(folder, "batch --status jobs.jsonl -o out");
    CHECK(before.status == 1);
    CHECK_THAT(before.out, Catch::Contains("5 jobs (8 images): 0 done, 0 failed, 5 missing") &&
                               Catch::Contains("missing lines: 1 2 3 4 5"));
    REQUIRE(run_phongrast(folder, "batch jobs.jsonl -q -o out --shard 0/2").status == 0);
    const Run half = run_phongrast(folder, "batch --status jobs.jsonl -o out");
    CHECK(half.status == 1);
    CHECK_THAT(half.out, Catch::Contains("0 failed") && !Catch::Contains("0 done") && !Catch::Contains("0 missing"));
}
