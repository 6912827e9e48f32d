// Scene assembly (internal header): a contract-version-2 scene (several
// objects, per-face materials, per-corner texture coordinates and file
// normals) turned into the one render mesh the pipeline draws, whose
// attributes are all per vertex. A version-1 scene (one `mesh`, none of the
// new fields) is not assembled at all: it takes the pipeline as it is.
#ifndef PHONGRAST_SRC_SCENE_ASSEMBLY_HPP
#define PHONGRAST_SRC_SCENE_ASSEMBLY_HPP

#include <cstddef>
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

/// Texture images whose texels were found finite, so that a Renderer scans
/// each image once rather than every frame. An image is recognised by its
/// address, its texel array's address and its dimensions, and is held (so
/// that its address cannot be reused by another image meanwhile); only the
/// images of the last assembled scene are kept.
struct CheckedTextures {
    struct Entry {
        std::shared_ptr<const TextureImage> image;
        const void* texels = nullptr;
        std::size_t count = 0;
        int rows = 0, columns = 0;
    };
    std::vector<Entry> entries;
    bool contains(const TextureImage& image) const;
    /// Every image held still has the texel array and dimensions it was checked with.
    bool unchanged() const;
};

/// The version-2 checks of a scene (objects, their transforms and meshes,
/// per-corner and per-face indices, texture coordinates, materials); throws
/// std::invalid_argument naming the member ("objects[2].transform: singular").
/// Kept apart from validate_render_request(), which then checks the assembled scene.
/// With `checked`, the texels of an image it contains are not scanned again
/// (dimensions are), and it is left holding the scene's images.
void validate_scene_objects(const Scene& scene, CheckedTextures* checked = nullptr);

/// A Renderer's assembly, kept from frame to frame. A scene is assembled
/// again only when something assembly reads differs from the last assembled
/// scene: the meshes' contents (every array compared bit for bit against a
/// copy, so a mesh edited in place between frames is assembled again, as
/// mesh order's rule asks: a guess may cost speed, never correctness), the
/// objects' transforms, materials and normal sources, and the scene's
/// material, material fields and normal source. Texture images are read,
/// not copied, so texels edited in place show in the next frame without a
/// new assembly; their finiteness is checked once per image
/// (CheckedTextures).
struct SceneAssembly {
    AssembledScene assembled;
    NormalsScratch normals_scratch;
    std::size_t assemblies = 0;  ///< scenes assembled so far (tests: an unchanged scene is not assembled again)

    /// validate_scene_objects(scene), then the assembled scene (reused when
    /// nothing it depends on changed); its non-mesh fields are `scene`'s.
    const AssembledScene& assemble(const Scene& scene);

    /// The next assemble() assembles anew (its memory is kept): for render()'s
    /// warm state, whose callers' meshes may reuse a freed mesh's address.
    void forget() { valid_ = false; }

private:
    struct ObjectKey {
        std::size_t snapshot = 0;  ///< index into snapshots_ of its mesh's copy
        std::size_t first_use = 0; ///< the first object (this frame's numbering) holding the same mesh
        glm::dmat4 transform{1.0};
        MaterialFields material;
        std::optional<NormalSource> normals;
    };
    bool mesh_scene_ = false;  ///< the last scene was a `mesh` scene (snapshots_[0] its mesh)
    std::vector<Mesh> snapshots_;  ///< the distinct source meshes' contents, as last assembled
    std::vector<ObjectKey> objects_;
    PhongMaterial key_material_;
    MaterialFields key_material_fields_;
    NormalSource key_normals_ = NormalSource::computed;
    CheckedTextures checked_textures_;
    bool valid_ = false;

    bool same_as_before(const Scene& scene) const;
    void remember(const Scene& scene);
};

/// The fields assembly does not read (camera, image, lights, ...), from `from` into `to`.
void copy_view_fields(const Scene& from, Scene& to);

/// assemble() without the cache (tests, validate_render()); `checked` as
/// validate_scene_objects() takes it.
void assemble_scene(const Scene& scene, AssembledScene& out, NormalsScratch& scratch,
                    CheckedTextures* checked = nullptr);

}  // namespace phongrast::detail

#endif  // PHONGRAST_SRC_SCENE_ASSEMBLY_HPP
