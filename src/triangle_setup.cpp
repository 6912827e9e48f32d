#include "triangle_setup.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <optional>

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "back_faces.hpp"
#include "clipping.hpp"
#include "coverage_screen.hpp"
#include "painter_order.hpp"
#include "prefetch.hpp"
#include "raster.hpp"
#include "seed_corner_batch.hpp"
#include "task_sizes.hpp"
#include "term_counts.hpp"

namespace phongrast::detail {
namespace {

// A clipped triangle is a fan of at most 6 pieces (ClipPolygon holds 8 corners).
static_assert(kSetupChunk * 6 < (std::size_t(1) << DrawSpan::kFirstBits), "a chunk's draws must fit DrawSpan");
static_assert(std::tuple_size<decltype(ClipPolygon<float>::vertices)>::value == 8, "at most 6 pieces per triangle");

/// One corner of a piece to draw: where it is (sample coordinates, z_c) and
/// the varyings the fill triangle will point to.
template <typename Real>
struct Corner {
    double column, row, depth;
    const Varyings<Real>* varyings;
};

/// How a triangle's pieces fared, for the counts.
struct PiecesOutcome {
    bool drawn = false;        ///< some piece covers a sample
    bool has_area = false;     ///< some piece has non-zero area after snapping
    bool meets_image = true;   ///< the (clipped) polygon overlaps the image
};

template <typename Real>
class TriangleSetup {
public:
    TriangleSetup(const SetupInput<Real>& input, ChunkVector<FillTriangle<Real>>& out,
                  ClipVertexStore<Real>& clip_vertices, SetupCounts& counts, LightVectorsAt<Real>& vectors)
        : in_(input), vertices_(input.vertices), out_(out), clip_vertices_(clip_vertices), counts_(counts),
          vectors_(vectors), same_lit_(same_lit_everywhere()),
          in_parts_(input.scene.shader == Shader::gouraud && input.textures != nullptr) {}

    /// Seed Gouraud: lights whole triangles' corners in `batch` (which lights
    /// them when full; light_batched_corners() lights the rest) rather than one
    /// triangle at a time, when one specialised shader lights every triangle.
    /// Returns whether it batches: if so, a whole triangle's draw has its `lit`
    /// only once its batch is lit.
    bool batch_seed_corners(SeedCornerBatch<Real>& batch) {
        const bool seed_gouraud = in_.scene.shader == Shader::gouraud &&
                                  in_.options.light_vectors == LightVectors::triangle_centroid;
        if (seed_gouraud && !in_parts_ && !same_lit_ && in_.triangle_surfaces == nullptr &&
            SeedCornerBatch<Real>::can_light(in_.shader)) {
            seed_batch_ = &batch;
        }
        return seed_batch_ != nullptr;
    }
    void light_batched_corners() {
        if (seed_batch_ != nullptr) seed_batch_->light(in_.shader, out_);
    }

    // Both paths, whole and clipped, make their pieces with set_up_piece()
    // and are counted and flat-lit here.
    void run(std::uint32_t source) {
        source_ = source;
        surface_ = in_.triangle_surfaces != nullptr ? in_.triangle_surfaces[source] : 0;
        const Triangle& tri = in_.scene.mesh.triangles[source];
        if (in_.cull != HiddenBackFaces::unknown && faces_away(in_.scene.mesh, in_.view.frame.eye, in_.cull, tri)) {
            ++counts_.culled;
            return;
        }
        const bool inside_image = vertices_.inside_image(tri[0], in_.view) &&
                                  vertices_.inside_image(tri[1], in_.view) && vertices_.inside_image(tri[2], in_.view);
        if (!inside_image && in_.options.border == BorderPolicy::drop_triangle) {
            ++counts_.dropped;
            return;
        }
        const FrameVector<ScreenVertex>& screen = vertices_.screen;
        if (!within_drawable_depth(screen[tri[0]]) || !within_drawable_depth(screen[tri[1]]) ||
            !within_drawable_depth(screen[tri[2]])) {
            ++counts_.out_of_range;
            return;
        }
        const Vec3<Real> centroid = centroid_if_lit_there(tri);
        const std::size_t first_draw = out_.size();
        const double near_depth = in_.view.near_depth;
        const bool whole = inside_image && screen[tri[0]].depth >= near_depth && screen[tri[1]].depth >= near_depth &&
                           screen[tri[2]].depth >= near_depth;
        PiecesOutcome outcome;
        if (whole) {
            set_up_whole(tri, centroid, outcome);
        } else {
            const ClipOutcome clipped = set_up_clipped(tri, centroid, inside_image, outcome);
            if (clipped != ClipOutcome::kept) {
                ++(clipped == ClipOutcome::empty ? counts_.outside : counts_.out_of_range);
                return;
            }
        }
        if (outcome.drawn && in_.scene.shader == Shader::flat) {
            // Lit only once something is to be drawn: clipped-away and
            // degenerate triangles cost no lighting.
            ++counts_.lit_points;
            if (in_.textures != nullptr && in_.textures[surface_].texels != nullptr) {
                // Textured: A and S apart, for the fill's T x A + S.
                const Vec3<Real> colour_part = flat_color(tri, centroid, in_.colour_part_shaders[surface_]);
                const Vec3<Real> specular_part = flat_color(tri, centroid, in_.specular_part_shaders[surface_]);
                for (std::size_t d = first_draw; d < out_.size(); ++d) {
                    out_[d].lit[0] = colour_part;
                    out_[d].lit[1] = specular_part;
                    out_[d].lit[2] = Vec3<Real>(Real(0));
                }
            } else {
                const Vec3<Real> lit = same_lit_ ? *same_lit_ : flat_color(tri, centroid, shader());
                for (std::size_t d = first_draw; d < out_.size(); ++d) {
                    for (Vec3<Real>& corner_lit : out_[d].lit) corner_lit = lit;
                }
            }
        }
        count(outcome);
    }

    /// Whether the coverage screen (coverage_screen.hpp) may decide for
    /// run(): it repeats run()'s tests but culling's.
    bool screens() const { return in_.cull == HiddenBackFaces::unknown && coverage_screen_in_use(); }
    /// Counts a triangle the screen decided as run() would have counted it.
    void count_screened(ScreenVerdict verdict) {
        ++(verdict == ScreenVerdict::degenerate ? counts_.degenerate : counts_.between_samples);
    }
    /// Counts a tiny triangle the walk filled from the screen's coverage (drawn, as run() counts it).
    void count_drawn() { ++counts_.drawn; }

