// Scene assembly: objects placed by their model matrices, mirrors reversed,
// normals per object in world space (computed, or the file's through the
// inverse transpose), materials resolved per face by the contract's
// precedence, and vertices split where one position carries different
// per-corner values, so that the per-vertex pipeline draws it unchanged.
#include "scene_assembly.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "finite.hpp"

namespace phongrast::detail {
namespace {

/// One object as assembly sees it: a `mesh` scene is object 0 with the identity.
struct SourceObject {
    const Mesh* mesh;
    glm::dmat4 transform;
    MaterialFields material;
    NormalSource normals;
    std::string label;  ///< "objects[2]" or "mesh", for messages
};

std::vector<SourceObject> source_objects(const Scene& scene) {
    std::vector<SourceObject> sources;
    if (scene.objects.empty()) {
        sources.push_back({&scene.mesh, glm::dmat4(1.0), MaterialFields{}, scene.normals, "mesh"});
        return sources;
    }
    sources.reserve(scene.objects.size());
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const SceneObject& object = scene.objects[i];
        sources.push_back({object.mesh.get(), object.transform, object.material, object.normals.value_or(scene.normals),
                           "objects[" + std::to_string(i) + "]"});
    }
    return sources;
}

bool same_texture(const std::optional<TextureMap>& a, const std::optional<TextureMap>& b) {
    if (a.has_value() != b.has_value()) return false;
    if (!a) return true;
    return a->image == b->image && a->wrap_s == b->wrap_s && a->wrap_t == b->wrap_t;
}

bool same_surface(const Surface& a, const Surface& b) {
    return a.material.ka == b.material.ka && a.material.kd == b.material.kd && a.material.ks == b.material.ks &&
           a.material.n == b.material.n && a.color_factor == b.color_factor && same_texture(a.texture, b.texture);
}

std::uint32_t surface_id(std::vector<Surface>& surfaces, const Surface& surface) {
    for (std::size_t i = 0; i < surfaces.size(); ++i) {
        if (same_surface(surfaces[i], surface)) return static_cast<std::uint32_t>(i);
    }
    surfaces.push_back(surface);
    return static_cast<std::uint32_t>(surfaces.size() - 1);
}

/// The surface of a face whose mesh material is `face` (kNoIndex: none);
/// `has_texcoords` false drops the texture (contract: such a face has T = 1).
Surface resolve_surface(const Scene& scene, const SourceObject& object, std::uint32_t face, bool has_texcoords) {
    MaterialFields fields = object.material.or_else(scene.material_fields);
    Surface surface;
    if (face != kNoIndex) {
        const FaceMaterial& material = object.mesh->materials[face];
        fields = fields.or_else(material.coefficients);
        surface.color_factor = material.color_factor;
        if (has_texcoords) surface.texture = material.texture;
    }
    surface.material = fields.over(scene.material);
    return surface;
}

bool is_identity(const glm::dmat4& m) { return m == glm::dmat4(1.0); }

/// What distinguishes two render vertices made from one position.
struct CornerKey {
    std::uint32_t texcoord, normal, surface;
    bool operator==(const CornerKey& o) const {
        return texcoord == o.texcoord && normal == o.normal && surface == o.surface;
    }
};

/// Appends one object to `out`.
class ObjectAssembler {
public:
    ObjectAssembler(const Scene& scene, const SourceObject& object, AssembledScene& out, NormalsScratch& scratch)
        : scene_(scene), object_(object), mesh_(*object.mesh), out_(out), scratch_(scratch) {}

