#include "batch_worker.hpp"

#include <algorithm>
#include <cerrno>
#include <condition_variable>
#include <deque>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <thread>

#if defined(__GLIBC__)
#include <malloc.h>
#endif
#include <nlohmann/json.hpp>
#include <sched.h>
#include <unistd.h>

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
    /// Null when loading failed. Lent by JobScenesMemo: a lane changes only
    /// the camera, lights and options (which the memo puts back).
    std::shared_ptr<JobScenes> scenes;
    std::string error;
};

/// One image to write (`image`, or `bytes` for an 8-bit PNG), or (neither)
/// the end of job `position`.
struct WriteItem {
    std::size_t position = 0;
    std::optional<Image> image;
    std::optional<io::Rgb8Image> bytes;
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

    bool is_image() const { return image.has_value() || bytes.has_value(); }
};

/// Image memory the writer has finished with, for the lanes' next copies:
/// a 256x256 frame is 786 KB of floats (196 KB as 8-bit values), and a
/// fresh allocation of that size comes back from the kernel as fresh pages
/// (a page fault each) every image.
class SpareImages {
public:
    /// `result` converted to an 8-bit PNG's values (io::convert_to_8_bit) in kept memory when there is some.
    io::Rgb8Image bytes_of(const Image& result) {
        io::Rgb8Image bytes;
        {
            std::lock_guard<std::mutex> lock(mutex_);
            if (!spare_bytes_.empty()) {
                bytes = std::move(spare_bytes_.back());
                spare_bytes_.pop_back();
            }
        }
        io::convert_to_8_bit(result, bytes);
        return bytes;
    }

    void give_back(io::Rgb8Image&& bytes) {
        if (bytes.values.capacity() > 3 * kPixelsMax) return;
        std::lock_guard<std::mutex> lock(mutex_);
        if (spare_bytes_.size() < kKept) spare_bytes_.push_back(std::move(bytes));
    }

    /// `result` copied into kept memory when there is some.
    Image copy_of(const Image& result) {
        Image image;
        {
            std::lock_guard<std::mutex> lock(mutex_);
            if (!spare_.empty()) {
                image = std::move(spare_.back());
                spare_.pop_back();
            }
        }
        image.rows = result.rows;
        image.columns = result.columns;
        image.pixels.assign(result.pixels.begin(), result.pixels.end());
        return image;
    }

    /// Keeps `image`'s memory: a few images' worth (those in flight), of
    /// small frames only (a large frame's copy costs far more than its pages).
    void give_back(Image&& image) {
        if (image.pixels.capacity() > kPixelsMax) return;
        std::lock_guard<std::mutex> lock(mutex_);
        if (spare_.size() < kKept) spare_.push_back(std::move(image));
    }

private:
    static constexpr std::size_t kKept = 8;
    static constexpr std::size_t kPixelsMax = std::size_t{512} * 512;
    std::mutex mutex_;
    std::vector<Image> spare_;
    std::vector<io::Rgb8Image> spare_bytes_;
};

/// Images on their way from the render lanes to the writer, which takes them
/// job by job in the list's order (so the supervisor hears of jobs ending in
/// order, as it expects): the job being written, then the next. A lane
/// waits while `capacity` images are waiting, except for the job being
/// written (up to `capacity` of its own), which can therefore always go on.
class OrderedWrites {
public:
    OrderedWrites(std::size_t first, std::size_t capacity) : current_(first), capacity_(capacity) {}

    void push(WriteItem item) {
        std::unique_lock<std::mutex> lock(mutex_);
        changed_.wait(lock, [&] {
            return items_.size() < capacity_ || (item.position == current_ && waiting_for(current_) < capacity_);
        });
        items_.push_back(std::move(item));
        changed_.notify_all();
    }

    /// The next image (or end) of the job being written; after its end, the next job is.
    WriteItem pop() {
        std::unique_lock<std::mutex> lock(mutex_);
        std::deque<WriteItem>::iterator found;
        changed_.wait(lock, [&] {
            found = std::find_if(items_.begin(), items_.end(), [&](const WriteItem& i) { return i.position == current_; });
            return found != items_.end();
        });
        WriteItem item = std::move(*found);
        items_.erase(found);
        if (!item.is_image()) ++current_;
        changed_.notify_all();
        return item;
    }

private:
    std::size_t waiting_for(std::size_t position) const {
        return static_cast<std::size_t>(std::count_if(items_.begin(), items_.end(),
                                                      [&](const WriteItem& i) { return i.position == position; }));
    }

