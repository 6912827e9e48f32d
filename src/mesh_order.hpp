// Mesh order (internal header): before a large mesh enters the pipeline it
// is copied into an order whose memory accesses stay local, whatever order
// the caller's arrays come in: triangles sorted spatially (by the Morton
// code of their centroid's cell in a 64^3 grid), vertices renumbered by
// first use in that order. Set-up,
// clipping and painter's keys then read neighbouring vertices for
// neighbouring triangles instead of three random cache lines per triangle.
//
// The picture does not change, bit for bit: every per-vertex and
// per-triangle computation is the same whatever the order (each triangle
// keeps its corners in their order), and the two things that depend on a
// triangle's place in the list use its original index: painter's tie-break
// (equal mean depths are drawn in the caller's order: painter_order()'s
// tie rank) and the id output (AovPassInput::original_triangle). Computed
// normals are summed in the caller's order too: each vertex of the copy adds
// its faces in the order a pass over the caller's triangles would
// (MeshOrder::vertex_corners), so the copy's normals have the caller's
// mesh's bits while every read stays local.
//
// What a Renderer keeps: the permutation, computed once per mesh (the
// expensive part: a spatial sort), and the reordered copy. The vertex stage
// gathers the caller's vertex arrays through the permutation on every frame
// (a copy of them is made only when normals are computed here); its triangles
// (whose making reads the caller's at random) are kept while the caller's
// compare equal, every frame, to a snapshot of those they were made from. So
// a mesh edited in place between frames is never drawn stale: only the
// permutation is reused, and any permutation gives the same picture. Whether the
// permutation is reused is decided by the mesh's identity (the arrays'
// addresses and sizes and a sample of its triangles); guessing wrong costs
// speed only, never correctness.
#ifndef PHONGRAST_SRC_MESH_ORDER_HPP
#define PHONGRAST_SRC_MESH_ORDER_HPP

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

#include "normals.hpp"
#include "vertex_stage.hpp"
#include "phongrast/render.hpp"

namespace phongrast::detail {

/// Meshes with fewer triangles are rendered in the caller's order: their
/// vertex arrays stay in cache, and the copy would cost more than it saves.
/// A Renderer pays the permutation once per mesh, render() on every call,
/// so render() starts much higher: under 2^18 triangles, a one-off render
/// that reordered lost on every mesh measured (the bunny 1.3-1.6x, the
/// armadillo 1.15x, shuffled icospheres of 65k-128k up to 1.07x; above it
/// shuffled meshes gain, Gouraud 0.70-0.90; docs/performance.md, "Mesh order").
constexpr std::size_t kReorderMinTriangles = 16384;
constexpr std::size_t kReorderMinTrianglesOneOff = 262144;

/// A mesh whose order already misses the cache less than this, in vertex
/// cache lines per triangle (local_order_misses()), is rendered as it
/// comes: a generator's or a tool's well-ordered mesh pays no copy.
/// Measured on a 72,000-triangle icosphere (tests/test_mesh_order.cpp):
/// 0.21 in the generator's order and in the spatial one, 1.x with only
/// the faces shuffled, 2.3 with faces and vertices shuffled.
constexpr double kReorderMinMissesPerTriangle = 0.6;

/// Overrides both thresholds of triangles (a test or benchmark: 0 reorders
/// every mesh whose order is not local, SIZE_MAX none, today's path);
/// returns the previous override, 0 meaning... see reorder_min_triangles().
std::size_t set_reorder_min_triangles(std::size_t triangles);
/// The threshold in force: the override when set, else the constant for a
/// Renderer (`one_off` false) or render() (true).
std::size_t reorder_min_triangles(bool one_off = false);
/// Turns the locality test off (true: every mesh over the threshold is
/// reordered, for tests); returns the previous setting.
bool set_reorder_always(bool always);

/// Vertex cache lines missed per triangle when the mesh's triangles are
/// read in its order, in a small direct-mapped model of the cache (4,096
/// lines of 64 bytes, 24-byte vertices), over up to 16 windows of 8,192
/// triangles spread over the mesh.
double local_order_misses(const Mesh& mesh);

/// A mesh's reordering, and the reordered scene of the frame being rendered.
struct MeshOrder {
    /// Internal triangle -> the caller's triangle (empty: not reordered).
    std::vector<std::uint32_t> triangle_source;
    /// Internal vertex -> the caller's vertex (its inverse, vertex_targets(),
    /// is made when needed and not kept: 4 bytes per vertex).
    std::vector<std::uint32_t> vertex_source;
    /// What the permutation was computed for (only the speed depends on it).
    const void* positions_data = nullptr;
    const void* triangles_data = nullptr;
    std::size_t vertex_count = 0, triangle_count = 0;
    std::uint64_t triangles_sample = 0;
    /// The caller's order was found local enough: rendered as it comes.
    bool caller_order_is_local = false;
    /// This frame renders `scene` (below) rather than the caller's.
    bool reordered = false;

    /// This frame's copy holds the vertex arrays (gathered from the caller's):
    /// only when normals are computed here (from the copy's positions); else
    /// it holds triangles only, and the vertex stage reads the caller's arrays
    /// through vertex_source (caller_vertices()).
    bool vertex_arrays_copied = false;
    /// The caller's mesh of the frame being rendered (while reordered).
    const Mesh* caller_mesh = nullptr;

