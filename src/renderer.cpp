// The public entry points: Renderer (a render pass's memory and a thread
// arena per thread count, kept from frame to frame), render() (the same
// memory kept per thread from call to call, for small frames) and
// render_object().
#include <algorithm>
#include <chrono>
#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

#include <tbb/info.h>
#include <tbb/task_arena.h>

#include "aov_pass.hpp"
#include "mesh_order.hpp"
#include "phongrast/render.hpp"
#include "pipeline.hpp"
#include "progress_monitor.hpp"
#include "resolve.hpp"
#include "scene_assembly.hpp"
#include "validation.hpp"

namespace phongrast {
namespace detail {

/// A Renderer's state: its options, its thread arenas and the memory every frame works in.
struct RendererState final : PassRenderer {
    RenderOptions options;
    std::vector<std::pair<int, std::unique_ptr<tbb::task_arena>>> arenas;
    RenderResult result;
    ResolveImages resolve_images;
    FrameMemory<float> single;
    FrameMemory<double> twice;
    AovSamples aov_samples;  ///< one pass's extra outputs per sample, before their resolve into result.aovs
    SceneAssembly assembly;  ///< a version-2 scene as one render mesh, kept for the next frame
    MeshOrder mesh_order;    ///< mesh order hook: a large mesh's cache-friendly copy and its permutation
    // During render():
    const Scene* scene = nullptr;          ///< the scene being rendered (assembled, for a version-2 scene)
    const AssembledScene* assembled = nullptr;  ///< what assembly made of it, or null (version 1)
    ProgressMonitor* progress = nullptr;   ///< its progress reports
    AovRequest aov_planes;                 ///< the planes each pass fills (none unless asked for)
    int passes = 1, passes_done = 0;       ///< render passes of this frame (rotated grid: one per sample)

    /// One arena per thread count asked for, kept: switching thread counts between frames allocates nothing either.
    tbb::task_arena& arena_for(int asked) {
        // More threads than the machine runs at once would only make oneTBB
        // print a warning and use fewer: clamp quietly (the picture does not
        // depend on the count).
        const int threads = std::min(asked, tbb::info::default_concurrency());
        for (auto& [count, arena] : arenas) {
            if (count == threads) return *arena;
        }
        constexpr int kAllCores = tbb::task_arena::automatic;  // a copy: no reference to TBB's static member
        arenas.emplace_back(threads, std::make_unique<tbb::task_arena>(threads > 0 ? threads : kAllCores));
        return *arenas.back().second;
    }

    void render_pass(int rows, int columns, glm::dvec2 sample_offset, RenderStats& stats, Image& image) override {
        progress->set_pass(passes_done++, passes);
        const PassOutput out{image, aov_planes, aov_samples, mesh_order.original_triangles(),
                             mesh_order.caller_vertices()};
        if (options.precision == Precision::double_float) {
            detail::render_pass(*scene, assembled, options, rows, columns, sample_offset, twice, stats, out,
                                *progress);
        } else {
            detail::render_pass(*scene, assembled, options, rows, columns, sample_offset, single, stats, out,
                                *progress);
        }
        // A pass has samples_per_axis samples per pixel axis (ordered grid) or one (rotated grid, no supersampling).
        if (aov_planes.any()) resolve_aovs(aov_samples, rows / scene->image.rows, aov_planes, result.aovs);
    }