    /// Seed Gouraud, batched (batch_seed_corners()): notes tiny triangle
    /// `source`, whose corners in coverage order are `corners`, in the batch
    /// as set_up_whole() notes a whole triangle's draw, counted as there, and
    /// lights the batch when full. Returns its slot (SeedCornerBatch::lit()).
    std::size_t batch_tiny_corners(std::uint32_t source, const Varyings<Real>* const (&corners)[3]) {
        counts_.lit_points += 3;
        const std::size_t slot = seed_batch_->add(corners, centroid_if_lit_there(in_.scene.mesh.triangles[source]),
                                                  SeedCornerBatch<Real>::kNoDraw);
        if (seed_batch_->full()) seed_batch_->light(in_.shader, out_);
        return slot;
    }

    /// Whether a drawn triangle's FillTriangle::lit are its corners' colours
    /// lit per vertex, nothing lit per triangle (exact Gouraud, untextured):
    /// each vertex's `lit`, or same_lit() where that is not null.
    bool lit_per_vertex() const {
        return in_.scene.shader == Shader::gouraud && in_.options.light_vectors != LightVectors::triangle_centroid &&
               !in_parts_;
    }
    /// The one lit colour of every corner (same_lit_everywhere()), or null.
    const Vec3<Real>* same_lit() const { return same_lit_ ? &*same_lit_ : nullptr; }

    /// Flat, untextured: the colour run() gives drawn triangle `source`'s
    /// draws, lit and counted as there (the caller fills it: TinyDraw).
    Vec3<Real> flat_lit(std::uint32_t source) {
        source_ = source;
        surface_ = in_.triangle_surfaces != nullptr ? in_.triangle_surfaces[source] : 0;
        const Triangle& tri = in_.scene.mesh.triangles[source];
        ++counts_.lit_points;
        return same_lit_ ? *same_lit_ : flat_color(tri, centroid_if_lit_there(tri), shader());
    }

private:
    /// The triangle's centroid (camera space) where flat shading or the
    /// seed's light vectors light at it; else zero, unread, and the vertex
    /// positions are not loaded at all.
    Vec3<Real> centroid_if_lit_there(const Triangle& tri) const {
        if ((in_.scene.shader != Shader::flat && in_.options.light_vectors != LightVectors::triangle_centroid) ||
            same_lit_ || (in_.scene.shader != Shader::phong && !lights_at_points_read_them())) {
            return Vec3<Real>(Real(0));
        }
        const FrameVector<Varyings<Real>>& varyings = vertices_.varyings;
        return (varyings[tri[0]].position + varyings[tri[1]].position + varyings[tri[2]].position) / Real(3);
    }

    void count(const PiecesOutcome& outcome) {
        if (outcome.drawn) {
            ++counts_.drawn;
        } else if (!outcome.has_area) {
            ++counts_.degenerate;
        } else if (outcome.meets_image) {
            ++counts_.between_samples;
        } else {
            ++counts_.outside;  // within the guard band, beyond the image's border
        }
    }

    /// Snaps three corners and sets up their coverage into `draw`; false when
    /// they cover no sample. `order[i]` is the corner that became draw corner i.
    bool set_up_piece(const Corner<Real> (&corner)[3], const Vec3<Real>& centroid, FillTriangle<Real>& draw,
                      PiecesOutcome& outcome, int (&order)[3]) const {
        const SnappedPoint a = snap(corner[0].column, corner[0].row);
        const SnappedPoint b = snap(corner[1].column, corner[1].row);
        const SnappedPoint c = snap(corner[2].column, corner[2].row);
        CoverageTriangle coverage;
        // A box of at most 2 x 2 centres that holds none inside the triangle: between samples, as an empty box.
        const bool covers = setup_coverage(a, b, c, in_.view.frame.rows, in_.view.frame.columns, coverage) &&
                            may_cover_a_centre(coverage);
        if (covers || coverage.area2() != 0) outcome.has_area = true;  // set whenever the snapped area is non-zero
        if (!covers) return false;
        draw.coverage = coverage;  // what the fill reads: not `swapped`, used just below
        order[0] = 0;
        order[1] = coverage.swapped ? 2 : 1;
        order[2] = coverage.swapped ? 1 : 2;
        // Only Gouraud reads the corners' lit colours (flat writes its own
        // below): Phong's set-up leaves the vertex's varyings unread.
        const bool gouraud = in_.scene.shader == Shader::gouraud;
        for (int i = 0; i < 3; ++i) {
            const Corner<Real>& from = corner[order[i]];
            draw.v[i] = from.varyings;
            draw.lit[i] = !gouraud ? Vec3<Real>(Real(0)) : same_lit_ ? *same_lit_ : from.varyings->lit;
            draw.depth[i] = static_cast<Real>(from.depth);
        }
        if (in_.scene.shader == Shader::phong) draw.set_centroid(centroid);
        draw.source = source_;
        draw.surface = surface_;
        outcome.drawn = true;
        return true;
    }

    // The common case, nothing to clip: one piece straight from the vertex arrays.
    // `outcome` is the caller's, not a return value: GCC returned the struct
    // in a register assembled through the stack from byte stores, and the
    // 16-bit load that read it back stalled on them (13% of this function's samples).
    void set_up_whole(const Triangle& tri, const Vec3<Real>& centroid, PiecesOutcome& outcome) {
        Corner<Real> corner[3];
        for (int i = 0; i < 3; ++i) {
            const ScreenVertex& s = vertices_.screen[tri[i]];
            corner[i] = {s.column, s.row, s.depth, &vertices_.varyings[tri[i]]};
        }
        FillTriangle<Real> draw;
        int order[3];
        if (!set_up_piece(corner, centroid, draw, outcome, order)) return;
        if (in_parts_) {
            set_up_whole_in_parts(tri, centroid, order, draw);
            out_.push_back(draw);
            return;
        }
        // Exact vectors: set_up_piece() copied the `lit` light_vertices() gave each vertex.
        if (in_.scene.shader == Shader::gouraud && in_.options.light_vectors == LightVectors::triangle_centroid) {
            if (same_lit_) {
                counts_.lit_points += 3;  // lit like the corners below, to the colour set_up_piece() wrote
            } else if (seed_batch_ != nullptr) {
                counts_.lit_points += 3;
                seed_batch_->add(draw.v, centroid, out_.size());
                out_.push_back(draw);
                if (seed_batch_->full()) seed_batch_->light(in_.shader, out_);
                return;
            } else {
                // Lit copies of the corners: light_corners() writes their `lit`, the mesh's vertices stay as they are.
                Varyings<Real> copies[3] = {*draw.v[0], *draw.v[1], *draw.v[2]};
                Varyings<Real>* corners[3] = {&copies[0], &copies[1], &copies[2]};
                counts_.lit_points += light_corners(corners, centroid);
                for (int i = 0; i < 3; ++i) draw.lit[i] = copies[i].lit;
            }
        }
        out_.push_back(draw);
    }

