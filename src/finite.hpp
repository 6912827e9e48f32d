// Finite-value tests shared by validation, the camera and the normals (internal header).
#ifndef PHONGRAST_SRC_FINITE_HPP
#define PHONGRAST_SRC_FINITE_HPP

#include <cmath>

namespace phongrast::detail {

/// Whether every component of a three-component vector (glm::vec3, glm::dvec3) is finite.
template <typename Vector3>
bool all_finite(const Vector3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

}  // namespace phongrast::detail

#endif  // PHONGRAST_SRC_FINITE_HPP