    void run(std::vector<glm::vec3>& out_colors, std::vector<glm::vec3>& out_normals,
             std::vector<std::uint32_t>& out_vertex_surfaces, std::vector<std::uint32_t>& out_triangle_surfaces) {
        const std::size_t count = mesh_.positions.size();
        const glm::dmat4& m = object_.transform;
        const bool identity = is_identity(m);
        const bool mirror = glm::determinant(glm::dmat3(m)) < 0.0;
        world_.resize(count);
        for (std::size_t i = 0; i < count; ++i) {
            world_[i] = identity ? mesh_.positions[i] : glm::dvec3(m * glm::dvec4(mesh_.positions[i], 1.0));
            if (!all_finite(world_[i])) {
                throw std::invalid_argument(object_.label + ".transform: takes vertex " + std::to_string(i) +
                                            " to a non-finite position");
            }
        }
        // Each object's own triangles, reversed under a mirror, give its normals.
        triangles_ = mesh_.triangles;
        if (mirror) {
            for (Triangle& t : triangles_) std::swap(t[0], t[2]);
        }
        calculate_normals_into(world_, triangles_, scratch_, computed_);

        const bool use_texcoords = !mesh_.texcoord_triangles.empty();
        const bool use_file_normals = object_.normals == NormalSource::file && !mesh_.file_normal_triangles.empty();
        const glm::dmat3 normal_matrix = glm::transpose(glm::inverse(glm::dmat3(m)));

        // Surfaces by face material (+1: none), with and without texture coordinates.
        const std::size_t materials = mesh_.materials.size();
        std::vector<std::uint32_t> surface_of(2 * (materials + 1), kNoIndex);
        const auto face_surface = [&](std::uint32_t face, bool has_texcoords) {
            const std::size_t slot = (face == kNoIndex ? materials : face) * 2 + (has_texcoords ? 1 : 0);
            if (surface_of[slot] == kNoIndex) {
                surface_of[slot] = surface_id(out_.surfaces, resolve_surface(scene_, object_, face, has_texcoords));
            }
            return surface_of[slot];
        };

        const std::uint32_t base = static_cast<std::uint32_t>(out_.scene.mesh.positions.size());
        // A position no triangle uses keeps this placeholder (assemble_scene() makes it 0): resolving a
        // material for it would add one that no face uses to the effect set.
        const std::uint32_t default_surface = kNoIndex;
        // Vertex base + p is the first variant of position p; further variants are appended.
        keys_.assign(count, CornerKey{kNoIndex, kNoIndex, default_surface});
        used_.assign(count, 0);
        next_.assign(count, kNoIndex);
        Mesh& render = out_.scene.mesh;
        render.positions.insert(render.positions.end(), world_.begin(), world_.end());
        for (std::size_t i = 0; i < count; ++i) {
            out_colors.push_back(mesh_.colors.empty() ? glm::vec3(1.0f) : mesh_.colors[i]);
            out_normals.push_back(computed_[i]);
            out_vertex_surfaces.push_back(default_surface);
        }
        if (!out_.texcoords.empty() || use_texcoords) out_.texcoords.resize(render.positions.size(), glm::vec2(0.0f));

        const auto make_vertex = [&](std::uint32_t p, const CornerKey& key) {
            glm::vec3 color = mesh_.colors.empty() ? glm::vec3(1.0f) : mesh_.colors[p];
            const glm::vec3& factor = out_.surfaces[key.surface].color_factor;
            if (factor != glm::vec3(1.0f)) color *= factor;
            glm::vec3 normal = computed_[p];
            if (key.normal != kNoIndex) {
                const glm::vec3& file = mesh_.file_normals[key.normal];
                if (all_finite(file) && file != glm::vec3(0.0f)) {
                    const glm::dvec3 world = normal_matrix * glm::dvec3(file);
                    const double length = glm::length(world);
                    if (length > 0.0 && std::isfinite(length)) normal = glm::vec3(world / length);
                }
            }
            const glm::vec2 st = key.texcoord != kNoIndex ? mesh_.texcoords[key.texcoord] : glm::vec2(0.0f);
            std::uint32_t vertex;
            if (!used_[p]) {
                used_[p] = 1;
                keys_[p] = key;
                vertex = base + p;
                out_colors[vertex] = color;
                out_normals[vertex] = normal;
                out_vertex_surfaces[vertex] = key.surface;
            } else {
                vertex = static_cast<std::uint32_t>(render.positions.size());
                render.positions.push_back(world_[p]);
                out_colors.push_back(color);
                out_normals.push_back(normal);
                out_vertex_surfaces.push_back(key.surface);
                if (!out_.texcoords.empty()) out_.texcoords.push_back(glm::vec2(0.0f));
                extra_keys_.push_back(key);
                next_.push_back(kNoIndex);
            }
            if (!out_.texcoords.empty()) out_.texcoords[vertex] = st;
            return vertex;
        };
        const auto find_vertex = [&](std::uint32_t p, const CornerKey& key) {
            if (!used_[p]) return make_vertex(p, key);
            // Walk p's variants: the first at p, the others in next_ (local numbering).
            std::uint32_t local = p;
            while (true) {
                const CornerKey& have = local < count ? keys_[local] : extra_keys_[local - count];
                if (have == key) return base + local;
                if (next_[local] == kNoIndex) break;
                local = next_[local];
            }
            const std::uint32_t vertex = make_vertex(p, key);
            next_[local] = vertex - base;
            return vertex;
        };

        extra_keys_.clear();
        const std::size_t triangles = mesh_.triangles.size();
        for (std::size_t t = 0; t < triangles; ++t) {
            const Triangle& positions = triangles_[t];
            Triangle texcoords{kNoIndex, kNoIndex, kNoIndex}, normals{kNoIndex, kNoIndex, kNoIndex};
            if (use_texcoords) texcoords = mesh_.texcoord_triangles[t];
            if (use_file_normals) normals = mesh_.file_normal_triangles[t];
            if (mirror) {
                std::swap(texcoords[0], texcoords[2]);
                std::swap(normals[0], normals[2]);
            }
            const bool has_texcoords =
                texcoords[0] != kNoIndex && texcoords[1] != kNoIndex && texcoords[2] != kNoIndex;
            const std::uint32_t face = mesh_.face_materials.empty() ? kNoIndex : mesh_.face_materials[t];
            const std::uint32_t surface = face_surface(face, has_texcoords);
            Triangle render_triangle;
            for (int k = 0; k < 3; ++k) {
                render_triangle[k] = find_vertex(positions[k], CornerKey{texcoords[k], normals[k], surface});
            }
            render.triangles.push_back(render_triangle);
            out_triangle_surfaces.push_back(surface);
        }
    }

private:
    const Scene& scene_;
    const SourceObject& object_;
    const Mesh& mesh_;
    AssembledScene& out_;
    NormalsScratch& scratch_;
    std::vector<glm::dvec3> world_;
    std::vector<Triangle> triangles_;
    std::vector<glm::vec3> computed_;
    std::vector<CornerKey> keys_, extra_keys_;
    std::vector<std::uint8_t> used_;
    std::vector<std::uint32_t> next_;
};

/// The channel-wise largest magnitudes of every surface's coefficients: what
/// the lit-value bound and the effect set (any surface's term) read.
PhongMaterial envelope(const std::vector<Surface>& surfaces) {
    PhongMaterial result{glm::vec3(0.0f), glm::vec3(0.0f), glm::vec3(0.0f), 0.0f};
    for (const Surface& s : surfaces) {
        result.ka = glm::max(result.ka, glm::abs(s.material.ka));
        result.kd = glm::max(result.kd, glm::abs(s.material.kd));
        result.ks = glm::max(result.ks, glm::abs(s.material.ks));
        result.n = std::max(result.n, s.material.n);
    }
    return result;
}

}  // namespace

