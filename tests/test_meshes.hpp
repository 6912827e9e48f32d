// The generated meshes for the tests, and Catch printing of glm vectors.
#ifndef PHONGRAST_TESTS_TEST_MESHES_HPP
#define PHONGRAST_TESTS_TEST_MESHES_HPP

#include "support/meshes.hpp"

// The generators live in tests/support/meshes.hpp (one definition for the tests and
// the benchmarks); the tests call them by this shorter name.
namespace test_meshes = phongrast::support;

#include <sstream>
#include <catch2/catch.hpp>

namespace Catch {
template <>
struct StringMaker<glm::vec3> {
    static std::string convert(const glm::vec3& v) {
        std::ostringstream out;
        out << "(" << v.x << ", " << v.y << ", " << v.z << ")";
        return out.str();
    }
};
}  // namespace Catch

#endif  // PHONGRAST_TESTS_TEST_MESHES_HPP
