// Python values to phongrast's C++ types, as the seed's scripts pass them:
// numpy arrays (float32 or float64, any strides, 3 x Nv or Nv x 3), lists,
// numpy scalars and 0-d arrays wherever a number goes, and material and light
// objects of the user's own classes (duck typing). Every failure raises
// ValueError or TypeError naming the argument and what was expected.
#ifndef PHONGRAST_PYTHON_ARRAYS_HPP
#define PHONGRAST_PYTHON_ARRAYS_HPP

#include <string>
#include <vector>

#include <glm/vec3.hpp>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "phongrast/lighting.hpp"
#include "phongrast/mesh.hpp"
#include "phongrast/render.hpp"

namespace phongrast::python {

namespace py = pybind11;

/// How a 3 x 3 array of points is read: the seed's functions take points as
/// columns (3 x Nv, the exercise's layout); the Pythonic layer takes rows (Nv x 3).
enum class SquareLayout { columns_are_points, rows_are_points };

/// A finite number from a float, int, numpy scalar or 0-d array.
double read_number(py::handle value, const std::string& name);
/// A whole number in [minimum, maximum] (an int, a numpy integer, or a float with no fraction).
int read_int(py::handle value, const std::string& name, int minimum, int maximum);
/// Three finite numbers; a single number means the same for all three when `allow_scalar`.
glm::dvec3 read_vec3(py::handle value, const std::string& name, bool allow_scalar = false);

/// Points as 3 x Nv or Nv x 3. float32 and float64 arrays are read where they
/// are, whatever their strides; anything else is converted to float64 first.
std::vector<glm::dvec3> read_points(py::handle value, const std::string& name, SquareLayout square,
                                    std::size_t expected_count = 0);
/// The same as float RGB triples (colours, normals).
std::vector<glm::vec3> read_float_points(py::handle value, const std::string& name,
                                         SquareLayout square, std::size_t expected_count = 0);
/// Faces as 3 x NT or NT x 3 integer (or whole-number float) indices, 0-based, each below `vertex_count`.
std::vector<Triangle> read_faces(py::handle value, const std::string& name, std::size_t vertex_count,
                                 SquareLayout square);

/// A material by duck typing: ka/k_a, kd/k_d, ks/k_s (numbers or 3-vectors), n_phong/nphong/n;
/// a mapping with those keys works too.
PhongMaterial read_material(py::handle value, const std::string& name);
/// One light (pos/position, intensity) or a list of them; mappings work too.
std::vector<PointLight> read_lights(py::handle value, const std::string& name);
/// "ambient", "diffusion"/"diffuse", "specular", "full"/"all", or several joined with '+'.
Lighting read_lighting(py::handle value, const std::string& name);
Shader read_shader(py::handle value, const std::string& name);

/// The rendering options from keyword arguments: mode ("seed" or "exact", else
/// `default_mode`), then samples, threads, visibility, precision, sample_pattern,
/// overdraw, back_faces. An unknown keyword is a TypeError naming it.
RenderOptions options_from_keywords(const py::kwargs& keywords, const std::string& default_mode);
/// The keyword list above, for docstrings.
extern const char* const option_keywords_doc;

}  // namespace phongrast::python

#endif  // PHONGRAST_PYTHON_ARRAYS_HPP