void copy_view_fields(const Scene& from, Scene& to) {
    to.camera = from.camera;
    to.image = from.image;
    to.ambient = from.ambient;
    to.lights = from.lights;
    to.shader = from.shader;
    to.lighting = from.lighting;
    to.normals = from.normals;
}

bool needs_assembly(const Scene& scene) {
    const Mesh& mesh = scene.mesh;
    return !scene.objects.empty() || !scene.material_fields.empty() || !mesh.face_materials.empty() ||
           !mesh.texcoord_triangles.empty() ||
           (scene.normals == NormalSource::file && !mesh.file_normal_triangles.empty());
}

void assemble_scene(const Scene& scene, AssembledScene& out, NormalsScratch& scratch, CheckedTextures* checked) {
    validate_scene_objects(scene, checked);
    out.surfaces.clear();
    out.texcoords.clear();
    out.triangle_surfaces.clear();
    out.vertex_surfaces.clear();
    Mesh& render = out.scene.mesh;
    render = Mesh{};
    std::vector<glm::vec3> colors, normals;
    bool any_colors = false;
    for (const SourceObject& object : source_objects(scene)) {
        any_colors = any_colors || !object.mesh->colors.empty();
        ObjectAssembler(scene, object, out, scratch).run(colors, normals, out.vertex_surfaces, out.triangle_surfaces);
    }
    if (out.surfaces.empty()) out.surfaces.push_back(Surface{scene.material, std::nullopt, glm::vec3(1.0f)});
    for (std::uint32_t& surface : out.vertex_surfaces) {
        if (surface == kNoIndex) surface = 0;  // a vertex no triangle uses
    }
    bool factors = false;
    for (const Surface& s : out.surfaces) factors = factors || s.color_factor != glm::vec3(1.0f);
    if (any_colors || factors) render.colors = std::move(colors);
    render.normals = std::move(normals);
    if (out.single_surface()) {
        out.triangle_surfaces.clear();
        out.vertex_surfaces.clear();
    }
    copy_view_fields(scene, out.scene);
    out.scene.material = out.single_surface() ? out.surfaces[0].material : envelope(out.surfaces);
}

}  // namespace phongrast::detail