    // A triangle crossing the image border or the near plane: clipped to a
    // polygon, drawn as a fan, unless clipping leaves nothing or meets a corner out of range.
    ClipOutcome set_up_clipped(const Triangle& tri, const Vec3<Real>& centroid, bool inside_image,
                               PiecesOutcome& outcome) {
        ClipPolygon<Real> polygon;
        polygon.count = 3;
        for (int i = 0; i < 3; ++i) {
            ClipVertex<Real>& v = polygon.vertices[i];
            v.varyings = vertices_.varyings[tri[i]];
            const ScreenVertex& s = vertices_.screen[tri[i]];
            v.depth = s.depth;
            v.column = s.column;
            v.row = s.row;
        }
        const bool perspective = perspective_weights(in_.scene, in_.options);
        if (in_parts_) return set_up_clipped_in_parts(tri, centroid, inside_image, polygon, outcome);
        if (in_.scene.shader == Shader::gouraud) {
            // Before clipping, so that clipped corners interpolate lit colours.
            Varyings<Real>* corners[3] = {&polygon.vertices[0].varyings, &polygon.vertices[1].varyings,
                                          &polygon.vertices[2].varyings};
            counts_.lit_points += light_corners(corners, centroid);
        }
        const ClipOutcome clipped = clip_to_view(polygon, in_.view, perspective);
        if (clipped != ClipOutcome::kept) return clipped;
        draw_fan(polygon, centroid, outcome, nullptr);
        if (!inside_image) ++counts_.clipped;
        if (!outcome.drawn && outcome.has_area) {
            outcome.meets_image = meets_image(polygon, in_.view.frame.rows, in_.view.frame.columns);
        }
        return ClipOutcome::kept;
    }

    /// Whether a corner's depth can be drawn in Real: the fill weights each
    /// corner by 1/z_c and divides by their sum, so beyond kMaxDrawableDepth
    /// those weights underflow and the sum's inverse overflows (in float, a
    /// depth past 3.4e38 is infinite outright), and the pixels would be NaN.
    /// A corner behind the eye (negative depth, however far) is left to the
    /// near-plane clipping, which skips what it cannot represent. A NaN depth
    /// (a position whose transform overflowed) fails both tests: out of range.
    static bool within_drawable_depth(const ScreenVertex& corner) {
        return corner.depth <= kMaxDrawableDepth<Real> || corner.depth < 0.0;
    }

    /// `colour_parts`: textured Gouraud, the same polygon clipped with each
    /// corner's A in `color`, which becomes the draws' lit[i]; else null.
    void draw_fan(const ClipPolygon<Real>& polygon, const Vec3<Real>& centroid, PiecesOutcome& outcome,
                  const ClipPolygon<Real>* colour_parts) {
        const Varyings<Real>* stored[8] = {};  // the polygon's corners, stored once the first piece is drawn
        for (std::size_t k = 1; k + 1 < polygon.count; ++k) {
            const std::size_t index[3] = {0, k, k + 1};
            Corner<Real> corner[3];
            for (int i = 0; i < 3; ++i) {
                const ClipVertex<Real>& v = polygon.vertices[index[i]];
                corner[i] = {v.column, v.row, v.depth, &v.varyings};
            }
            const bool first = !outcome.drawn;
            FillTriangle<Real> draw;
            int order[3];
            if (!set_up_piece(corner, centroid, draw, outcome, order)) continue;
            if (first) {
                for (std::size_t i = 0; i < polygon.count; ++i) stored[i] = clip_vertices_.push(polygon.vertices[i].varyings);
            }
            for (int i = 0; i < 3; ++i) draw.v[i] = stored[index[order[i]]];
            if (colour_parts != nullptr) {
                for (int i = 0; i < 3; ++i) draw.lit[i] = colour_parts->vertices[index[order[i]]].varyings.color;
            }
            out_.push_back(draw);
        }
    }

    // Textured Gouraud (contract "Texture maps": A and S at each vertex, both
    // interpolated, the pixel T x A + S). The draw's lit[i] is the corner's A;
    // its varyings carry S in `color` and (s, t) in `lit`. A face without a
    // texture carries its whole lit colour in lit[i], as untextured Gouraud does.

    /// Whether the triangle being set up draws its material's texture.
    bool textured_face() const { return in_.textures[surface_].texels != nullptr; }

    void set_up_whole_in_parts(const Triangle& tri, const Vec3<Real>& centroid, const int (&order)[3],
                               FillTriangle<Real>& draw) {
        if (in_.options.light_vectors != LightVectors::triangle_centroid) {
            // Exact vectors: each vertex was lit once (light_vertices_in_parts), S already in its `color`.
            for (int i = 0; i < 3; ++i) draw.lit[i] = in_.vertex_colour_parts[tri[order[i]]];
            return;
        }
        Varyings<Real> corners[3] = {*draw.v[0], *draw.v[1], *draw.v[2]};
        Vec3<Real> colour_parts[3];
        counts_.lit_points += light_corners_in_parts(corners, centroid, colour_parts);
        for (int i = 0; i < 3; ++i) draw.lit[i] = colour_parts[i];
        if (!textured_face()) return;  // the corners' varyings are unchanged: the mesh's serve
        // S depends on the triangle (its centroid's vectors): the corners are the triangle's own.
        for (int i = 0; i < 3; ++i) draw.v[i] = clip_vertices_.push(corners[i]);
    }