    std::mutex mutex_;
    std::condition_variable changed_;
    std::deque<WriteItem> items_;
    std::size_t current_;
    std::size_t capacity_;
};

/// Which lanes may render now. A small job (lane_sized()) renders on one
/// thread beside the other lanes' small jobs; any other job renders alone,
/// with every thread, as a single lane would: it waits until every earlier
/// job has been rendered and no other lane is rendering, and later jobs wait
/// for it. (Waiting for the earlier jobs first means the job rendering alone
/// is the one being written, so its images are never held up behind a full
/// queue: no lane can wait for another in a circle.)
class RenderGate {
public:
    explicit RenderGate(std::size_t first) : rendered_below_(first) {}

    /// Blocks until job `position` may render a frame; `alone`: a job that renders alone.
    void enter(std::size_t position, bool alone) {
        std::unique_lock<std::mutex> lock(mutex_);
        if (alone) {
            waiting_alone_.insert(position);
            changed_.wait(lock, [&] { return rendered_below_ == position && rendering_ == 0; });
        } else {
            changed_.wait(lock, [&] { return waiting_alone_.empty() || *waiting_alone_.begin() > position; });
        }
        ++rendering_;
    }

    void leave() {
        std::lock_guard<std::mutex> lock(mutex_);
        --rendering_;
        changed_.notify_all();
    }

    /// Job `position` has rendered every frame (or failed).
    void done(std::size_t position) {
        std::lock_guard<std::mutex> lock(mutex_);
        waiting_alone_.erase(position);
        rendered_.insert(position);
        while (!rendered_.empty() && *rendered_.begin() == rendered_below_) {
            rendered_.erase(rendered_.begin());
            ++rendered_below_;
        }
        changed_.notify_all();
    }

private:
    std::mutex mutex_;
    std::condition_variable changed_;
    std::size_t rendered_below_;         ///< every job before this one has been rendered
    std::set<std::size_t> rendered_;     ///< jobs rendered at or after rendered_below_
    std::set<std::size_t> waiting_alone_;  ///< jobs rendering alone, waiting or under way
    int rendering_ = 0;                  ///< frames being rendered now
};

/// A job small enough to render on one thread beside other lanes: few views
/// of small frames, which a renderer's threads share out poorly (each stage
/// of a 256x256 frame is a fraction of a millisecond, and the threads wait
/// for each other between stages) and whose memory per lane is small (the
/// limits of render()'s kept memory, src/renderer.cpp).
bool lane_sized(const JobScenes& scenes) {
    constexpr std::size_t kViewsMax = 8;
    constexpr std::size_t kSamplesMax = std::size_t{512} * 512;
    constexpr std::size_t kTrianglesMax = std::size_t{1} << 18;
    const Scene& scene = scenes.prepared.scene;
    const auto per_axis = static_cast<std::size_t>(std::max(1, scenes.prepared.options.samples_per_axis));
    const std::size_t samples = static_cast<std::size_t>(std::max(0, scene.image.rows)) *
                                static_cast<std::size_t>(std::max(0, scene.image.columns)) * per_axis * per_axis;
    std::size_t triangles = scene.mesh.triangles.size();
    for (const SceneObject& object : scene.objects) triangles += object.mesh ? object.mesh->triangles.size() : 0;
    return scenes.cameras.size() <= kViewsMax && samples <= kSamplesMax && triangles <= kTrianglesMax;
}

/// Loaded jobs from the loader threads, handed to the lanes in the list's
/// order. A loader waits while its job is `capacity` or more ahead of the
/// next one to hand out (which another loader, never waiting, is loading).
class OrderedLoads {
public:
    OrderedLoads(std::size_t first, std::size_t capacity) : next_(first), capacity_(capacity) {}

    void push(std::size_t position, LoadedJob job) {
        std::unique_lock<std::mutex> lock(mutex_);
        changed_.wait(lock, [&] { return position < next_ + capacity_; });
        ready_.emplace(position, std::move(job));
        changed_.notify_all();
    }

