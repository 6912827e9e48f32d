// Scene assembly (internal header): a contract-version-2 scene (several
// objects, per-face materials, per-corner texture coordinates and file
// normals) turned into the one render mesh the pipeline draws, whose
// attributes are all per vertex. A version-1 scene (one `mesh`, none of the
// new fields) is not assembled at all: it takes the pipeline as it is.
#ifndef PHONGRAST_SRC_SCENE_ASSEMBLY_HPP
#define PHONGRAST_SRC_SCENE_ASSEMBLY_HPP

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>

#include "normals.hpp"
#include "phongrast/render.hpp"

namespace phongrast::detail {

/// One distinct material of the assembled scene: the resolved coefficients
/// (contract precedence: object, scene, face, base), the texture and the
/// colour factor baked into the vertex colours.
struct Surface {
    PhongMaterial material;
    std::optional<TextureMap> texture;
    glm::vec3 color_factor{1.0f};
};

/// What assembly makes of a scene: a version-1-shaped Scene (its `mesh` the
/// render mesh: world positions, colours, unit normals per vertex, every
/// object's triangles in order) and what that Scene cannot say.
struct AssembledScene {
    Scene scene;  ///< scene.material: the only surface's material, or the channel-wise largest of all (bounds, effects)
    std::vector<Surface> surfaces;                  ///< at least one
    std::vector<std::uint32_t> triangle_surfaces;   ///< per render triangle (empty: all surface 0)
    std::vector<std::uint32_t> vertex_surfaces;     ///< per render vertex (empty: all surface 0)
    std::vector<glm::vec2> texcoords;               ///< per render vertex (empty: none in the scene)

    bool single_surface() const { return surfaces.size() <= 1; }
    /// Some material has a texture with an image, and faces with texture coordinates use it.
    bool textured() const {
        if (texcoords.empty()) return false;
        for (const Surface& s : surfaces) {
            if (s.texture && s.texture->image) return true;
        }
        return false;
    }
};

/// Whether `scene` needs assembly: it has objects, or its mesh uses a
/// version-2 attribute (per-face materials, texture coordinates, file normals
/// with Scene::normals = file), or scene.material_fields is set.
bool needs_assembly(const Scene& scene);

/// The version-2 checks of a scene (objects, their transforms and meshes,
/// per-corner and per-face indices, texture coordinates, materials); throws
/// std::invalid_argument naming the member ("objects[2].transform: singular").
/// Kept apart from validate_render_request(), which then checks the assembled scene.
void validate_scene_objects(const Scene& scene);

/// A Renderer's assembly, kept from frame to frame: an objects scene whose
/// meshes (by address and size), transforms, materials and normal sources
/// are those of the previous frame is not assembled again. A `mesh` scene
/// is held by value and may change in place, so it is assembled every frame.
struct SceneAssembly {
    AssembledScene assembled;
    NormalsScratch normals_scratch;

    /// validate_scene_objects(scene), then the assembled scene (reused when
    /// nothing it depends on changed); its non-mesh fields are `scene`'s.
    const AssembledScene& assemble(const Scene& scene);

    /// The next assemble() assembles anew (its memory is kept): for render()'s
    /// warm state, whose callers' meshes may reuse a freed mesh's address.
    void forget() { valid_ = false; }

private:
    struct ObjectKey {
        const Mesh* mesh = nullptr;
        std::size_t sizes[8] = {};
        glm::dmat4 transform{1.0};
        MaterialFields material;
        std::optional<NormalSource> normals;
    };
    std::vector<ObjectKey> key_;
    PhongMaterial key_material_;
    MaterialFields key_material_fields_;
    NormalSource key_normals_ = NormalSource::computed;
    bool valid_ = false;

    bool same_as_before(const Scene& scene) const;
    void remember(const Scene& scene);
};

/// assemble() without the cache (tests, validate_render()).
void assemble_scene(const Scene& scene, AssembledScene& out, NormalsScratch& scratch);

}  // namespace phongrast::detail

#endif  // PHONGRAST_SRC_SCENE_ASSEMBLY_HPP
