#include "mesh_order.hpp"

#include <algorithm>
#include <atomic>
#include <cstring>
#include <limits>

#include <glm/common.hpp>
#include <meshoptimizer.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "resize_polling.hpp"
#include "same_array.hpp"
#include "effects.hpp"

namespace phongrast::detail {
namespace {

/// Elements gathered by one task.
constexpr std::size_t kGatherBlock = 16384;
/// Triangles compared or copied by one task (1.5 MiB).
constexpr std::size_t kCompareBlock = 131072;

/// out[i] = in[source[i]] for every i, in parallel; `out` resized (its memory reused).
template <typename T>
void gather(const std::vector<T>& in, const std::vector<std::uint32_t>& source, std::vector<T>& out,
            const std::function<void()>& poll) {
    if (in.empty()) {
        out.clear();
        return;
    }
    resize_polling(out, source.size(), poll);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, source.size(), kGatherBlock),
                      [&](const tbb::blocked_range<std::size_t>& range) {
        for (std::size_t i = range.begin(); i != range.end(); ++i) out[i] = in[source[i]];
    });
}

/// Per-corner index triples (texture coordinates, file normals) follow
/// their triangles; the values they index stay where they are.
void gather_corner_indices(const std::vector<Triangle>& in, const std::vector<std::uint32_t>& source,
                           std::vector<Triangle>& out) {
    gather(in, source, out, nullptr);
}

/// Whether two triangle lists are the same, bit for bit, compared in parallel.
bool same_triangles(const std::vector<Triangle>& a, const std::vector<Triangle>& b) {
    if (a.size() != b.size()) return false;
    std::atomic<bool> differ{false};
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, a.size(), kCompareBlock),
                      [&](const tbb::blocked_range<std::size_t>& range) {
        if (differ.load(std::memory_order_relaxed)) return;
        if (std::memcmp(a.data() + range.begin(), b.data() + range.begin(), range.size() * sizeof(Triangle)) != 0) {
            differ.store(true, std::memory_order_relaxed);
        }
    });
    return !differ.load();
}

/// out = in, in parallel, growing `out` with polls (resize_polling()).
void copy_polling(const std::vector<Triangle>& in, std::vector<Triangle>& out, const std::function<void()>& poll) {
    resize_polling(out, in.size(), poll);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, in.size(), kCompareBlock),
                      [&](const tbb::blocked_range<std::size_t>& range) {
        std::memcpy(out.data() + range.begin(), in.data() + range.begin(), range.size() * sizeof(Triangle));
    });
}

/// The copy's triangles: the caller's, in the permutation's order, naming the copy's vertices.
void copy_triangles(const Mesh& mesh, const MeshOrder& order, std::vector<Triangle>& out) {
    const std::vector<std::uint32_t> vertex_target = vertex_targets(order);
    out.resize(mesh.triangles.size());
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, out.size(), kGatherBlock),
                      [&](const tbb::blocked_range<std::size_t>& range) {
        for (std::size_t k = range.begin(); k != range.end(); ++k) {
            const Triangle& tri = mesh.triangles[order.triangle_source[k]];
            out[k] = {vertex_target[tri[0]], vertex_target[tri[1]], vertex_target[tri[2]]};
        }
    });
}

/// Cells per axis of the spatial sort's grid, and the finer grid that orders
/// the triangles within a cell: kFineBits bits per axis, the top kCellBits of
/// which name the cell.
constexpr int kCellBits = 6, kFineBits = 10;
constexpr std::uint32_t kCells = 1u << kCellBits, kFineCells = 1u << kFineBits;
/// The bits of a fine Morton code below its cell's code.
constexpr int kWithinCellBits = 3 * (kFineBits - kCellBits);

/// A fine-grid coordinate, 0..kFineCells-1, from a position scaled to
/// [0, kFineCells] (clamped: rounding, and an infinite or NaN extent, stay in the grid).
std::uint32_t grid_coordinate(double scaled) {
    if (!(scaled > 0.0)) return 0;
    return scaled >= kFineCells - 1 ? kFineCells - 1 : static_cast<std::uint32_t>(scaled);
}

/// x's low 10 bits moved to bits 0, 3, 6, ..., 27 (the usual shifts and masks).
std::uint32_t spread_bits(std::uint32_t x) {
    x &= 0x3ffu;
    x = (x | (x << 16)) & 0x030000ffu;
    x = (x | (x << 8)) & 0x0300f00fu;
    x = (x | (x << 4)) & 0x030c30c3u;
    x = (x | (x << 2)) & 0x09249249u;
    return x;
}

