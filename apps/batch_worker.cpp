#include "batch_worker.hpp"

#include <cerrno>
#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

#include <nlohmann/json.hpp>
#include <unistd.h>

#include "batch_queue.hpp"
#include "batch_views.hpp"
#include "phongrast/io/camera_record.hpp"
#include "phongrast/io/dataset_files.hpp"
#include "phongrast/io/image_file.hpp"
#include "phongrast/io/text_file.hpp"

namespace phongrast::cli {
namespace {

namespace fs = std::filesystem;

/// Whole lines to the supervisor; the renderer and writer threads both report.
class Reporter {
public:
    explicit Reporter(int descriptor) : descriptor_(descriptor) {}

    void send(const nlohmann::json& message) {
        const std::string line = message.dump() + "\n";
        std::lock_guard<std::mutex> lock(mutex_);
        std::size_t sent = 0;
        while (sent < line.size()) {
            const ssize_t written = ::write(descriptor_, line.data() + sent, line.size() - sent);
            if (written < 0 && errno == EINTR) continue;
            if (written <= 0) _exit(3);  // the supervisor is gone: nobody would record the work
            sent += static_cast<std::size_t>(written);
        }
    }

private:
    int descriptor_;
    std::mutex mutex_;
};

struct LoadedJob {
    std::unique_ptr<JobScenes> scenes;  ///< null when loading failed
    std::string error;
};

/// One image to write, or (image empty) the end of job `position`.
struct WriteItem {
    std::size_t position = 0;
    std::optional<Image> image;
    std::string path;
    /// The view's dataset files (BatchJob::dataset_files), written before the image.
    io::DatasetFiles dataset_files;
    io::DatasetFileOptions dataset_options;
    AovPlanes planes;
    std::vector<std::size_t> object_first_triangles;
    std::string error;            ///< end of job: why it failed, if it did before writing
    double render_seconds = 0.0;  ///< end of job: its views' render time
    /// End of job: the job's own files (path, text), written once every view's files are.
    std::vector<std::pair<std::string, std::string>> job_files;
};

void load_ahead(const std::vector<const BatchJob*>& jobs, std::size_t first, int threads,
                BoundedQueue<LoadedJob>& loaded) {
    MeshFileCache meshes;  // every mesh parsed once per shard, while memory allows
    for (std::size_t position = first; position < jobs.size(); ++position) {
        LoadedJob job;
        try {
            job.scenes = std::make_unique<JobScenes>(load_job(*jobs[position], threads, &meshes));
        } catch (const std::exception& error) {
            job.error = error.what();
        }
        loaded.push(std::move(job));
    }
}

void write_images(std::size_t count, BoundedQueue<WriteItem>& pending, Reporter& reporter,
                  const io::ImageWriteOptions& image_options) {
    std::string error;  // of the job being written
    for (std::size_t finished = 0; finished < count;) {
        WriteItem item = pending.pop();
        if (item.image) {
            if (!error.empty()) continue;  // the job already failed: its other views are moot
            try {
                const fs::path folder = fs::path(item.path).parent_path();
                if (!folder.empty()) fs::create_directories(folder);
                if (item.dataset_files.any()) {
                    item.dataset_options.png_compression = image_options.png_compression;
                    io::write_dataset_files(item.planes, item.object_first_triangles, item.path, item.dataset_files,
                                            item.dataset_options);
                }
                io::write_image(*item.image, item.path, image_options);
            } catch (const std::exception& failure) {
                error = failure.what();
            }
            continue;
        }
        if (error.empty()) error = item.error;
        if (error.empty()) {
            try {
                for (const auto& [path, text] : item.job_files) {
                    const fs::path folder = fs::path(path).parent_path();
                    if (!folder.empty()) fs::create_directories(folder);
                    io::write_text_file(path, text);
                }
            } catch (const std::exception& failure) {
                error = failure.what();
            }
        }
        nlohmann::json message = {{"finished", item.position},
                                  {"status", error.empty() ? "done" : "failed"},
                                  {"render_seconds", item.render_seconds}};
        if (!error.empty()) message["error"] = error;
        reporter.send(message);
        error.clear();
        ++finished;
    }
}

/// The job's camera file and transforms.json (BatchJob::files_of_job), one
/// record per view. Computed before rendering: a camera the layout cannot
/// hold (transforms.json: orthographic, skew) fails the job before any view.
/// (Sets the scene's camera to each view's in turn: the render sets it again.)
std::vector<std::pair<std::string, std::string>> camera_files(const BatchJob& job, JobScenes& scenes,
                                                              const std::string& output_folder) {
    std::vector<std::pair<std::string, std::string>> files;
    const auto records_for = [&](const std::string& file) {
        Scene& scene = scenes.prepared.scene;  // not a copy: it holds the mesh
        std::vector<io::CameraRecord> records;
        for (std::size_t view = 0; view < scenes.cameras.size(); ++view) {
            scene.camera = scenes.cameras[view];
            records.push_back(io::camera_record(scene, (fs::path(output_folder) / job.outputs[view]).string(), file));
        }
        return records;
    };
    if (!job.camera_file.empty()) {
        const std::string path = (fs::path(output_folder) / job.camera_file).string();
        files.emplace_back(path, io::camera_records_json(records_for(path)));
    }
    if (!job.transforms_file.empty()) {
        const std::string path = (fs::path(output_folder) / job.transforms_file).string();
        files.emplace_back(path, io::transforms_json(records_for(path)));
    }
    return files;
}

/// Renders every view of one loaded job and queues its images, then its end.
void render_job(Renderer& renderer, std::size_t position, const BatchJob& job, LoadedJob& loaded,
                const std::string& output_folder, BoundedQueue<WriteItem>& pending) {
    WriteItem end;
    end.position = position;
    end.error = loaded.error;
    if (loaded.scenes) {
        JobScenes& scenes = *loaded.scenes;
        try {
            const std::vector<std::size_t> object_first_triangles = io::object_first_triangles(scenes.prepared.scene);
            if (job.dataset_files.any()) {
                io::check_dataset_files(job.dataset_files, job.dataset_options, scenes.prepared.scene);
                job.dataset_files.add_planes_to(scenes.prepared.options.aovs);
            }
            end.job_files = camera_files(job, scenes, output_folder);
            renderer.set_options(scenes.prepared.options);
            for (std::size_t view = 0; view < scenes.cameras.size(); ++view) {
                scenes.prepared.scene.camera = scenes.cameras[view];
                scenes.prepared.scene.lights = scenes.lights[view];
                const RenderResult& result = renderer.render(scenes.prepared.scene);
                end.render_seconds += result.stats.seconds;
                WriteItem image;
                image.position = position;
                image.image = result.image;
                image.path = (fs::path(output_folder) / job.outputs[view]).string();
                if (job.dataset_files.any()) {
                    image.dataset_files = job.dataset_files;
                    image.dataset_options = job.dataset_options;
                    image.planes = result.aovs;
                    image.object_first_triangles = object_first_triangles;
                }
                pending.push(std::move(image));
            }
        } catch (const std::exception& error) {
            end.error = error.what();
        }
    }
    pending.push(std::move(end));
}

}  // namespace

void run_worker(const std::vector<const BatchJob*>& jobs, std::size_t first, const std::string& output_folder,
                int threads, const io::ImageWriteOptions& image_options, int report_fd) {
    Reporter reporter(report_fd);
    BoundedQueue<LoadedJob> loaded(2);
    BoundedQueue<WriteItem> pending(4);
    std::thread loader([&] { load_ahead(jobs, first, threads, loaded); });
    std::thread writer([&] { write_images(jobs.size() - first, pending, reporter, image_options); });
    Renderer renderer;
    for (std::size_t position = first; position < jobs.size(); ++position) {
        reporter.send({{"start", position}});
        LoadedJob job = loaded.pop();
        render_job(renderer, position, *jobs[position], job, output_folder, pending);
    }
    loader.join();
    writer.join();
}

}  // namespace phongrast::cli
