// Mesh loading: MB/s and triangles/s per format and size, phongrast's readers
// against the previous OBJ path (tinyobjloader after a line check) and, when
// built with them, Assimp (every format) and tinygltf (GLB). The files are
// generated spheres written by this program into $PHONGRAST_LOADING_DIR
// (default /tmp/phongrast-loading), 10k to $PHONGRAST_LOADING_MAX_TRIANGLES
// (default 1M; 8M for the full table) triangles. Medians come from Google
// Benchmark's repetitions; bench/loading_table.py turns the JSON into the
// table of docs/loading.md. $PHONGRAST_LOADING_EXTRA may name more files
// (':'-separated, any format) to measure the same way, e.g. the issue's
// 71 MB sphere; ../shared/assets/sphere*.obj are measured when present.
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "legacy_obj_reader.hpp"
#include "loading_meshes.hpp"
#include "phongrast/io/mesh_file.hpp"

#ifdef PHONGRAST_BENCH_WITH_ASSIMP
#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#endif
#ifdef PHONGRAST_BENCH_WITH_TINYGLTF
#include <tiny_gltf.h>
#endif

namespace {

using phongrast_bench::LoadingFile;

/// Each reader returns the triangles it read, so a reader that skipped the work would show.
using Reader = std::size_t (*)(const std::string& path);

std::size_t phongrast_reader(const std::string& path) { return phongrast::io::read_mesh(path).mesh.triangles.size(); }
std::size_t legacy_obj_reader(const std::string& path) { return phongrast_bench::legacy_read_obj(path).triangles.size(); }

#ifdef PHONGRAST_BENCH_WITH_ASSIMP
/// Assimp with what matches phongrast's work: triangulation, and for STL the welding.
std::size_t assimp_reader(const std::string& path) {
    Assimp::Importer importer;
    const bool stl = path.size() > 4 && path.compare(path.size() - 4, 4, ".stl") == 0;
    const aiScene* scene = importer.ReadFile(path, unsigned(aiProcess_Triangulate) | (stl ? unsigned(aiProcess_JoinIdenticalVertices) : 0u));
    if (scene == nullptr) throw std::runtime_error(path + ": Assimp: " + importer.GetErrorString());
    std::size_t triangles = 0;
    for (unsigned m = 0; m < scene->mNumMeshes; ++m) triangles += scene->mMeshes[m]->mNumFaces;
    return triangles;
}
#endif

#ifdef PHONGRAST_BENCH_WITH_TINYGLTF
/// tinygltf's parse of a GLB (JSON, buffers copied), before any accessor is read into a mesh.
std::size_t tinygltf_reader(const std::string& path) {
    tinygltf::TinyGLTF loader;
    tinygltf::Model model;
    std::string error;
    std::string warning;
    if (!loader.LoadBinaryFromFile(&model, &error, &warning, path)) throw std::runtime_error(path + ": tinygltf: " + error);
    const tinygltf::Accessor& indices = model.accessors.at(static_cast<std::size_t>(model.meshes.at(0).primitives.at(0).indices));
    return indices.count / 3;
}
#endif

void measure(benchmark::State& state, Reader reader, const LoadingFile& file) {
    for (auto _ : state) {
        const std::size_t triangles = reader(file.path);
        if (triangles != file.triangles) {
            state.SkipWithError("wrong triangle count");
            return;
        }
        benchmark::DoNotOptimize(triangles);
    }
    state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * file.bytes));
    state.counters["triangles_per_second"] =
        benchmark::Counter(static_cast<double>(file.triangles), benchmark::Counter::kIsIterationInvariantRate);
    state.counters["file_MB"] = static_cast<double>(file.bytes) / 1e6;
}

void add(const std::string& reader_name, Reader reader, const LoadingFile& file) {
    const std::string name = "load/" + file.format + "/" + std::to_string(file.triangles) + "/" + reader_name;
    benchmark::RegisterBenchmark(name.c_str(), [reader, file](benchmark::State& state) { measure(state, reader, file); })
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime()
        ->MinTime(0.2)
        ->Repetitions(5)
        ->ReportAggregatesOnly(true);
}

/// $PHONGRAST_LOADING_EXTRA's files, and the shared assets' spheres when present.
std::vector<std::string> extra_files() {
    std::vector<std::string> paths;
    const char* extra = std::getenv("PHONGRAST_LOADING_EXTRA");
    std::istringstream list(extra != nullptr ? extra : "");
    for (std::string path; std::getline(list, path, ':');) {
        if (!path.empty()) paths.push_back(path);
    }
    std::error_code missing;
    for (const auto& entry : std::filesystem::directory_iterator(PHONGRAST_SHARED_ASSETS_DIR, missing)) {
        const std::string name = entry.path().filename().string();
        if (name.rfind("sphere", 0) == 0 && entry.path().extension() == ".obj") paths.push_back(entry.path().string());
    }
    return paths;
}

}  // namespace

int main(int argc, char** argv) {
    const char* folder = std::getenv("PHONGRAST_LOADING_DIR");
    const char* largest = std::getenv("PHONGRAST_LOADING_MAX_TRIANGLES");
    const std::size_t max_triangles = largest != nullptr ? std::strtoull(largest, nullptr, 10) : 1000000;
    for (const std::size_t size : {10000u, 100000u, 1000000u, 8000000u}) {
        if (size > max_triangles) continue;
        const phongrast::Mesh mesh = phongrast_bench::loading_sphere(size);
        for (const LoadingFile& file : phongrast_bench::write_loading_files(
                 mesh, folder != nullptr ? folder : "/tmp/phongrast-loading", "sphere-" + std::to_string(size))) {
            add("phongrast", phongrast_reader, file);
            if (file.format == "obj") add("previous", legacy_obj_reader, file);
#ifdef PHONGRAST_BENCH_WITH_ASSIMP
            add("assimp", assimp_reader, file);
#endif
#ifdef PHONGRAST_BENCH_WITH_TINYGLTF
            if (file.format == "glb") add("tinygltf", tinygltf_reader, file);
#endif
        }
    }
    for (const std::string& path : extra_files()) {
        LoadingFile file;
        file.format = std::filesystem::path(path).filename().string();
        file.path = path;
        file.bytes = std::filesystem::file_size(path);
        file.triangles = phongrast::io::read_mesh(path).mesh.triangles.size();
        add("phongrast", phongrast_reader, file);
        if (std::filesystem::path(path).extension() == ".obj") add("previous", legacy_obj_reader, file);
#ifdef PHONGRAST_BENCH_WITH_ASSIMP
        add("assimp", assimp_reader, file);
#endif
    }
    benchmark::Initialize(&argc, argv);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