/// The 30-bit Morton code of a fine cell: x, y and z bits interleaved, so
/// that its top 18 bits are the Morton code of the cell holding it.
std::uint32_t morton_code(std::uint32_t x, std::uint32_t y, std::uint32_t z) {
    static_assert(kFineBits == 10, "spread_bits() spreads 10 bits");
    return spread_bits(x) | spread_bits(y) << 1 | spread_bits(z) << 2;
}

/// A few triangles of the mesh, hashed: with the arrays' addresses and
/// sizes, what tells one mesh from another for reusing a permutation.
std::uint64_t sample_triangles(const std::vector<Triangle>& triangles) {
    constexpr std::size_t kSamples = 1024;
    std::uint64_t hash = 0x9e3779b97f4a7c15ull;
    const std::size_t step = std::max<std::size_t>(1, triangles.size() / kSamples);
    for (std::size_t t = 0; t < triangles.size(); t += step) {
        for (std::uint32_t index : triangles[t]) {
            hash ^= index + 0x9e3779b97f4a7c15ull + (hash << 6) + (hash >> 2);
        }
    }
    return hash;
}

bool same_mesh_as_before(const Mesh& mesh, const MeshOrder& order) {
    return order.triangle_count == mesh.triangles.size() && order.vertex_count == mesh.positions.size() &&
           order.positions_data == mesh.positions.data() &&
           order.triangles_data == mesh.triangles.data() && order.triangles_sample == sample_triangles(mesh.triangles);
}

/// Every field of the scene but its mesh (and objects, empty when reordering).
void copy_all_but_mesh(const Scene& from, Scene& to) {
    // A field added to Scene must be copied here (and the size below updated; x86-64).
    static_assert(sizeof(void*) != 8 || sizeof(Scene) == 672, "copy_all_but_mesh() copies every field of Scene");
    to.camera = from.camera;
    to.image = from.image;
    to.material = from.material;
    to.material_fields = from.material_fields;
    to.normals = from.normals;
    to.ambient = from.ambient;
    to.lights = from.lights;
    to.shader = from.shader;
    to.lighting = from.lighting;
}

/// Whether the pipeline reads normals (vertex_stage.cpp's need_normals).
bool needs_normals(const Scene& scene, const RenderOptions& options) {
    return find_effects(scene).normals || !options.specialize_effects || options.aovs.normal;
}

/// order.scene.mesh.normals computed (its positions and triangles already
/// copied), with the bits of calculate_normals() on the caller's mesh.
void normals_in_caller_order(const Mesh& mesh, MeshOrder& order, const std::function<void()>& poll) {
    Mesh& out = order.scene.mesh;
    if (mesh.triangles.size() <= kVertexCornersMaxTriangles) {
        // Made on the first frame that computes normals, and again after the
        // triangles were edited in place (the permutation is kept: any
        // permutation gives the same picture, but the list is the triangles').
        if (!order.vertex_corners_made) list_vertex_corners(mesh, order, poll);
        if (calculate_normals_by_corners(out.positions, out.triangles, order.vertex_corners, order.normals_scratch,
                                         out.normals, poll)) {
            return;
        }
    }
    // On the caller's mesh, then permuted (scattered reads, same bits).
    calculate_normals_into(mesh.positions, mesh.triangles, order.normals_scratch, order.normals, poll);
    if (poll) poll();
    gather(order.normals, order.vertex_source, out.normals, poll);
}

/// order.scene.mesh's positions, colours and normals, computed or kept
/// (MeshOrder::kept_normals), once the copy's triangles are made.
void copy_vertex_arrays_and_normals(const Mesh& mesh, MeshOrder& order, const std::function<void()>& poll) {
    Mesh& out = order.scene.mesh;
    MeshOrder::KeptNormals& kept = order.kept_normals;
    // Positions equal to those kept, gathered through the same permutation,
    // are the copy's already; the colours play no part in the normals.
    gather(mesh.colors, order.vertex_source, out.colors, poll);
    if (!(kept.valid && kept.triangles_made == order.triangles_made && same_array(kept.positions, mesh.positions))) {
        kept.valid = false;  // until computed whole (a cancel may stop it halfway)
        gather(mesh.positions, order.vertex_source, out.positions, poll);
        normals_in_caller_order(mesh, order, poll);
        ++order.normals_computed;
        if (mesh.triangles.size() <= kReusedNormalsMaxTriangles) {
            kept.positions.assign(mesh.positions.begin(), mesh.positions.end());
            kept.normals.assign(out.normals.begin(), out.normals.end());
            kept.triangles_made = order.triangles_made;
            kept.valid = true;
        } else {  // too large to keep
            std::vector<glm::dvec3>().swap(kept.positions);
            std::vector<glm::vec3>().swap(kept.normals);
        }
    } else {
        // The copy's normals may hold the last frame's given ones.
        out.normals.assign(kept.normals.begin(), kept.normals.end());
    }
    if (!mesh.normals.empty()) keep_given_normals(mesh.normals, order.vertex_source, out.normals);
}