    LoadedJob pop() {
        std::unique_lock<std::mutex> lock(mutex_);
        changed_.wait(lock, [&] { return ready_.count(next_) != 0; });
        const auto found = ready_.find(next_);
        LoadedJob job = std::move(found->second);
        ready_.erase(found);
        ++next_;
        changed_.notify_all();
        return job;
    }

private:
    std::mutex mutex_;
    std::condition_variable changed_;
    std::map<std::size_t, LoadedJob> ready_;
    std::size_t next_;
    std::size_t capacity_;
};

/// Loads jobs[first + offset], jobs[first + offset + stride], ...: one of
/// `stride` loaders. A batch's first jobs each name a mesh not parsed yet,
/// and one loader's parses then set the pace of every lane.
void load_ahead(const std::vector<const BatchJob*>& jobs, std::size_t first, std::size_t offset, std::size_t stride,
                int threads, JobScenesMemo& scenes, OrderedLoads& loaded) {
    for (std::size_t position = first + offset; position < jobs.size(); position += stride) {
        LoadedJob job;
        try {
            job.scenes = scenes.load(*jobs[position], threads);
        } catch (const std::exception& error) {
            job.error = error.what();
        }
        loaded.push(position, std::move(job));
    }
}

void write_images(std::size_t count, OrderedWrites& pending, Reporter& reporter,
                  const io::ImageWriteOptions& image_options, SpareImages& spares) {
    std::string error;  // of the job being written
    for (std::size_t finished = 0; finished < count;) {
        WriteItem item = pending.pop();
        if (item.is_image()) {
            const auto give_back = [&] {
                if (item.image) spares.give_back(std::move(*item.image));
                if (item.bytes) spares.give_back(std::move(*item.bytes));
            };
            if (!error.empty()) {  // the job already failed: its other views are moot
                give_back();
                continue;
            }
            try {
                const fs::path folder = fs::path(item.path).parent_path();
                if (!folder.empty()) fs::create_directories(folder);
                if (item.dataset_files.any()) {
                    item.dataset_options.png_compression = image_options.png_compression;
                    io::write_dataset_files(item.planes, item.object_first_triangles, item.path, item.dataset_files,
                                            item.dataset_options);
                }
                if (item.bytes) {
                    io::write_png_8_bit(*item.bytes, item.path, image_options.png_compression);
                } else {
                    io::write_image(*item.image, item.path, image_options);
                }
            } catch (const std::exception& failure) {
                error = failure.what();
            }
            give_back();
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

/// A lane's renderers: its own for small jobs (which keeps small frames'
/// memory only), and the one every lane shares for the jobs that render
/// alone (one at a time, RenderGate), so that large frames' memory is held once.
struct LaneRenderers {
    Renderer& alone;
    Renderer lane;
};

/// Whether `path` is written as an 8-bit PNG (then the lane hands the writer
/// io::convert_to_8_bit's bytes, not the float image).
bool written_as_8_bit_png(const std::string& path, const io::ImageWriteOptions& options) {
    if (options.png_bit_depth != 8) return false;
    try {
        return io::image_format_for(path) == io::ImageFormat::png;
    } catch (const std::exception&) {
        return false;  // the writer's write_image reports it
    }
}

/// Renders every view of one loaded job and queues its images, then its end.
/// `lanes`: how many render lanes the worker runs (more than one: a small
/// job renders on one thread, RenderGate).
void render_job(LaneRenderers& renderers, std::size_t position, const BatchJob& job, LoadedJob& loaded,
                const std::string& output_folder, OrderedWrites& pending, RenderGate& gate, int lanes,
                SpareImages& spares, const io::ImageWriteOptions& image_options) {
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
            const bool alone = lanes == 1 || !lane_sized(scenes);
            if (!alone) scenes.prepared.options.threads = 1;  // the other lanes use the other cores
            Renderer& renderer = alone ? renderers.alone : renderers.lane;
            for (std::size_t view = 0; view < scenes.cameras.size(); ++view) {
                scenes.prepared.scene.camera = scenes.cameras[view];
                scenes.prepared.scene.lights = scenes.lights[view];
                WriteItem image;
                image.path = (fs::path(output_folder) / job.outputs[view]).string();
                const bool as_bytes = written_as_8_bit_png(image.path, image_options);
                {
                    gate.enter(position, alone);
                    struct Leave {
                        RenderGate& gate;
                        ~Leave() { gate.leave(); }
                    } leave{gate};  // before the push, which may wait for another lane's job
                    renderer.set_options(scenes.prepared.options);  // inside: the alone renderer is shared
                    const RenderResult& result = renderer.render(scenes.prepared.scene);
                    end.render_seconds += result.stats.seconds;
                    // The renderer's image is overwritten by its next frame: converted
                    // (or copied) now. Converted here, the writer thread gets a quarter
                    // of the bytes, and nobody copies the floats.
                    if (as_bytes) {
                        image.bytes = spares.bytes_of(result.image);
                    } else {
                        image.image = spares.copy_of(result.image);
                    }
                    if (job.dataset_files.any()) image.planes = result.aovs;
                }
                image.position = position;
                if (job.dataset_files.any()) {
                    image.dataset_files = job.dataset_files;
                    image.dataset_options = job.dataset_options;
                    image.object_first_triangles = object_first_triangles;
                }
                pending.push(std::move(image));
            }
        } catch (const std::exception& error) {
            end.error = error.what();
        }
    }
    gate.done(position);
    pending.push(std::move(end));
}

/// Lets glibc's malloc keep the memory the worker frees rather than hand it
/// back to the kernel: by default each thread's heap gives back its free top
/// past 128 KiB, and blocks past 128 KiB (until the threshold adapts) are
/// mapped and unmapped on their own, so memory freed by one mesh's parse
/// came back as fresh pages (a page fault each, about 5 us on this project's
/// virtual machine) for the next. Up to 64 MiB free per heap is kept and
/// blocks up to 32 MiB come from the heaps: on the 1,000-thumbnail
/// benchmark (100 meshes parsed) 24,800 page faults instead of 33,500 and
/// 15-24% less CPU in the loader threads, the largest process no larger
/// (111 MB). The worker process only; the pictures do not change.
void keep_freed_memory() {
#if defined(__GLIBC__)
    ::mallopt(M_MMAP_THRESHOLD, 32 << 20);
    ::mallopt(M_TRIM_THRESHOLD, 64 << 20);
#endif
}

/// Render lanes for `threads` (0: every core this process may run on, up to 4).
int lane_count(int threads) {
    if (threads != 0) return 1;
    cpu_set_t cpus;
    CPU_ZERO(&cpus);
    const int cores = ::sched_getaffinity(0, sizeof cpus, &cpus) == 0 ? CPU_COUNT(&cpus) : 1;
    return std::clamp(cores, 1, 4);
}

}  // namespace