    /// The polygon is clipped twice: as it is (S in `color`, (s, t) in `lit`)
    /// and with A in `color`. Clipping decides from positions, depths and
    /// sample coordinates alone, which are the same in both, so both give the
    /// same corners with every attribute interpolated alike.
    ClipOutcome set_up_clipped_in_parts(const Triangle& tri, const Vec3<Real>& centroid, bool inside_image,
                                        ClipPolygon<Real>& polygon, PiecesOutcome& outcome) {
        Vec3<Real> colour_parts[3];
        if (in_.options.light_vectors == LightVectors::triangle_centroid) {
            Varyings<Real> corners[3] = {polygon.vertices[0].varyings, polygon.vertices[1].varyings,
                                         polygon.vertices[2].varyings};
            counts_.lit_points += light_corners_in_parts(corners, centroid, colour_parts);
            for (int i = 0; i < 3; ++i) polygon.vertices[i].varyings = corners[i];
        } else {
            for (int i = 0; i < 3; ++i) colour_parts[i] = in_.vertex_colour_parts[tri[i]];
        }
        ClipPolygon<Real> parts = polygon;
        for (int i = 0; i < 3; ++i) parts.vertices[i].varyings.color = colour_parts[i];
        const bool perspective = perspective_weights(in_.scene, in_.options);
        const ClipOutcome clipped = clip_to_view(polygon, in_.view, perspective);
        if (clipped != ClipOutcome::kept) return clipped;
        clip_to_view(parts, in_.view, perspective);  // the same outcome and corners (see above)
        draw_fan(polygon, centroid, outcome, &parts);
        if (!inside_image) ++counts_.clipped;
        if (!outcome.drawn && outcome.has_area) {
            outcome.meets_image = meets_image(polygon, in_.view.frame.rows, in_.view.frame.columns);
        }
        return ClipOutcome::kept;
    }

    /// Seed-Gouraud's corners lit at the centroid's vectors: on a textured
    /// face A into `colour_parts` and S into the corner's `color`; else the
    /// whole lit colour into `colour_parts`, as light_corners() computes it.
    std::uint64_t light_corners_in_parts(Varyings<Real> (&corners)[3], const Vec3<Real>& centroid,
                                         Vec3<Real> (&colour_parts)[3]) const {
        if (!textured_face()) {
            const PointShader<Real>& lighting = shader();
            lighting.compute_vectors(vectors_, centroid);
            for (int i = 0; i < 3; ++i) colour_parts[i] = lighting.shade_prepared(vectors_, corners[i].normal, corners[i].color);
            return 3;
        }
        const PointShader<Real>& colour_part = in_.colour_part_shaders[surface_];
        const PointShader<Real>& specular_part = in_.specular_part_shaders[surface_];
        colour_part.compute_vectors(vectors_, centroid);
        for (int i = 0; i < 3; ++i) {
            Varyings<Real>& v = corners[i];
            colour_parts[i] = colour_part.shade_prepared(vectors_, v.normal, v.color);
            v.color = specular_part.shade_prepared(vectors_, v.normal, v.color);
        }
        return 3;
    }

    /// The colour every point lights to, when that does not depend on the
    /// point: one surface colour and no term that depends on where (only
    /// ambient, or nothing), evaluated by the specialised shader, which then
    /// computes exactly this at every vertex, corner and centroid. Flat and
    /// Gouraud's corners then take it without reading any vertex.
    std::optional<Vec3<Real>> same_lit_everywhere() const {
        // One colour per material, or A and S apart on textured faces: lit per triangle.
        if (in_.triangle_surfaces != nullptr || in_.textures != nullptr) return std::nullopt;
        if (!in_.shader.specialized || in_.shader.effects.normals || !in_.fill_constants.uniform_color) return std::nullopt;
        return in_.shader.shade_prepared(vectors_, Vec3<Real>(Real(0)), in_.fill_constants.color);
    }

    /// Whether the shaders that light this triangle's points (its flat colour,
    /// the seed's Gouraud corners; not Phong, whose fill kernel, chosen per
    /// frame, may read the centroid) read the centroid and normals; an ambient-only
    /// scene's do not, and then neither is formed (flat ambient's walk on the
    /// 1.3M sphere, 1 thread, `--stages`: 75-87 ms before, 70 after, Phong
    /// ambient's 67).
    bool lights_at_points_read_them() const {
        if (in_.textures != nullptr && textured_face()) {
            return in_.colour_part_shaders[surface_].reads_position_and_normal() ||
                   in_.specular_part_shaders[surface_].reads_position_and_normal();
        }
        return shader().reads_position_and_normal();
    }

    // Flat: one colour per triangle, lit at the centroid with the mean vertex
    // normal (renormalised) and the mean vertex colour.
    Vec3<Real> flat_color(const Triangle& tri, const Vec3<Real>& centroid, const PointShader<Real>& lighting) const {
        Vec3<Real> normal(Real(0)), color(Real(0));
        const bool reads_normal = lighting.reads_position_and_normal();
        for (std::uint32_t index : tri) {
            if (reads_normal) normal += vertices_.varyings[index].normal;
            color += vertices_.varyings[index].color;
        }
        const Vec3<Real> surface = in_.fill_constants.uniform_color ? in_.fill_constants.color : color / Real(3);
        if (!reads_normal) return lighting.shade_unlit(vectors_, surface);  // the same terms, no call
        return lighting(vectors_, centroid, safe_normalize<Real>(normal), surface);
    }

    // Gouraud with the seed's centroid vectors: lights the triangle's own
    // corners. Returns the points lit (none for exact vectors, whose `lit`
    // came from light_vertices()).
    std::uint64_t light_corners(Varyings<Real>* const corners[3], const Vec3<Real>& centroid) const {
        if (in_.options.light_vectors != LightVectors::triangle_centroid) return 0;
        const PointShader<Real>& lighting = shader();
        if (!lighting.reads_position_and_normal()) {
            for (int i = 0; i < 3; ++i) corners[i]->lit = lighting.shade_unlit(vectors_, corners[i]->color);
            return 3;
        }
        lighting.compute_vectors(vectors_, centroid);  // the same vectors for all three corners
        for (int i = 0; i < 3; ++i) {
            Varyings<Real>& v = *corners[i];
            v.lit = lighting.shade_prepared(vectors_, v.normal, v.color);
        }
        return 3;
    }

    /// The shader of the triangle being set up: its material's.
    const PointShader<Real>& shader() const {
        return in_.triangle_surfaces != nullptr ? in_.surface_shaders[surface_] : in_.shader;
    }