constexpr std::size_t kNoOverride = std::numeric_limits<std::size_t>::max() - 1;
std::atomic<std::size_t> g_reorder_min_triangles{kNoOverride};
std::atomic<bool> g_reorder_always{false};

}  // namespace

std::size_t set_reorder_min_triangles(std::size_t triangles) { return g_reorder_min_triangles.exchange(triangles); }
std::size_t reorder_min_triangles(bool one_off) {
    const std::size_t value = g_reorder_min_triangles.load();
    if (value != kNoOverride) return value;
    return one_off ? kReorderMinTrianglesOneOff : kReorderMinTriangles;
}
bool set_reorder_always(bool always) { return g_reorder_always.exchange(always); }

bool should_reorder(const Scene& scene, const RenderOptions& options, bool one_off) {
    return scene.objects.empty() && scene.mesh.triangles.size() >= reorder_min_triangles(one_off) &&
           options.back_faces == BackFaces::draw;
}

double local_order_misses(const Mesh& mesh) {
    constexpr std::size_t kLines = 4096, kWindow = 8192, kWindows = 16;
    constexpr std::size_t kVertexBytes = 24, kLineBytes = 64;
    const std::size_t triangles = mesh.triangles.size();
    if (triangles == 0) return 0.0;
    const std::size_t windows = std::min(kWindows, (triangles + kWindow - 1) / kWindow);
    std::uint64_t misses = 0, read = 0;
    std::vector<std::uint64_t> tag(kLines);
    for (std::size_t w = 0; w < windows; ++w) {
        std::fill(tag.begin(), tag.end(), ~std::uint64_t(0));
        const std::size_t begin = windows == 1 ? 0 : w * (triangles - std::min(triangles, kWindow)) / (windows - 1);
        const std::size_t end = std::min(triangles, begin + kWindow);
        for (std::size_t t = begin; t < end; ++t) {
            for (std::uint32_t index : mesh.triangles[t]) {
                const std::uint64_t line = std::uint64_t(index) * kVertexBytes / kLineBytes;
                std::uint64_t& slot = tag[line % kLines];
                misses += slot != line;
                slot = line;
            }
        }
        read += end - begin;
    }
    return double(misses) / double(read);
}

