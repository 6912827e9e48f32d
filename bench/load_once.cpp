// Reads each mesh file given K times (--repeat, default 5) with read_mesh and
// prints, per file, the median wall-clock time and the process's CPU time
// (user + system, all threads, from getrusage) per load. CPU time hardly
// changes when other programs share the machine, wall-clock time does: the
// two together say what an idle machine would see.
//   bench/load_once [--repeat K] FILE...
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include <sys/resource.h>

#include "phongrast/io/mesh_file.hpp"

namespace {

double process_cpu_seconds() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    const auto seconds = [](const timeval& t) { return double(t.tv_sec) + 1e-6 * double(t.tv_usec); };
    return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

}  // namespace

int main(int argc, char** argv) {
    int repeat = 5;
    std::vector<std::string> files;
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--repeat") == 0 && i + 1 < argc) {
            repeat = std::max(1, std::atoi(argv[++i]));
        } else {
            files.emplace_back(argv[i]);
        }
    }
    std::printf("| file | MB | triangles | wall ms (median of %d) | CPU ms per load | MB per CPU second |\n|---|---:|---:|---:|---:|---:|\n", repeat);
    for (const std::string& file : files) {
        std::vector<double> wall;
        std::size_t triangles = 0;
        const double cpu_start = process_cpu_seconds();
        for (int r = 0; r < repeat; ++r) {
            const auto start = std::chrono::steady_clock::now();
            triangles = phongrast::io::read_mesh(file).mesh.triangles.size();
            wall.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        }
        const double cpu = (process_cpu_seconds() - cpu_start) / repeat;
        std::sort(wall.begin(), wall.end());
        const double megabytes = double(std::filesystem::file_size(file)) / 1e6;
        std::printf("| %s | %.1f | %zu | %.1f | %.1f | %.0f |\n", std::filesystem::path(file).filename().c_str(),
                    megabytes, triangles, 1e3 * wall[wall.size() / 2], 1e3 * cpu, megabytes / cpu);
    }
    return 0;
}
