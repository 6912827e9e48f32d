#include "back_faces.hpp"

#include <glm/geometric.hpp>

namespace phongrast::detail {
namespace {

// Checked on the vertices, conservatively.
template <typename Real>
bool front_faces_may_be_cut(const RenderOptions& options, const View& view,
                            const TransformedVertices<Real>& vertices) {
    for (std::size_t i = 0; i < vertices.screen.size(); ++i) {
        if (options.border == BorderPolicy::drop_triangle ? !vertices.inside_image(static_cast<std::uint32_t>(i), view)
                                                          : vertices.screen[i].depth < view.near_depth) {
            return true;
        }
    }
    return false;
}

}  // namespace

template <typename Real>
HiddenBackFaces back_faces_to_cull(const Scene& scene, const RenderOptions& options, const View& view,
                                   const TransformedVertices<Real>& vertices) {
    if (options.back_faces != BackFaces::cull_when_hidden) return HiddenBackFaces::unknown;
    // An orthographic viewer is at infinity, not at a point: not worked out, every face is drawn.
    if (!view.frame.perspective()) return HiddenBackFaces::unknown;
    const HiddenBackFaces hidden = find_hidden_back_faces(scene.mesh, view.frame.eye);
    if (hidden == HiddenBackFaces::unknown || front_faces_may_be_cut(options, view, vertices)) {
        return HiddenBackFaces::unknown;
    }
    return hidden;
}

bool faces_away(const Mesh& mesh, const glm::dvec3& eye, HiddenBackFaces orientation, const Triangle& triangle) {
    const glm::dvec3& a = mesh.positions[triangle[0]];
    const glm::dvec3 normal = glm::cross(mesh.positions[triangle[1]] - a, mesh.positions[triangle[2]] - a);
    const double facing = glm::dot(normal, eye - a);
    return orientation == HiddenBackFaces::outward_oriented ? facing < 0.0 : facing > 0.0;
}

template HiddenBackFaces back_faces_to_cull<float>(const Scene&, const RenderOptions&, const View&,
                                                   const TransformedVertices<float>&);
template HiddenBackFaces back_faces_to_cull<double>(const Scene&, const RenderOptions&, const View&,
                                                    const TransformedVertices<double>&);

}  // namespace phongrast::detail