    /// The caller's index of each triangle the pipeline sees, or null when it sees the caller's mesh.
    const std::uint32_t* original_triangles() const { return reordered ? triangle_source.data() : nullptr; }
    /// Where the vertex stage reads the vertex arrays: the caller's, when the copy holds triangles only.
    /// When the copy holds the vertex arrays, its normals are final (computed here).
    CallerVertices caller_vertices() const {
        if (!reordered) return CallerVertices{};
        return vertex_arrays_copied ? CallerVertices{nullptr, nullptr, true}
                                    : CallerVertices{caller_mesh, vertex_source.data(), false};
    }
    /// The caller's scene with the mesh in internal order: triangles made
    /// when the caller's changed; vertex arrays gathered every frame when
    /// vertex_arrays_copied, else empty.
    Scene scene;
    NormalsScratch normals_scratch;
    /// The caller's triangles as they were when the copy's (scene.mesh.triangles)
    /// were made: while they compare equal, the copy's are kept (made again
    /// otherwise, and after a new permutation: triangles_copied false).
    std::vector<Triangle> triangles_snapshot;
    bool triangles_copied = false;
    /// Computed normals: each vertex's corners in the caller's order of
    /// triangles, for the permutation in force and the copy's triangles
    /// (made once per mesh, on the first frame that computes normals; made
    /// again after the copy's triangles were: the mesh was edited in place).
    VertexCorners vertex_corners;
    bool vertex_corners_made = false;
    /// Normals computed in the caller's order, then permuted: only for a mesh
    /// too large for vertex_corners (kVertexCornersMaxTriangles).
    std::vector<glm::vec3> normals;
    /// The copy's computed normals (before given ones replace them), kept for
    /// the next frame while the caller's positions compare equal to those they
    /// were computed from and the copy's triangles are the same ones
    /// (triangles_made: they are made again after any edit of the caller's,
    /// or a new permutation, and compared every frame already): a Renderer's
    /// frames of a mesh without normals (or with zero ones) compute them once,
    /// and gather its positions once. Meshes of at most
    /// kReusedNormalsMaxTriangles triangles (24 + 12 bytes per vertex).
    struct KeptNormals {
        std::vector<glm::dvec3> positions;  ///< the caller's, as computed from
        std::size_t triangles_made = 0;     ///< MeshOrder::triangles_made then
        std::vector<glm::vec3> normals;
        bool valid = false;
    } kept_normals;
    /// Times the copy's normals were computed (tests: once while the mesh is unchanged).
    std::size_t normals_computed = 0;
    /// Permutations computed so far (tests: a Renderer computes one per mesh).
    std::size_t permutations_computed = 0;
    /// Times the copy's triangles were made (tests: once per permutation and edit).
    std::size_t triangles_made = 0;

    /// The next frame computes its permutation anew (the memory is kept): for
    /// render()'s warm state, whose callers' meshes may reuse a freed mesh's address.
    void forget_mesh() {
        positions_data = nullptr;
        triangles_data = nullptr;
    }
};

/// Whether `scene` may be rendered reordered with `options`: a mesh of at least
/// reorder_min_triangles(one_off) triangles (a single mesh: a scene of objects is
/// left as it is), and no back-face culling, whose closedness test sums
/// per-vertex volumes whose rounding could depend on vertex numbering.
bool should_reorder(const Scene& scene, const RenderOptions& options, bool one_off);

/// The scene the pipeline renders: `scene` itself when !should_reorder() or
/// when its order is already local (local_order_misses()), else order.scene, `scene` with its mesh permuted (order.triangle_source
/// then names each internal triangle's original index; otherwise it is
/// empty). Reuses order's permutation when the mesh looks like the last one.
/// `poll` (may be empty) is called between steps, for progress reports.
const Scene& scene_in_render_order(const Scene& scene, const RenderOptions& options, bool one_off,
                                   MeshOrder& order, const std::function<void()>& poll = nullptr);

/// How compute_mesh_order() orders the triangles of one cell of its 64^3
/// grid (a hundred or so on a 1.3M-triangle sphere).
enum class WithinCells {
    /// In the caller's order: free, and as local as the caller's order is.
    callers_order,
    /// By the Morton code of a 1024^3 grid, the caller's order breaking ties:
    /// the same order whatever order the mesh comes in. In the caller's
    /// order, a shuffled 1.3M sphere's cells list their triangles at random,
    /// and its walk took 16-20 ms (set-up 1.4x) more than the spatially
    /// ordered mesh's; by the finer grid 3-7 ms. The cells' sorts cost 18-25
    /// ms more at 1.3M (2 threads), which a Renderer pays once per mesh and
    /// render() would pay on every call: render() keeps the caller's order.
    by_finer_grid,
};

/// The permutation alone, for tests and benchmarks: fills order's
/// triangle_source and vertex_source for `mesh`.
void compute_mesh_order(const Mesh& mesh, MeshOrder& order, const std::function<void()>& poll = nullptr,
                        WithinCells within = WithinCells::by_finer_grid);

/// The caller's vertex -> internal vertex: the inverse of order.vertex_source.
std::vector<std::uint32_t> vertex_targets(const MeshOrder& order);

/// order.vertex_corners for `mesh` (the caller's) and order's permutation:
/// each internal vertex's corners, internal triangles, listed by ascending
/// caller's triangle, then corner (sets vertex_corners_made). Only for meshes
/// of at most kVertexCornersMaxTriangles triangles.
void list_vertex_corners(const Mesh& mesh, MeshOrder& order, const std::function<void()>& poll = nullptr);

}  // namespace phongrast::detail

#endif  // PHONGRAST_SRC_MESH_ORDER_HPP