void compute_mesh_order(const Mesh& mesh, MeshOrder& order, const std::function<void()>& poll, WithinCells within) {
    order.vertex_corners_made = false;  // made for the permutation being replaced
    order.triangles_copied = false;
    const auto report = [&poll] {
        if (poll) poll();
    };
    const std::size_t triangles = mesh.triangles.size(), vertices = mesh.positions.size();
    // Triangles by the Morton code of their centroid's cell in a 64^3 grid
    // over the mesh's bounding box (one counting sort: meshopt_spatialSortRemap's
    // full 30-bit sort took 0.25 s of a 1.3M-triangle frame), and within a
    // cell in the caller's order or by a 1024^3 grid's code (WithinCells).
    glm::dvec3 low(std::numeric_limits<double>::max()), high(std::numeric_limits<double>::lowest());
    for (const glm::dvec3& p : mesh.positions) {
        low = glm::min(low, p);
        high = glm::max(high, p);
    }
    const glm::dvec3 extent = high - low;
    const glm::dvec3 scale(kFineCells / std::max(extent.x, 1e-300), kFineCells / std::max(extent.y, 1e-300),
                           kFineCells / std::max(extent.z, 1e-300));
    std::vector<std::uint32_t> code(triangles);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, triangles, kGatherBlock),
                      [&](const tbb::blocked_range<std::size_t>& range) {
        for (std::size_t t = range.begin(); t != range.end(); ++t) {
            const Triangle& tri = mesh.triangles[t];
            const glm::dvec3 c = (mesh.positions[tri[0]] + mesh.positions[tri[1]] + mesh.positions[tri[2]]) / 3.0;
            std::uint32_t q[3];
            for (int axis = 0; axis < 3; ++axis) q[axis] = grid_coordinate((c[axis] - low[axis]) * scale[axis]);
            code[t] = morton_code(q[0], q[1], q[2]);
        }
    });
    report();
    std::vector<std::uint32_t> start(std::size_t(kCells) * kCells * kCells + 1, 0);
    for (std::uint32_t fine : code) ++start[(fine >> kWithinCellBits) + 1];
    for (std::size_t c = 1; c < start.size(); ++c) start[c] += start[c - 1];
    order.triangle_source.resize(triangles);
    // Each start[c] moves to its cell's end: then start[c] is where cell c + 1 begins.
    for (std::size_t t = 0; t < triangles; ++t) {
        order.triangle_source[start[code[t] >> kWithinCellBits]++] = static_cast<std::uint32_t>(t);
    }
    report();
    if (within == WithinCells::by_finer_grid) {
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, start.size() - 1, 4096),
                          [&](const tbb::blocked_range<std::size_t>& cells) {
            std::vector<std::uint64_t> keyed;  // (fine code, caller's index) of one cell's triangles
            for (std::size_t c = cells.begin(); c != cells.end(); ++c) {
                const std::size_t begin = c == 0 ? 0 : start[c - 1], end = start[c];
                if (end - begin < 2) continue;
                keyed.clear();
                for (std::size_t k = begin; k < end; ++k) {
                    const std::uint32_t t = order.triangle_source[k];
                    keyed.push_back(std::uint64_t(code[t]) << 32 | t);
                }
                std::sort(keyed.begin(), keyed.end());
                for (std::size_t k = begin; k < end; ++k) {
                    order.triangle_source[k] = static_cast<std::uint32_t>(keyed[k - begin]);
                }
            }
        });
    }
    std::vector<std::uint32_t>().swap(code);
    report();

    // Vertices numbered by first use in that order; unused ones after them.
    std::vector<std::uint32_t> indices(3 * triangles);
    for (std::size_t k = 0; k < triangles; ++k) {
        const Triangle& tri = mesh.triangles[order.triangle_source[k]];
        for (int i = 0; i < 3; ++i) indices[3 * k + i] = tri[i];
    }
    std::vector<std::uint32_t> vertex_target(vertices);
    report();
    std::size_t used = meshopt_optimizeVertexFetchRemap(vertex_target.data(), indices.data(), indices.size(),
                                                        vertices);
    report();
    for (std::uint32_t& target : vertex_target) {
        if (target == ~0u) target = static_cast<std::uint32_t>(used++);
    }
    order.vertex_source.resize(vertices);
    for (std::size_t v = 0; v < vertices; ++v) order.vertex_source[vertex_target[v]] = static_cast<std::uint32_t>(v);
    ++order.permutations_computed;
}

std::vector<std::uint32_t> vertex_targets(const MeshOrder& order) {
    std::vector<std::uint32_t> target(order.vertex_source.size());
    for (std::size_t v = 0; v < target.size(); ++v) target[order.vertex_source[v]] = static_cast<std::uint32_t>(v);
    return target;
}

void list_vertex_corners(const Mesh& mesh, MeshOrder& order, const std::function<void()>& poll) {
    order.vertex_corners_made = false;  // until finished (a cancel may stop it halfway)
    const std::size_t triangles = mesh.triangles.size(), vertices = mesh.positions.size();
    const std::vector<std::uint32_t> vertex_target = vertex_targets(order);
    std::vector<std::uint32_t> triangle_target(triangles);
    for (std::size_t k = 0; k < triangles; ++k) triangle_target[order.triangle_source[k]] = static_cast<std::uint32_t>(k);
    if (poll) poll();
    // A counting sort by internal vertex of the caller's corners, visited in
    // the caller's order: each vertex's list comes out in that order.
    std::vector<std::uint32_t>& first = order.vertex_corners.first;
    std::vector<std::uint32_t>& corners = order.vertex_corners.corners;
    // Polls inside the walks too: each walks every triangle on one thread.
    constexpr std::size_t kPollEvery = 65536;
    first.assign(vertices + 1, 0);
    for (std::size_t t = 0; t < triangles; ++t) {
        if (poll && t % kPollEvery == 0) poll();
        for (std::uint32_t index : mesh.triangles[t]) ++first[vertex_target[index] + 1];
    }
    for (std::size_t v = 1; v <= vertices; ++v) first[v] += first[v - 1];
    resize_polling(corners, 3 * triangles, poll);
    // first[v] serves as v's cursor, ending at v + 1's start; then shifted back.
    for (std::size_t t = 0; t < triangles; ++t) {
        if (poll && t % kPollEvery == 0) poll();
        const Triangle& tri = mesh.triangles[t];
        for (std::uint32_t corner = 0; corner < 3; ++corner) {
            corners[first[vertex_target[tri[corner]]]++] = triangle_target[t] << 2 | corner;
        }
    }
    for (std::size_t v = vertices; v > 0; --v) first[v] = first[v - 1];
    first[0] = 0;
    order.vertex_corners_made = true;
}