    std::uint32_t source_ = 0;  ///< the mesh triangle being set up
    std::uint32_t surface_ = 0; ///< its material (index into SetupInput::surface_shaders)
    const SetupInput<Real>& in_;
    const TransformedVertices<Real>& vertices_;
    ChunkVector<FillTriangle<Real>>& out_;
    ClipVertexStore<Real>& clip_vertices_;
    SetupCounts& counts_;
    LightVectorsAt<Real>& vectors_;
    const std::optional<Vec3<Real>> same_lit_;  ///< same_lit_everywhere()
    /// Textured Gouraud: every draw's lit[i] is its corner's A (or whole lit
    /// colour on a face without texture), S and (s, t) are in the corners' varyings.
    const bool in_parts_;
    SeedCornerBatch<Real>* seed_batch_ = nullptr;  ///< batch_seed_corners()
};

/// Records where the draws of the triangle just set up are, and its painter's-order key.
template <typename Real>
void record_drawn(const ChunkVector<FillTriangle<Real>>& out, std::size_t first, std::size_t chunk,
                  std::uint64_t key, ChunkVector<DrawSpan>& drawn, ChunkVector<std::uint64_t>& keys) {
    const std::size_t count = out.size() - first;
    // Bands fit 16 bits: images are at most kMaxSampleSide = 2^19 samples high.
    drawn.push_back(count == 1 ? DrawSpan::one(chunk, first, out[first].coverage.row_min / kBandRows,
                                                    out[first].coverage.row_max / kBandRows)
                               : DrawSpan::several(chunk, first, static_cast<int>(count)));
    keys.push_back(key);
}

void add_counts(const SetupCounts& counts, RenderStats& stats) {
    stats.triangles_culled += counts.culled;
    stats.triangles_dropped += counts.dropped;
    stats.triangles_clipped += counts.clipped;
    stats.triangles_outside += counts.outside;
    stats.triangles_out_of_range += counts.out_of_range;
    stats.triangles_between_samples += counts.between_samples;
    stats.triangles_degenerate += counts.degenerate;
    stats.triangles_drawn += counts.drawn;
}

}  // namespace

/// What the coverage screen reads of set-up's input.
template <typename Real>
CoverageScreenInput coverage_screen_input(const SetupInput<Real>& input) {
    CoverageScreenInput screen;
    screen.triangles = input.scene.mesh.triangles.data();
    screen.screen = input.vertices.screen.data();
    screen.column_offset = input.view.sample_offset.x;
    screen.row_offset = input.view.sample_offset.y;
    screen.columns = input.view.frame.columns;
    screen.rows = input.view.frame.rows;
    screen.min_depth = std::max(input.view.near_depth, std::numeric_limits<double>::denorm_min());
    screen.max_depth = kMaxDrawableDepth<Real>;
    return screen;
}

/// The coverage screen's verdicts on a chunk's triangles, a block at a time
/// as they are asked for. Where it decides few (a mesh of triangles larger
/// than a sample, which set-up keeps), screening would cost more than it
/// saves: after such a block the next kRestBlocks blocks are left to set-up.
class ScreenedBlock {
public:
    /// A block pays when it decides at least this share of its triangles.
    static constexpr std::size_t kWorthShare = 4;  // 1 in 4
    static constexpr std::size_t kRestBlocks = 8;

    /// With `tiny`, tiny covered triangles are found too (ScreenVerdict::tiny_covered).
    ScreenedBlock(const CoverageScreenInput& input, std::size_t end, TinyCoverageBlock* tiny = nullptr)
        : input_(input), end_(end), tiny_(tiny) {}
    ScreenVerdict verdict(std::size_t t) {
        if (t >= block_end_ || t < block_begin_) screen_from(t);
        return verdicts_[t - block_begin_];
    }
    /// The coverage of triangle t, whose verdict() was tiny_covered.
    void tiny_coverage(std::size_t t, TinyCoverage& out) const { tiny_->get(t - block_begin_, out); }

private:
    void screen_from(std::size_t t) {
        block_begin_ = t;
        block_end_ = std::min(end_, t + kScreenBlock);
        if (t < resume_at_) {
            std::fill(verdicts_, verdicts_ + (block_end_ - block_begin_), ScreenVerdict::set_up);
            return;
        }
        screen_coverage_dispatched(input_, block_begin_, block_end_, verdicts_, tiny_);
        const std::size_t decided = static_cast<std::size_t>(std::count_if(
            verdicts_, verdicts_ + (block_end_ - block_begin_), [](ScreenVerdict v) { return v != ScreenVerdict::set_up; }));
        if (decided * kWorthShare < block_end_ - block_begin_) resume_at_ = block_end_ + kRestBlocks * kScreenBlock;
    }