    /// `one_off`: render() (the reordering is not kept), not a Renderer.
    void render(const Scene& requested, bool one_off = false) {
        const auto start = std::chrono::steady_clock::now();
        // A version-1 scene goes as it is; a version-2 one as the mesh assembly makes of it.
        assembled = needs_assembly(requested) ? &assembly.assemble(requested) : nullptr;
        const Scene& rendered = assembled != nullptr ? assembled->scene : requested;
        validate_render_request(rendered, options);
        ProgressMonitor monitor(options.progress);
        const int factor = options.samples_per_axis;
        progress = &monitor;
        aov_planes = options.aovs.any() ? sample_planes_for(options.aovs, factor) : AovRequest{};
        passes = factor > 1 && options.sample_pattern == SamplePattern::rotated_grid ? factor * factor : 1;
        passes_done = 0;
        reset_aov_planes(rendered.image.rows, rendered.image.columns, aov_planes, result.aovs);
        result.stats = RenderStats{};
        result.stats.triangles_in = rendered.mesh.triangles.size();
        arena_for(options.threads).execute([&] {
            // Mesh order hook: from here on the pipeline sees the mesh in a cache-friendly order
            // (inside the arena: the copy is made with the threads the options ask for).
            // An assembled (version-2) scene is drawn in assembly order: its per-triangle
            // surfaces are indexed by that order, which the reordering does not permute.
            mesh_order.reordered = false;
            const Scene& drawn =
                assembled != nullptr ? rendered
                                    : scene_in_render_order(rendered, options, one_off, mesh_order,
                                                            monitor.poll_function());
            scene = &drawn;
            render_and_resolve(drawn, options, *this, resolve_images, result);
        });
        scene = nullptr;
        assembled = nullptr;
        progress = nullptr;
        // After the passes: a rotated grid's resolve rebuilds the statistics from its passes'.
        result.stats.empty_scene = result.stats.triangles_in == 0;
        if (aov_planes.any()) finish_aovs(options.aovs, factor * factor, result.aovs);
        monitor.finish();
        result.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
};

}  // namespace detail

Renderer::Renderer(const RenderOptions& options) : state_(std::make_unique<detail::RendererState>()) {
    state_->options = options;
}
Renderer::~Renderer() = default;
Renderer::Renderer(Renderer&&) noexcept = default;
Renderer& Renderer::operator=(Renderer&&) noexcept = default;

// A moved-from Renderer has no state: it works again as a new Renderer()
// (exact options) would, rather than dereferencing nothing.
detail::RendererState& Renderer::state() {
    if (!state_) {
        state_ = std::make_unique<detail::RendererState>();
        state_->options = RenderOptions::exact();
    }
    return *state_;
}

const RenderOptions& Renderer::options() const {
    static const RenderOptions moved_from = RenderOptions::exact();
    return state_ ? state_->options : moved_from;
}
void Renderer::set_options(const RenderOptions& options) { state().options = options; }

const RenderResult& Renderer::render(const Scene& scene) {
    detail::RendererState& current = state();
    current.render(scene);
    return current.result;
}

void validate_render(const Scene& scene, const RenderOptions& options) {
    if (detail::needs_assembly(scene)) {
        detail::AssembledScene assembled;
        detail::NormalsScratch scratch;
        detail::assemble_scene(scene, assembled, scratch);
        detail::validate_render_request(assembled.scene, options);
    } else {
        detail::validate_render_request(scene, options);
    }
    make_camera_frame(scene.camera, scene.image.rows, scene.image.columns);
}

namespace {

/// render()'s memory on this thread, kept for its next call: a fresh
/// RendererState faults in its buffers page by page, which costs a small
/// frame several times its drawing (docs/startup.md, "One-off calls").
/// Only the memory is reused: what a Renderer remembers about the previous
/// scene (the mesh order, the assembly) is forgotten before every call, so
/// each call computes what a fresh state would, and draws the same picture.
struct OneOffMemory {
    std::unique_ptr<detail::RendererState> state;
    bool busy = false;  ///< a call is under way (render() from a progress callback gets fresh memory)
};

thread_local OneOffMemory t_one_off;

/// Frames up to this size keep their memory for the thread's next call (a
/// few tens of MB at most: tests/test_renderer.cpp); larger ones release it
/// as they return, as every render() did before (a Renderer keeps any size).
constexpr std::size_t kKeptTrianglesMax = std::size_t{1} << 18;
constexpr std::size_t kKeptSamplesMax = std::size_t{2048} * 2048;

bool keeps_memory(const Scene& scene, const RenderOptions& options) {
    const auto samples = static_cast<std::size_t>(std::max(scene.image.rows, 0)) *
                         static_cast<std::size_t>(std::max(scene.image.columns, 0)) *
                         static_cast<std::size_t>(std::max(options.samples_per_axis, 1)) *
                         static_cast<std::size_t>(std::max(options.samples_per_axis, 1));
    std::size_t triangles = scene.mesh.triangles.size();
    for (const SceneObject& object : scene.objects) triangles += object.mesh ? object.mesh->triangles.size() : 0;
    return triangles <= kKeptTrianglesMax && samples <= kKeptSamplesMax;
}

}  // namespace

namespace {

/// render()'s work, handing the frame's result to `deliver` while the
/// thread's state (or a fresh one, for a large frame or a nested call) still
/// holds it: `kept` says whether the state stays for the next call. With the
/// kept state, `prepare` may first put the caller's buffers in its result.
template <typename Prepare, typename Deliver>
void render_one_off(const Scene& scene, const RenderOptions& options, Prepare&& prepare, Deliver&& deliver) {
    OneOffMemory& warm = t_one_off;
    if (warm.busy || !keeps_memory(scene, options)) {
        detail::RendererState state;
        state.options = options;
        state.render(scene, true);
        deliver(state.result, false);
        return;
    }
    warm.busy = true;
    struct Release {
        OneOffMemory& warm;
        ~Release() { warm.busy = false; }
    } release{warm};
    if (!warm.state) warm.state = std::make_unique<detail::RendererState>();
    detail::RendererState& state = *warm.state;
    state.options = options;
    state.assembly.forget();
    state.mesh_order.forget_mesh();
    prepare(state.result);
    try {
        state.render(scene, true);
    } catch (...) {
        warm.state.reset();  // a failed or cancelled frame: start the next call afresh
        throw;
    }
    deliver(state.result, true);
    state.options = RenderOptions{};  // drops the caller's progress callback and what it holds
}

}  // namespace

RenderResult render(const Scene& scene, const RenderOptions& options) {
    RenderResult result;
    render_one_off(scene, options, [](RenderResult&) {}, [&result](RenderResult& made, bool kept) {
        // A copy when the state stays: it keeps its image (and extra outputs)
        // for the next call. Moving it out would make the next call grow a
        // new image, mapping and zeroing its pages (about 0.5 ms at 512x512
        // here) where a copy costs a memcpy into memory malloc has usually
        // just had back from the caller.
        if (kept) {
            result = made;
        } else {
            result = std::move(made);
        }
    });
    return result;
}

void render(const Scene& scene, const RenderOptions& options, RenderResult& out) {
    // The frame is drawn in out's image when it can hold it, the state's own
    // image staying as it is: a loop handing the same buffer back (a C++ loop
    // passing one RenderResult, Python's recycled arrays) then draws in one
    // buffer, not in two by turns, as the trade after the frame alone would.
    const std::size_t pixels = static_cast<std::size_t>(std::max(scene.image.rows, 0)) *
                               static_cast<std::size_t>(std::max(scene.image.columns, 0));
    const auto draw_in_out = [&out, pixels](RenderResult& working) {
        if (out.image.pixels.capacity() >= pixels && pixels != 0) std::swap(out.image, working.image);
    };
    render_one_off(scene, options, draw_in_out, [&out](RenderResult& made, bool kept) {
        if (!kept) {
            out = std::move(made);
            return;
        }
        // The frame's image goes out as it is; what out held (the state's own
        // image, or out's old one when it was too small) becomes the state's
        // working image for the next frame, which resizes and overwrites it.
        std::swap(out.image, made.image);
        out.stats = made.stats;
        out.aovs = made.aovs;
    });
}

void release_render_memory() { t_one_off.state.reset(); }

Image render_object(const std::vector<glm::dvec3>& positions, const std::vector<glm::vec3>& colors,
                    const std::vector<Triangle>& faces, const Camera& camera, const ImageSpec& image,
                    const PhongMaterial& material, const glm::vec3& ambient,
                    const std::vector<PointLight>& lights, Shader shader, Lighting lighting,
                    const RenderOptions& options) {
    Scene scene;
    scene.mesh.positions = positions;
    scene.mesh.colors = colors;
    scene.mesh.triangles = faces;
    scene.camera = camera;
    scene.image = image;
    scene.material = material;
    scene.ambient = ambient;
    scene.lights = lights;
    scene.shader = shader;
    scene.lighting = lighting;
    return render(scene, options).image;
}

}  // namespace phongrast