const Scene& scene_in_render_order(const Scene& scene, const RenderOptions& options, bool one_off,
                                   MeshOrder& order, const std::function<void()>& poll) {
    const auto report = [&poll] {
        if (poll) poll();
    };
    order.reordered = false;  // the id output and painter's ties take the pipeline's indices as they are
    order.caller_mesh = nullptr;
    if (!should_reorder(scene, options, one_off)) return scene;
    const Mesh& mesh = scene.mesh;
    if (!same_mesh_as_before(mesh, order)) {
        order.caller_order_is_local =
            !g_reorder_always.load() && local_order_misses(mesh) < kReorderMinMissesPerTriangle;
        if (order.caller_order_is_local) {
            // Remembered as this mesh's (same_mesh_as_before() then holds), with no permutation.
            order.triangle_source.clear();
            order.vertex_source.clear();
            order.vertex_corners_made = false;
            order.triangles_copied = false;
            std::vector<Triangle>().swap(order.triangles_snapshot);
        } else {
            // Forgotten first: a cancel inside compute_mesh_order (RenderCancelled from
            // `poll`) leaves half-written permutations that must not pass for this mesh's.
            order.positions_data = nullptr;
            order.triangles_data = nullptr;
            // A Renderer keeps the permutation for frame after frame: it orders the cells too.
            compute_mesh_order(mesh, order, poll, one_off ? WithinCells::callers_order : WithinCells::by_finer_grid);
        }
        order.positions_data = mesh.positions.data();
        order.triangles_data = mesh.triangles.data();
        order.vertex_count = mesh.positions.size();
        order.triangle_count = mesh.triangles.size();
        order.triangles_sample = sample_triangles(mesh.triangles);
    }
    if (order.caller_order_is_local) return scene;
    // The copy, from the caller's arrays as they are now.
    order.reordered = true;
    order.caller_mesh = &mesh;
    copy_all_but_mesh(scene, order.scene);
    Mesh& out = order.scene.mesh;
    report();
    // The normals the pipeline would compute from the caller's mesh (all of
    // them, or where a user normal is zero: "compute this one") are computed
    // here, from a copy of the vertex arrays. Otherwise the copy holds no
    // vertex array: the vertex stage reads the caller's (CallerVertices), and
    // a shuffled mesh's 24 bytes per triangle are not held twice.
    const bool needed = needs_normals(scene, options);
    const bool computes_normals = needed && (mesh.normals.empty() || has_zero_normal(mesh.normals));
    order.vertex_arrays_copied = computes_normals;
    if (!computes_normals) {
        order.kept_normals.valid = false;  // they go with the copy's positions, dropped here
        std::vector<glm::dvec3>().swap(out.positions);
        std::vector<glm::vec3>().swap(out.colors);
        std::vector<glm::vec3>().swap(out.normals);
    }
    // The copy's triangles depend on the caller's triangles and the
    // permutation only: made again when the caller's differ from the snapshot
    // they were made from (a sequential comparison, where making them reads
    // the caller's triangles and the vertex targets at random), else kept. The
    // corner list, made for those triangles, is made again with them.
    if (!order.triangles_copied || !same_triangles(mesh.triangles, order.triangles_snapshot)) {
        order.triangles_copied = false;  // until both are whole (a cancel may stop it halfway)
        order.vertex_corners_made = false;
        copy_triangles(mesh, order, out.triangles);
        ++order.triangles_made;
        if (poll) poll();
        copy_polling(mesh.triangles, order.triangles_snapshot, poll);
        order.triangles_copied = true;
    }
    report();
    // Computed normals, with the caller's mesh's bits: a zero one is zero in
    // every order (a vertex whose faces all have zero length: the sums' order
    // cannot matter), so the vertex stage takes them as final.
    if (computes_normals) {
        copy_vertex_arrays_and_normals(mesh, order, poll);
        report();
    }
    // Contract version 2's per-triangle attributes follow their triangles.
    out.texcoords = mesh.texcoords;
    gather_corner_indices(mesh.texcoord_triangles, order.triangle_source, out.texcoord_triangles);
    out.file_normals = mesh.file_normals;
    gather_corner_indices(mesh.file_normal_triangles, order.triangle_source, out.file_normal_triangles);
    out.materials = mesh.materials;
    gather(mesh.face_materials, order.triangle_source, out.face_materials, poll);
    return order.scene;
}

}  // namespace phongrast::detail