void run_worker(const std::vector<const BatchJob*>& jobs, std::size_t first, const std::string& output_folder,
                int threads, const io::ImageWriteOptions& image_options, int report_fd, bool one_lane) {
    Reporter reporter(report_fd);
    keep_freed_memory();
    const int lanes = one_lane ? 1 : lane_count(threads);
    // One loader per lane, up to 2 (one with a single lane, as before the lanes).
    const std::size_t loaders = lanes > 1 ? 2 : 1;
    MeshFileCache meshes;  // every mesh parsed once per shard, while memory allows
    JobScenesMemo scenes(meshes);  // and each job's scenes made once (before `loaded`, whose jobs it lent)
    OrderedLoads loaded(first, static_cast<std::size_t>(std::max(2, lanes)));
    OrderedWrites pending(first, 4);
    RenderGate gate(first);
    SpareImages spares;
    std::vector<std::thread> loader_threads;
    for (std::size_t offset = 0; offset < loaders; ++offset) {
        loader_threads.emplace_back([&, offset] { load_ahead(jobs, first, offset, loaders, threads, scenes, loaded); });
    }
    std::thread writer([&] { write_images(jobs.size() - first, pending, reporter, image_options, spares); });
    std::mutex taking;  // jobs are taken, reported started and popped in order
    std::size_t next = first;
    Renderer alone;
    const auto lane = [&] {
        LaneRenderers renderers{alone, Renderer()};
        for (;;) {
            std::size_t position = 0;
            LoadedJob job;
            {
                std::lock_guard<std::mutex> lock(taking);
                if (next >= jobs.size()) return;
                position = next++;
                reporter.send({{"start", position}});
                job = loaded.pop();
            }
            render_job(renderers, position, *jobs[position], job, output_folder, pending, gate, lanes, spares,
                       image_options);
        }
    };
    std::vector<std::thread> more_lanes;
    for (int i = 1; i < lanes; ++i) more_lanes.emplace_back(lane);
    lane();
    for (std::thread& other : more_lanes) other.join();
    for (std::thread& loader : loader_threads) loader.join();
    writer.join();
}

}  // namespace phongrast::cli
