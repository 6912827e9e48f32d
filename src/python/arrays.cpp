#include "arrays.hpp"

#include <cmath>
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <initializer_list>
#include <stdexcept>
#include <type_traits>

namespace phongrast::python {
namespace {

std::string shape_text(const py::array& array) {
    std::string text = "(";
    for (py::ssize_t axis = 0; axis < array.ndim(); ++axis) {
        if (axis > 0) text += ", ";
        text += std::to_string(array.shape(axis));
    }
    return text + (array.ndim() == 1 ? ",)" : ")");
}

py::module_ numpy() { return py::module_::import("numpy"); }

bool is_native_dtype(const py::array& array, char kind, std::initializer_list<py::ssize_t> sizes) {
    if (array.dtype().kind() != kind) return false;
    if (!array.dtype().attr("isnative").cast<bool>()) return false;
    for (py::ssize_t size : sizes) {
        if (array.itemsize() == size) return true;
    }
    return false;
}

/// `value` as a numpy array, without a copy when it is one already.
py::array as_array(py::handle value, const std::string& name, const char* expected) {
    if (py::isinstance<py::array>(value)) return py::reinterpret_borrow<py::array>(value);
    if (py::isinstance<py::str>(value) || value.is_none()) {
        throw py::type_error(name + ": expected " + expected + ", got " +
                             std::string(py::str(py::type::of(value).attr("__name__"))));
    }
    try {
        return numpy().attr("asarray")(value);
    } catch (py::error_already_set&) {
        throw py::type_error(name + ": expected " + expected);
    }
}

/// A float32 or float64 array (read in place), or the values converted to float64.
py::array as_float_array(py::handle value, const std::string& name, const char* expected) {
    py::array array = as_array(value, name, expected);
    if (is_native_dtype(array, 'f', {4, 8})) return array;
    const char kind = array.dtype().kind();
    if (kind != 'f' && kind != 'i' && kind != 'u') {
        throw py::type_error(name + ": expected " + expected + ", got an array of dtype " +
                             std::string(py::str(array.dtype())));
    }
    return numpy().attr("asarray")(array, "float64");
}

struct PointAxes {
    std::size_t count = 0;
    py::ssize_t point_stride = 0;
    py::ssize_t component_stride = 0;
};

PointAxes point_axes(const py::array& array, const std::string& name, SquareLayout square,
                     std::size_t expected_count, const char* what) {
    const bool rows_of_three = array.ndim() == 2 && array.shape(1) == 3;
    const bool columns_of_three = array.ndim() == 2 && array.shape(0) == 3;
    if (!rows_of_three && !columns_of_three) {
        throw py::value_error(name + ": expected a 3 x N or N x 3 array of " + what + ", got shape " +
                              shape_text(array));
    }
    const bool columns = columns_of_three && (!rows_of_three || square == SquareLayout::columns_are_points);
    PointAxes axes;
    axes.count = static_cast<std::size_t>(array.shape(columns ? 1 : 0));
    axes.point_stride = array.strides(columns ? 1 : 0);
    axes.component_stride = array.strides(columns ? 0 : 1);
    if (expected_count != 0 && axes.count != expected_count) {
        throw py::value_error(name + ": expected " + std::to_string(expected_count) + " " + what +
                              " (one per vertex), got " + std::to_string(axes.count) + " (shape " +
                              shape_text(array) + ")");
    }
    return axes;
}

[[noreturn]] void throw_nonfinite(const std::string& name, std::size_t point, double value) {
    throw py::value_error(name + ": point " + std::to_string(point) + " has a " + (std::isnan(value) ? "NaN" : "infinite") +
                          " value; expected finite numbers");
}

/// Whether the array's values lie one after another, three per point, at their type's alignment:
/// then they are read as a plain array (numpy's arrays are aligned unless made from a buffer at an
/// odd offset; those are read value by value through memcpy).
template <typename Value>
bool packed(const char* base, const PointAxes& axes) {
    return axes.point_stride == 3 * static_cast<py::ssize_t>(sizeof(Value)) &&
           axes.component_stride == static_cast<py::ssize_t>(sizeof(Value)) &&
           reinterpret_cast<std::uintptr_t>(base) % alignof(Value) == 0;
}

/// Converts the components and notes, without a branch per value, whether all are finite
/// (x - x is 0 for a finite x and NaN otherwise, and a NaN stays in a sum); the slow search
/// for the culprit runs only on failure. The packed path keeps four independent sums so the
/// check does not serialise the loop (a single running `&=` cost 1.6 ns a value: render_object's
/// arrays are read on every call).
template <typename Source, typename Point>
void copy_points(const py::array& array, const PointAxes& axes, const std::string& name,
                 std::vector<Point>& out) {
    using Component = typename Point::value_type;
    static_assert(sizeof(Point) == 3 * sizeof(Component), "points must be three packed components");
    const auto* base = static_cast<const char*>(array.data());
    const auto read = [&](std::size_t i, int c) {
        Source value;
        std::memcpy(&value, base + static_cast<py::ssize_t>(i) * axes.point_stride + c * axes.component_stride,
                    sizeof value);
        return value;
    };
    bool finite = true;
    if (packed<Source>(base, axes)) {
        // Nv x 3 C-ordered, or 3 x Nv Fortran-ordered: the same packed memory.
        const auto* source = reinterpret_cast<const Source*>(base);
        const std::size_t values = 3 * axes.count;
        if constexpr (std::is_same_v<Source, Component>) {
            out.assign(reinterpret_cast<const Point*>(base), reinterpret_cast<const Point*>(base) + axes.count);
        } else {
            out.resize(axes.count);
            auto* target = reinterpret_cast<Component*>(out.data());
            for (std::size_t k = 0; k < values; ++k) target[k] = static_cast<Component>(source[k]);
        }
        Source sums[4] = {0, 0, 0, 0};
        std::size_t k = 0;
        for (; k + 4 <= values; k += 4) {
            for (std::size_t lane = 0; lane < 4; ++lane) sums[lane] += source[k + lane] - source[k + lane];
        }
        for (; k < values; ++k) sums[0] += source[k] - source[k];
        finite = (sums[0] + sums[1] + sums[2] + sums[3]) == Source(0);
    } else {
        out.resize(axes.count);
        auto* target = reinterpret_cast<Component*>(out.data());
        for (std::size_t i = 0; i < axes.count; ++i) {
            for (int c = 0; c < 3; ++c) {
                const Source value = read(i, c);
                finite &= (value - value == Source(0));
                target[3 * i + static_cast<std::size_t>(c)] = static_cast<Component>(value);
            }
        }
    }
    if (finite) return;
    for (std::size_t i = 0; i < axes.count; ++i) {
        for (int c = 0; c < 3; ++c) {
            if (!std::isfinite(read(i, c))) throw_nonfinite(name, i, static_cast<double>(read(i, c)));
        }
    }
}

template <typename Point>
std::vector<Point> read_any_points(py::handle value, const std::string& name, SquareLayout square,
                                   std::size_t expected_count, const char* what) {
    const py::array array = as_float_array(value, name, "a 3 x N or N x 3 array of numbers");
    const PointAxes axes = point_axes(array, name, square, expected_count, what);
    std::vector<Point> points;
    if (array.itemsize() == 4) {
        copy_points<float>(array, axes, name, points);
    } else {
        copy_points<double>(array, axes, name, points);
    }
    return points;
}

/// Integer indices in place (native int32/int64/uint32/uint64), else converted to int64.
py::array as_index_array(py::handle value, const std::string& name) {
    const char* expected = "a 3 x NT or NT x 3 array of 0-based vertex indices";
    py::array array = as_array(value, name, expected);
    if (is_native_dtype(array, 'i', {4, 8}) || is_native_dtype(array, 'u', {4, 8})) return array;
    const char kind = array.dtype().kind();
    if (kind == 'f') {
        const py::array whole = numpy().attr("floor")(array);
        const bool finite = numpy().attr("isfinite")(array).attr("all")().cast<bool>();
        if (!finite || !numpy().attr("array_equal")(whole, array).cast<bool>()) {
            throw py::value_error(name + ": expected whole-number vertex indices, got fractional or non-finite values");
        }
    } else if (kind != 'i' && kind != 'u') {
        throw py::type_error(name + ": expected " + expected + ", got an array of dtype " +
                             std::string(py::str(array.dtype())));
    }
    return numpy().attr("asarray")(array, "int64");
}

/// The largest of `count` indices, or ~0 when one is negative (so one comparison with the vertex
/// count catches both ends), kept in four running maxima and minima: a single one would chain every
/// comparison to the last (1.1 ns an index; render_object reads its faces on every call).
template <typename Index>
unsigned long long largest_index(const Index* source, std::size_t count) {
    Index maxima[4] = {0, 0, 0, 0};
    Index minima[4] = {0, 0, 0, 0};
    std::size_t k = 0;
    for (; k + 4 <= count; k += 4) {
        for (std::size_t lane = 0; lane < 4; ++lane) {
            maxima[lane] = std::max(maxima[lane], source[k + lane]);
            minima[lane] = std::min(minima[lane], source[k + lane]);
        }
    }
    for (; k < count; ++k) {
        maxima[0] = std::max(maxima[0], source[k]);
        minima[0] = std::min(minima[0], source[k]);
    }
    const Index smallest = std::min(std::min(minima[0], minima[1]), std::min(minima[2], minima[3]));
    if (smallest < 0) return ~0ULL;
    return static_cast<unsigned long long>(std::max(std::max(maxima[0], maxima[1]), std::max(maxima[2], maxima[3])));
}

/// Reads the indices (packed fast path as for points), then checks them all against
/// the vertex count at once; the face and index are searched for only on failure.
template <typename Index>
std::vector<Triangle> copy_faces(const py::array& array, const PointAxes& axes, const std::string& name,
                                 std::size_t vertex_count) {
    const auto* base = static_cast<const char*>(array.data());
    std::vector<Triangle> faces;
    const auto read = [&](std::size_t i, int c) {
        Index index;
        std::memcpy(&index, base + static_cast<py::ssize_t>(i) * axes.point_stride + c * axes.component_stride,
                    sizeof index);
        return index;
    };
    unsigned long long largest = 0;
    if (packed<Index>(base, axes)) {
        const auto* source = reinterpret_cast<const Index*>(base);
        const std::size_t values = 3 * axes.count;
        largest = largest_index(source, values);
        if constexpr (std::is_same_v<Index, std::uint32_t>) {
            faces.assign(reinterpret_cast<const Triangle*>(base), reinterpret_cast<const Triangle*>(base) + axes.count);
        } else {
            faces.resize(axes.count);
            auto* target = reinterpret_cast<std::uint32_t*>(faces.data());
            for (std::size_t k = 0; k < values; ++k) target[k] = static_cast<std::uint32_t>(source[k]);
        }
    } else {
        faces.resize(axes.count);
        auto* target = reinterpret_cast<std::uint32_t*>(faces.data());
        for (std::size_t i = 0; i < axes.count; ++i) {
            for (int c = 0; c < 3; ++c) {
                const Index index = read(i, c);
                const bool negative = std::is_signed_v<Index> && index < 0;
                largest = std::max(largest, negative ? ~0ULL : static_cast<unsigned long long>(index));
                target[3 * i + static_cast<std::size_t>(c)] = static_cast<std::uint32_t>(index);
            }
        }
    }
    if (axes.count == 0 || largest < vertex_count) return faces;
    for (std::size_t i = 0; i < axes.count; ++i) {
        for (int c = 0; c < 3; ++c) {
            const Index index = read(i, c);
            if (index < 0 || static_cast<unsigned long long>(index) >= vertex_count) {
                throw py::value_error(name + ": face " + std::to_string(i) + " has vertex index " +
                                      std::to_string(index) + "; expected 0-based indices from 0 to " +
                                      std::to_string(static_cast<long long>(vertex_count) - 1) + " (" +
                                      std::to_string(vertex_count) + " vertices)");
            }
        }
    }
    return faces;
}

bool is_scalar(py::handle value) {
    if (py::isinstance<py::array>(value)) return py::reinterpret_borrow<py::array>(value).ndim() == 0;
    return py::isinstance<py::float_>(value) || py::isinstance<py::int_>(value) ||
           py::isinstance(value, numpy().attr("number"));
}

/// The first of `names` that `value` has (as an attribute, or as a key of a mapping).
py::object find_field(py::handle value, std::initializer_list<const char*> names) {
    const bool mapping = py::isinstance<py::dict>(value);
    for (const char* field : names) {
        if (mapping) {
            const py::dict dict = py::reinterpret_borrow<py::dict>(value);
            if (dict.contains(field)) return dict[field];
        } else if (py::hasattr(value, field)) {
            return value.attr(field);
        }
    }
    return py::none();
}

py::object require_field(py::handle value, const std::string& name, std::initializer_list<const char*> names,
                         const std::string& description) {
    py::object found = find_field(value, names);
    if (found.is_none()) {
        throw py::type_error(name + ": expected " + description + "; missing '" + *names.begin() + "'");
    }
    return found;
}

/// A Python float or int (not a bool, not a numpy scalar) as a double, without numpy: the
/// seed's calls pass a dozen numbers and triples each, and asking numpy about every one cost
/// more than rendering a small mesh (40 us of a 60 us call). Anything else takes the general path.
bool plain_number(py::handle value, double& out) {
    if (PyFloat_CheckExact(value.ptr())) {
        out = PyFloat_AS_DOUBLE(value.ptr());
        return true;
    }
    if (PyLong_CheckExact(value.ptr())) {
        out = PyLong_AsDouble(value.ptr());
        if (out == -1.0 && PyErr_Occurred()) {
            PyErr_Clear();  // too large for a double: the general path says so
            return false;
        }
        return true;
    }
    return false;
}

/// Three finite plain numbers from a list, a tuple or a 1-d float64/float32 array, or false for
/// the general path (which also words every error).
bool plain_triple(py::handle value, glm::dvec3& out) {
    PyObject* object = value.ptr();
    if (PyList_CheckExact(object) || PyTuple_CheckExact(object)) {
        const bool list = PyList_CheckExact(object);
        if ((list ? PyList_GET_SIZE(object) : PyTuple_GET_SIZE(object)) != 3) return false;
        for (int c = 0; c < 3; ++c) {
            PyObject* item = list ? PyList_GET_ITEM(object, c) : PyTuple_GET_ITEM(object, c);
            if (!plain_number(item, out[c])) return false;
        }
    } else if (py::isinstance<py::array>(value)) {
        const auto array = py::reinterpret_borrow<py::array>(value);
        if (array.ndim() != 1 || array.shape(0) != 3) return false;
        const char kind = array.dtype().kind();
        const py::ssize_t size = array.itemsize();
        if (kind != 'f' || (size != 8 && size != 4) || array.dtype().byteorder() == '>') return false;
        const auto* base = static_cast<const char*>(array.data());
        for (int c = 0; c < 3; ++c) {
            const char* at = base + c * array.strides(0);
            if (size == 8) {
                std::memcpy(&out[c], at, sizeof(double));
            } else {
                float component;
                std::memcpy(&component, at, sizeof component);
                out[c] = component;
            }
        }
    } else {
        return false;
    }
    return std::isfinite(out.x) && std::isfinite(out.y) && std::isfinite(out.z);
}

}  // namespace

double read_number(py::handle value, const std::string& name) {
    double plain = 0;
    if (plain_number(value, plain) && std::isfinite(plain)) return plain;
    if (!is_scalar(value)) {
        throw py::type_error(name + ": expected a number, got " +
                             std::string(py::str(py::type::of(value).attr("__name__"))));
    }
    const double number = py::float_(py::reinterpret_borrow<py::object>(value)).cast<double>();
    if (!std::isfinite(number)) throw py::value_error(name + ": expected a finite number, got " + std::to_string(number));
    return number;
}

int read_int(py::handle value, const std::string& name, int minimum, int maximum) {
    const double number = read_number(value, name);
    if (number != std::floor(number) || number < minimum || number > maximum) {
        throw py::value_error(name + ": expected a whole number from " + std::to_string(minimum) + " to " +
                              std::to_string(maximum) + ", got " + std::string(py::str(value)));
    }
    return static_cast<int>(number);
}

glm::dvec3 read_vec3(py::handle value, const std::string& name, bool allow_scalar) {
    glm::dvec3 plain;
    if (plain_triple(value, plain)) return plain;
    if (allow_scalar && is_scalar(value)) return glm::dvec3(read_number(value, name));
    const char* expected = allow_scalar ? "a number or 3 numbers" : "3 numbers (x, y, z)";
    const py::array array = as_float_array(value, name, expected);
    if (array.size() != 3 || array.ndim() > 2) {
        throw py::value_error(name + ": expected " + expected + ", got shape " + shape_text(array));
    }
    const py::array flat = numpy().attr("ravel")(array).attr("astype")("float64");
    const auto* data = static_cast<const double*>(flat.data());
    for (int c = 0; c < 3; ++c) {
        if (!std::isfinite(data[c])) {
            throw py::value_error(name + ": expected finite numbers, got " + std::string(py::str(value)));
        }
    }
    return {data[0], data[1], data[2]};
}

std::vector<glm::dvec3> read_points(py::handle value, const std::string& name, SquareLayout square,
                                    std::size_t expected_count) {
    return read_any_points<glm::dvec3>(value, name, square, expected_count, "points");
}

std::vector<glm::vec3> read_float_points(py::handle value, const std::string& name, SquareLayout square,
                                         std::size_t expected_count) {
    return read_any_points<glm::vec3>(value, name, square, expected_count, "RGB triples or vectors");
}

std::vector<Triangle> read_faces(py::handle value, const std::string& name, std::size_t vertex_count,
                                 SquareLayout square) {
    const py::array array = as_index_array(value, name);
    const PointAxes axes = point_axes(array, name, square, 0, "vertex indices");
    const bool is_signed = array.dtype().kind() == 'i';
    if (array.itemsize() == 4) {
        return is_signed ? copy_faces<std::int32_t>(array, axes, name, vertex_count)
                         : copy_faces<std::uint32_t>(array, axes, name, vertex_count);
    }
    return is_signed ? copy_faces<std::int64_t>(array, axes, name, vertex_count)
                     : copy_faces<std::uint64_t>(array, axes, name, vertex_count);
}

PhongMaterial read_material(py::handle value, const std::string& name) {
    const std::string description =
        "a material with ka (or k_a), kd (or k_d), ks (or k_s) and n_phong (or nphong, n)";
    PhongMaterial material;
    material.ka = glm::vec3(read_vec3(require_field(value, name, {"ka", "k_a"}, description), name + ".ka", true));
    material.kd = glm::vec3(read_vec3(require_field(value, name, {"kd", "k_d"}, description), name + ".kd", true));
    material.ks = glm::vec3(read_vec3(require_field(value, name, {"ks", "k_s"}, description), name + ".ks", true));
    const double n = read_number(require_field(value, name, {"n_phong", "nphong", "n"}, description), name + ".n_phong");
    if (n < 0) throw py::value_error(name + ".n_phong: expected a non-negative Phong exponent, got " + std::to_string(n));
    material.n = static_cast<float>(n);
    return material;
}

std::vector<PointLight> read_lights(py::handle value, const std::string& name) {
    const auto read_one = [](py::handle light, const std::string& light_name) {
        const std::string description = "a light with pos (or position) and intensity";
        PointLight result;
        result.position = read_vec3(require_field(light, light_name, {"pos", "position"}, description),
                                    light_name + ".pos");
        result.intensity = glm::vec3(read_vec3(require_field(light, light_name, {"intensity"}, description),
                                               light_name + ".intensity", true));
        return result;
    };
    if (!find_field(value, {"pos", "position"}).is_none()) return {read_one(value, name)};
    if (!py::isinstance<py::iterable>(value) || py::isinstance<py::str>(value) || py::isinstance<py::dict>(value)) {
        throw py::type_error(name + ": expected a light (pos, intensity) or a list of lights");
    }
    std::vector<PointLight> lights;
    for (py::handle light : value) {
        lights.push_back(read_one(light, name + "[" + std::to_string(lights.size()) + "]"));
    }
    return lights;
}

Lighting read_lighting(py::handle value, const std::string& name) {
    if (!py::isinstance<py::str>(value)) throw py::type_error(name + ": expected a string such as 'full' or 'ambient+diffuse'");
    std::string text = value.cast<std::string>();
    std::string canonical;
    std::size_t start = 0;
    while (true) {
        const std::size_t plus = text.find('+', start);
        const std::string part = text.substr(start, plus == std::string::npos ? std::string::npos : plus - start);
        canonical += (part == "all") ? "full" : part;
        if (plus == std::string::npos) break;
        canonical += '+';
        start = plus + 1;
    }
    try {
        return parse_lighting(canonical);
    } catch (const std::invalid_argument&) {
        throw py::value_error(name + ": unknown lighting '" + text +
                              "'; expected ambient, diffusion (or diffuse), specular, full (or all), "
                              "or several joined with '+'");
    }
}

Shader read_shader(py::handle value, const std::string& name) {
    if (!py::isinstance<py::str>(value)) throw py::type_error(name + ": expected 'flat', 'gouraud' or 'phong'");
    try {
        return parse_shader(value.cast<std::string>());
    } catch (const std::invalid_argument&) {
        throw py::value_error(name + ": unknown shader '" + value.cast<std::string>() +
                              "'; expected flat, gouraud or phong");
    }
}

}  // namespace phongrast::python