    const CoverageScreenInput& input_;
    std::size_t end_;
    TinyCoverageBlock* tiny_;
    std::size_t block_begin_ = 0, block_end_ = 0;
    std::size_t resume_at_ = 0;  ///< no screening before this triangle
    ScreenVerdict verdicts_[kScreenBlock];
};

template <typename Real>
void set_up_triangle(const SetupInput<Real>& input, std::uint32_t source, ChunkVector<FillTriangle<Real>>& out,
                     ClipVertexStore<Real>& clip_vertices, SetupCounts& counts, LightVectorsAt<Real>& vectors) {
    TriangleSetup<Real>(input, out, clip_vertices, counts, vectors).run(source);
}

/// New chunk vectors for `chunks` chunks (more than the list has): in one
/// huge-page arena when the frame is small enough (chunk_arena.hpp), else
/// on the heap as any vector. The old vectors go first: they may hold slots.
template <typename Real>
void make_chunk_vectors(DrawList<Real>& draws, std::size_t chunks) {
    draws.chunk_draws.clear();
    draws.chunk_drawn.clear();
    draws.chunk_keys.clear();
    draws.chunk_mapped.clear();  // new storage, possibly at a freed one's address: nothing mapped yet
    draws.arena.reset(chunks, {kSetupChunk * sizeof(FillTriangle<Real>), kSetupChunk * sizeof(DrawSpan),
                               kSetupChunk * sizeof(std::uint64_t)});
    draws.chunk_draws.reserve(chunks);
    draws.chunk_drawn.reserve(chunks);
    draws.chunk_keys.reserve(chunks);
    for (std::size_t chunk = 0; chunk < chunks; ++chunk) {
        draws.chunk_draws.emplace_back(SlotAllocator<FillTriangle<Real>>(draws.arena.slot(chunk, 0)));
        draws.chunk_drawn.emplace_back(SlotAllocator<DrawSpan>(draws.arena.slot(chunk, 1)));
        draws.chunk_keys.emplace_back(SlotAllocator<std::uint64_t>(draws.arena.slot(chunk, 2)));
    }
}

template <typename Real>
void set_up_triangles(const SetupInput<Real>& input, DrawList<Real>& draws, RenderStats& stats,
                      ProgressMonitor& progress) {
    const std::vector<Triangle>& triangles = input.scene.mesh.triangles;
    // Smaller chunks only for a mesh of fewer than kTasksPerThread x kSetupChunk triangles per thread,
    // about kTasksPerThread chunks per thread then: a chunk's number fits DrawSpan's 17 bits.
    const std::size_t chunk_triangles = items_per_task(
        triangles.size(), tbb::this_task_arena::max_concurrency(), kSetupChunk, kSmallestSetupChunk);
    const std::size_t chunks = (triangles.size() + chunk_triangles - 1) / chunk_triangles;
    assert(chunks <= (std::size_t(1) << (32 - DrawSpan::kFirstBits)));
    if (draws.chunk_draws.size() < chunks) make_chunk_vectors(draws, chunks);
    if (draws.chunk_clip_vertices.size() < chunks) draws.chunk_clip_vertices.resize(chunks);
    if (draws.chunk_vectors.size() < chunks) draws.chunk_vectors.resize(chunks);
    if (draws.chunk_mapped.size() < chunks) draws.chunk_mapped.resize(chunks);
    draws.chunk_counts.assign(chunks, SetupCounts{});
    draws.chunks = chunks;
    const FrameVector<ScreenVertex>& screen = input.vertices.screen;
    const bool mapped = draws.arena.mapped();  // huge pages: no 4 KiB map-ahead
    const CoverageScreenInput screen_input = coverage_screen_input(input);
    progress.begin_stage(0.1, 0.35, chunks);
    tbb::parallel_for(std::size_t(0), chunks, [&](std::size_t chunk) {
        if (progress.cancelled()) return;
        const std::size_t begin = chunk * chunk_triangles;
        const std::size_t end = std::min(triangles.size(), begin + chunk_triangles);
        // The chunk's vectors and counts are moved here for the loop and back
        // after it: in the list, two chunks' vector headers and counts share
        // cache lines, and each triangle writes them (a vector's end, a
        // count). Two threads writing one line made set-up 3x slower at 2
        // threads than at 1 on spot (512², docs/performance.md "Where the
        // time goes now").
        ChunkVector<FillTriangle<Real>> out = std::move(draws.chunk_draws[chunk]);
        ChunkVector<DrawSpan> drawn = std::move(draws.chunk_drawn[chunk]);
        ChunkVector<std::uint64_t> keys = std::move(draws.chunk_keys[chunk]);
        ClipVertexStore<Real> clip_vertices = std::move(draws.chunk_clip_vertices[chunk]);
        LightVectorsAt<Real> vectors = std::move(draws.chunk_vectors[chunk]);
        SetupCounts counts;
        // Room for every triangle of the chunk, its pages mapped a step
        // ahead of the writes (RecordPages) rather than all at once:
        // triangles that cover no sample, lie outside the view or are culled
        // leave their records unwritten (a fifth of the 8M-triangle mesh's),
        // and mapping those would add to the peak memory.
        // In the arena, the whole slot at once: a later frame's larger last
        // chunk must not outgrow it onto the heap.
        const std::size_t room = mapped ? kSetupChunk : end - begin;
        out.clear();
        out.reserve(room);
        drawn.clear();
        drawn.reserve(room);
        keys.clear();
        keys.reserve(room);
        clip_vertices.clear();
        TriangleSetup<Real> setup(input, out, clip_vertices, counts, vectors);
        SeedCornerBatch<Real> seed_batch;
        setup.batch_seed_corners(seed_batch);
        RecordPages<FillTriangle<Real>> pages(draws.chunk_mapped[chunk]);
        const bool screened = setup.screens();
        ScreenedBlock screening(screen_input, end);
        for (std::size_t t = begin; t < end; ++t) {
            if (screened) {
                const ScreenVerdict verdict = screening.verdict(t);
                if (verdict != ScreenVerdict::set_up) {
                    setup.count_screened(verdict);
                    continue;
                }
            }
            if (!mapped) pages.map_ahead(out, end - t);
            const std::size_t first = out.size();
            setup.run(static_cast<std::uint32_t>(t));
            if (out.size() == first) continue;
            record_drawn(out, first, chunk, painter_key(triangles[t], screen), drawn, keys);
        }
        setup.light_batched_corners();
        if (!mapped) pages.release_unwritten(out);
        // Equal allocators (the same slot): each vector's storage moves back as it is.
        draws.chunk_draws[chunk] = std::move(out);
        draws.chunk_drawn[chunk] = std::move(drawn);
        draws.chunk_keys[chunk] = std::move(keys);
        draws.chunk_clip_vertices[chunk] = std::move(clip_vertices);
        draws.chunk_vectors[chunk] = std::move(vectors);
        draws.chunk_counts[chunk] = counts;
        progress.piece_done();
    });
    progress.throw_if_cancelled();
    for (std::size_t chunk = 0; chunk < chunks; ++chunk) add_setup_counts(input, draws.chunk_counts[chunk], stats);
}

/// How many triangles ahead set_up_and_fill() asks for what it will read.
constexpr std::size_t kDirectAhead = 16;

/// How far outside its corners' rows a triangle may cover a sample: a
/// sample's centre is half a row below its row number, and snapping moves a
/// corner by at most 1/512 (raster.hpp); a clipped piece lies inside the
/// triangle. Two rows leave room to spare.
constexpr double kCoverageReach = 2.0;

void split_rows_by_triangles(const std::vector<Triangle>& triangles, const FrameVector<ScreenVertex>& screen,
                             int rows, int parts, std::vector<double>& work, RowSplit& split) {
    parts = std::max(1, std::min(parts, rows));
    split.starts.assign(1, 0);
    if (parts > 1) {
        // The work per row, from a sample of triangles: each costs about as
        // much as kSetupSamples samples at its first corner's row, plus its
        // area spread evenly over the rows it spans (a difference array).
        constexpr std::size_t kSample = 4096;
        constexpr double kSetupSamples = 32.0;
        const std::size_t step = std::max<std::size_t>(1, triangles.size() / kSample);
        work.assign(static_cast<std::size_t>(rows) + 1, 0.0);
        const double last_row = rows - 1;
        for (std::size_t t = 0; t < triangles.size(); t += step) {
            const ScreenVertex& a = screen[triangles[t][0]];
            const ScreenVertex& b = screen[triangles[t][1]];
            const ScreenVertex& c = screen[triangles[t][2]];
            // Left out: a corner not in front of the eye (NaN) and a triangle off the image.
            if (!(std::isfinite(a.row) && std::isfinite(b.row) && std::isfinite(c.row))) continue;
            const double top = std::min({a.row, b.row, c.row}), bottom = std::max({a.row, b.row, c.row});
            if (!(bottom >= 0.0 && top <= last_row)) continue;
            const double first = std::clamp(a.row, 0.0, last_row);
            work[static_cast<std::size_t>(first)] += kSetupSamples;
            work[static_cast<std::size_t>(first) + 1] -= kSetupSamples;
            const double area = 0.5 * std::abs((b.column - a.column) * (c.row - a.row) -
                                               (c.column - a.column) * (b.row - a.row));
            const std::size_t from = static_cast<std::size_t>(std::max(top, 0.0));
            const std::size_t to = static_cast<std::size_t>(std::min(bottom, last_row)) + 1;
            const double per_row = std::min(area, 1e12) / (bottom - top + 1.0);
            if (!std::isfinite(per_row)) continue;
            work[from] += per_row;
            work[to] -= per_row;
        }
        // Per row, then running totals: work[r] = the work of rows [0, r].
        double density = 0.0, total = 0.0;
        for (int r = 0; r < rows; ++r) {
            density += work[static_cast<std::size_t>(r)];
            total += std::max(density, 0.0);
            work[static_cast<std::size_t>(r)] = total;
        }
        std::size_t row = 0;
        for (int p = 1; p < parts; ++p) {
            // The first row whose running total passes p / parts of the work: equal rows when there is none.
            const double share = total * p / parts;
            if (total > 0.0) {
                while (row < static_cast<std::size_t>(rows) && work[row] <= share) ++row;
            } else {
                row = static_cast<std::size_t>(rows) * static_cast<std::size_t>(p) / static_cast<std::size_t>(parts);
            }
            const int start = std::max(split.starts.back() + 1, static_cast<int>(row));
            if (start > rows - (parts - p)) break;  // leave a row for each part after it
            split.starts.push_back(start);
        }
    }
    split.starts.push_back(rows);
}

template <typename Real>
void set_up_and_fill(const SetupInput<Real>& input, const DirectFill<Real>& fill, const RowSplit& split, int part,
                     DirectScratch<Real>& scratch, ProgressMonitor& progress) {
    const std::vector<Triangle>& triangles = input.scene.mesh.triangles;
    const std::size_t chunks = std::min(fill.end_chunk, (triangles.size() + kSetupChunk - 1) / kSetupChunk);
    const FrameVector<ScreenVertex>& screen = input.vertices.screen;
    ChunkVector<FillTriangle<Real>>& out = scratch.draws;
    out.clear();
    // A clipped triangle's fan has at most 6 pieces, and seed Gouraud queues up
    // to kSeedBatch triangles (below): no allocation per triangle.
    out.reserve(6 * kSeedBatch);
    ClipVertexStore<Real>& clip_vertices = scratch.clip_vertices;
    // The triangles this part owns are counted; the others it sets up only to fill their rows here.
    scratch.counts = SetupCounts{};
    scratch.tiny_draws = 0;
    SetupCounts counted_elsewhere;
    TriangleSetup<Real> owned_setup(input, out, clip_vertices, scratch.counts, scratch.vectors);
    TriangleSetup<Real> shared_setup(input, out, clip_vertices, counted_elsewhere, scratch.vectors);
    const bool whole_image = split.parts() == 1;
    const std::size_t part_index = static_cast<std::size_t>(part);
    const int first_row = split.starts[part_index], end_row = split.starts[part_index + 1];
    // A triangle whose corners all lie this far above or below the part's rows covers none of them.
    const double reach_begin = first_row - kCoverageReach, reach_end = end_row + kCoverageReach;
    FillTarget<Real>& target = *fill.target;
    const FrameVector<Varyings<Real>>& varyings = input.vertices.varyings;
    const double columns = target.image.columns;
    const std::size_t row_length = static_cast<std::size_t>(target.image.columns);
    // Seed Gouraud lights the corners of several triangles at once: their
    // draws wait in `out` (queued below) until then, and are filled in mesh order.
    SeedCornerBatch<Real> seed_batch;
    const bool batched = owned_setup.batch_seed_corners(seed_batch) && shared_setup.batch_seed_corners(seed_batch);
    // A triangle's painter's rank (FillTarget::key, tie), when the fill ranks.
    struct Rank {
        std::uint64_t key = 0;
        std::uint32_t tie = 0;
    };
    const auto rank_of = [&](std::size_t t, const Triangle& tri) {
        Rank rank;
        if (fill.ranked) {
            rank.key = painter_key(tri, screen);
            rank.tie = fill.original_triangle != nullptr ? fill.original_triangle[t] : static_cast<std::uint32_t>(t);
        }
        return rank;
    };
    const auto rank_target = [&](const Rank& rank) {
        if (fill.ranked) {
            target.key = rank.key;
            target.tie = rank.tie;
        }
    };
    // A queued triangle is its draws in `out`, or a tiny one (tiny_queue).
    struct QueuedTriangle {
        std::size_t first_draw, end_draw;
        Rank rank;
        int tiny;  ///< index in tiny_queue, or -1
    };
    QueuedTriangle queue[kSeedBatch];
    TinyDraw<Real> tiny_queue[kSeedBatch];
    std::size_t queued = 0, tiny_queued = 0;
    const auto fill_queued = [&] {
        owned_setup.light_batched_corners();  // both share seed_batch: lights every queued draw
        for (std::size_t q = 0; q < queued; ++q) {
            rank_target(queue[q].rank);
            if (queue[q].tiny >= 0) {
                fill.tiny_kernel(tiny_queue[queue[q].tiny], target, *fill.constants);
                continue;
            }
            for (std::size_t d = queue[q].first_draw; d < queue[q].end_draw; ++d) {
                fill.kernel(out[d], target, *fill.vectors, *fill.constants);
            }
        }
        scratch.tiny_draws += tiny_queued;
        queued = 0;
        tiny_queued = 0;
        out.clear();
        clip_vertices.clear();
    };
    const CoverageScreenInput screen_input = coverage_screen_input(input);
    const bool screened = owned_setup.screens();
    // Tiny covered triangles straight from the screen to the fill, where
    // the kernel has a TinyDraw twin and set-up would take the corners'
    // values as they are: Gouraud's lit per vertex, Phong's vertex colours;
    // or lit as run() lights them: flat's colour, the seed's Gouraud corners
    // (queued with the batch, as set-up's draws are).
    const bool gouraud = input.scene.shader == Shader::gouraud, flat = input.scene.shader == Shader::flat;
    const bool fills_tiny = screened && fill.tiny_kernel != nullptr &&
                            (!gouraud || owned_setup.lit_per_vertex() || batched) &&
                            (!flat || input.textures == nullptr);
    const Vec3<Real>* const same_lit = owned_setup.same_lit();
    TinyCoverageBlock tiny_block;
    TinyDraw<Real> tiny;
    tiny.surface = 0;
    Vec3<Real> flat_colour(Real(0));
    for (std::size_t chunk = fill.first_chunk; chunk < chunks && !progress.cancelled(); ++chunk) {
        const std::size_t end = std::min(triangles.size(), (chunk + 1) * kSetupChunk);
        ScreenedBlock screening(screen_input, end, fills_tiny ? &tiny_block : nullptr);
        for (std::size_t t = chunk * kSetupChunk; t < end; ++t) {
            const Triangle& tri = triangles[t];
            bool owned = true;
            if (!whole_image) {
                // NaN rows (a corner not in front of the eye) compare false: such a triangle is never skipped.
                const double r0 = screen[tri[0]].row, r1 = screen[tri[1]].row, r2 = screen[tri[2]].row;
                const bool apart = (r0 < reach_begin && r1 < reach_begin && r2 < reach_begin) ||
                                   (r0 > reach_end && r1 > reach_end && r2 > reach_end);
                owned = split.owner(r0) == part;
                if (apart && !owned) continue;
            }
            if (t + kDirectAhead < triangles.size()) {
                // The samples a triangle of a large mesh covers lie next to its
                // first corner: ask for their ranks and pixels, and for the corners'
                // varyings, a few triangles ahead (most are a cache miss each).
                const Triangle& ahead = triangles[t + kDirectAhead];
                const ScreenVertex& corner = screen[ahead[0]];
                if (corner.row >= first_row && corner.row < end_row && corner.column >= 0.0 &&
                    corner.column < columns) {
                    const std::size_t at = static_cast<std::size_t>(corner.row) * row_length +
                                           static_cast<std::size_t>(corner.column);
                    // And the row below: a triangle of a pixel or two often covers two rows.
                    const std::size_t below = corner.row + 1.0 < end_row ? at + row_length : at;
                    if (target.rank_keys != nullptr) {
                        prefetch_address(target.rank_keys + at);
                        prefetch_address(target.rank_keys + below);
                    }
                    prefetch_address(target.image.pixels.data() + at);
                    prefetch_address(target.image.pixels.data() + below);
                }
                // Not for a triangle another walk fills: its varyings are that walk's reads.
                const bool reaches_here = whole_image || (corner.row >= reach_begin && corner.row <= reach_end);
                if (fill.reads_varyings && reaches_here) {
                    for (std::uint32_t vertex : ahead) prefetch_object(&varyings[vertex]);
                }
            }
            if (screened) {
                const ScreenVerdict verdict = screening.verdict(t);
                if (verdict == ScreenVerdict::tiny_covered) {
                    if (owned) owned_setup.count_drawn();
                    screening.tiny_coverage(t, tiny.coverage);
                    const std::uint32_t corners[3] = {tri[0], tiny.coverage.swapped ? tri[2] : tri[1],
                                                      tiny.coverage.swapped ? tri[1] : tri[2]};
                    for (int i = 0; i < 3; ++i) {
                        const Varyings<Real>& v = varyings[corners[i]];
                        tiny.corner[i] = !gouraud ? &v.color : same_lit != nullptr ? same_lit : &v.lit;
                        tiny.depth[i] = static_cast<Real>(screen[corners[i]].depth);
                    }
                    if (flat) {
                        flat_colour = (owned ? owned_setup : shared_setup).flat_lit(static_cast<std::uint32_t>(t));
                        tiny.corner[0] = &flat_colour;
                    }
                    if (input.triangle_surfaces != nullptr) tiny.surface = input.triangle_surfaces[t];
                    const Rank rank = rank_of(t, tri);
                    if (batched) {
                        // The seed's corners: lit with the batch, filled in turn with the queued draws.
                        const Varyings<Real>* const corner_varyings[3] = {&varyings[corners[0]], &varyings[corners[1]],
                                                                          &varyings[corners[2]]};
                        const std::size_t slot = (owned ? owned_setup : shared_setup)
                                                     .batch_tiny_corners(static_cast<std::uint32_t>(t), corner_varyings);
                        TinyDraw<Real>& queued_tiny = tiny_queue[tiny_queued];
                        queued_tiny = tiny;
                        for (int i = 0; i < 3; ++i) queued_tiny.corner[i] = seed_batch.lit(slot) + i;
                        queue[queued++] = {0, 0, rank, static_cast<int>(tiny_queued++)};
                        if (queued == kSeedBatch) fill_queued();
                        continue;
                    }
                    rank_target(rank);
                    fill.tiny_kernel(tiny, target, *fill.constants);
                    ++scratch.tiny_draws;
                    continue;
                }
                if (verdict != ScreenVerdict::set_up) {
                    if (owned) owned_setup.count_screened(verdict);
                    continue;
                }
            }
            if (!batched) {
                out.clear();
                clip_vertices.clear();  // the draws pointing there are filled before the next triangle
            }
            const std::size_t first_draw = out.size();
            (owned ? owned_setup : shared_setup).run(static_cast<std::uint32_t>(t));
            if (out.size() == first_draw) continue;
            const Rank rank = rank_of(t, tri);
            if (batched) {
                queue[queued++] = {first_draw, out.size(), rank, -1};
                if (queued == kSeedBatch) fill_queued();
                continue;
            }
            rank_target(rank);
            for (const FillTriangle<Real>& draw : out) fill.kernel(draw, target, *fill.vectors, *fill.constants);
        }
        if (batched) fill_queued();
        progress.piece_done();
    }
}

template <typename Real>
void add_setup_counts(const SetupInput<Real>& input, const SetupCounts& counts, RenderStats& stats) {
    add_counts(counts, stats);
    count_term_evaluations(input.scene, input.options, input.shader.effects, counts.lit_points,
                           LitPoints::outside_the_fill, stats);
}

#define PHONGRAST_INSTANTIATE_SETUP(Real)                                                                       \
    template void set_up_triangles<Real>(const SetupInput<Real>&, DrawList<Real>&, RenderStats&,                \
                                         ProgressMonitor&);                                                     \
    template void set_up_and_fill<Real>(const SetupInput<Real>&, const DirectFill<Real>&, const RowSplit&, int,  \
                                        DirectScratch<Real>&, ProgressMonitor&);                                 \
    template void add_setup_counts<Real>(const SetupInput<Real>&, const SetupCounts&, RenderStats&);             \
    template void set_up_triangle<Real>(const SetupInput<Real>&, std::uint32_t, ChunkVector<FillTriangle<Real>>&, \
                                        ClipVertexStore<Real>&, SetupCounts&, LightVectorsAt<Real>&);
PHONGRAST_INSTANTIATE_SETUP(float)
PHONGRAST_INSTANTIATE_SETUP(double)
#undef PHONGRAST_INSTANTIATE_SETUP

}  // namespace phongrast::detail
