// The seed's per-triangle fill: shade_gouraud and shade_phong paint one
// projected triangle into a numpy canvas through the library's functions of
// the same names (include/phongrast/seed_fill.hpp).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include <pybind11/numpy.h>

#include "arrays.hpp"
#include "phongrast/seed_fill.hpp"
#include "bindings.hpp"

namespace phongrast::python {
namespace {

std::array<glm::dvec2, 3> read_projected(const py::object& verts_p) {
    const py::array_t<double> array = py::module_::import("numpy").attr("asarray")(verts_p, "float64");
    const bool columns = array.ndim() == 2 && array.shape(0) == 2 && array.shape(1) == 3;
    const bool rows = array.ndim() == 2 && array.shape(0) == 3 && array.shape(1) == 2;
    if (!columns && !rows) throw py::value_error("verts_p: expected a 2 x 3 (or 3 x 2) array of (column, row) pixel coordinates");
    const auto view = array.unchecked<2>();
    std::array<glm::dvec2, 3> corners;
    for (py::ssize_t k = 0; k < 3; ++k) {
        corners[static_cast<std::size_t>(k)] = {columns ? view(0, k) : view(k, 0), columns ? view(1, k) : view(k, 1)};
    }
    return corners;
}

std::array<glm::dvec3, 3> three_vectors(const py::object& value, const std::string& name) {
    const std::vector<glm::dvec3> points = read_points(value, name, SquareLayout::columns_are_points, 3);
    return {points[0], points[1], points[2]};
}

/// The canvas X as a writable M x N x 3 float32 or float64 array (written in place).
py::array writable_canvas(const py::object& X) {
    if (!py::isinstance<py::array>(X)) throw py::type_error("X: expected a numpy array of shape M x N x 3");
    py::array canvas = py::reinterpret_borrow<py::array>(X);
    if (canvas.ndim() != 3 || canvas.shape(2) != 3) throw py::value_error("X: expected shape M x N x 3");
    const char kind = canvas.dtype().kind();
    if (kind != 'f' || (canvas.itemsize() != 4 && canvas.itemsize() != 8) || !canvas.dtype().attr("isnative").cast<bool>()) {
        throw py::type_error("X: expected a float32 or float64 array");
    }
    if (!canvas.writeable()) throw py::value_error("X: the array is read-only");
    return canvas;
}

/// Paints into the canvas as a float32 or float64 array, whatever its strides.
PaintPixel canvas_painter(py::array& canvas) {
    char* data = static_cast<char*>(canvas.mutable_data());
    const py::ssize_t stride_row = canvas.strides(0), stride_column = canvas.strides(1), stride_channel = canvas.strides(2);
    const bool doubles = canvas.itemsize() == 8;
    return [=](int row, int column, const glm::dvec3& value) {
        char* pixel = data + row * stride_row + column * stride_column;
        for (int c = 0; c < 3; ++c) {
            if (doubles) {
                *reinterpret_cast<double*>(pixel + c * stride_channel) = value[c];
            } else {
                *reinterpret_cast<float*>(pixel + c * stride_channel) = static_cast<float>(value[c]);
            }
        }
    };
}

struct TriangleCall {
    std::array<SeedCorner, 3> corners;
    SeedLighting lighting;
};

TriangleCall read_call(const py::object& verts_p, const py::object& verts_n, const py::object& verts_c,
                       const py::object& bcoords, const py::object& cam_pos, const py::object& mat,
                       const py::object& lights, const py::object& light_amb, const py::object& lighting) {
    TriangleCall call;
    const std::array<glm::dvec2, 3> pixels = read_projected(verts_p);
    const std::array<glm::dvec3, 3> normals = three_vectors(verts_n, "verts_n");
    const std::array<glm::dvec3, 3> colors = three_vectors(verts_c, "verts_c");
    for (std::size_t k = 0; k < 3; ++k) call.corners[k] = {pixels[k], normals[k], colors[k]};
    call.lighting.centroid = read_vec3(bcoords, "bcoords");
    call.lighting.eye = read_vec3(cam_pos, "cam_pos");
    call.lighting.material = read_material(mat, "mat");
    call.lighting.lights = read_lights(lights, "lights");
    call.lighting.ambient = read_vec3(light_amb, "light_amb", true);
    call.lighting.lighting = read_lighting(lighting, "lighting");
    return call;
}

template <typename Fill>
py::object shade_with(const Fill& fill, const py::object& verts_p, const py::object& verts_n, const py::object& verts_c,
                      const py::object& bcoords, const py::object& cam_pos, const py::object& mat,
                      const py::object& lights, const py::object& light_amb, const py::object& X,
                      const py::object& lighting) {
    py::array canvas = writable_canvas(X);
    const TriangleCall call = read_call(verts_p, verts_n, verts_c, bcoords, cam_pos, mat, lights, light_amb, lighting);
    try {
        fill(call.corners, call.lighting, static_cast<int>(canvas.shape(0)), static_cast<int>(canvas.shape(1)),
             canvas_painter(canvas));
    } catch (const std::invalid_argument& error) {
        throw py::value_error(error.what());
    }
    return py::reinterpret_borrow<py::object>(X);
}

py::object shade_gouraud(const py::object& verts_p, const py::object& verts_n, const py::object& verts_c, const py::object& bcoords,
                         const py::object& cam_pos, const py::object& mat, const py::object& lights, const py::object& light_amb, const py::object& X,
                         const py::object& lighting) {
    return shade_with(phongrast::shade_gouraud, verts_p, verts_n, verts_c, bcoords, cam_pos, mat, lights, light_amb, X,
                      lighting);
}

py::object shade_phong(const py::object& verts_p, const py::object& verts_n, const py::object& verts_c, const py::object& bcoords,
                       const py::object& cam_pos, const py::object& mat, const py::object& lights, const py::object& light_amb, const py::object& X,
                       const py::object& lighting) {
    return shade_with(phongrast::shade_phong, verts_p, verts_n, verts_c, bcoords, cam_pos, mat, lights, light_amb, X,
                      lighting);
}

const char* const fill_doc = R"(

Paints one triangle into the canvas X (an M x N x 3 float32 or float64 array,
row 0 at the top) in place and returns X, as the seed's render loop calls it.
verts_p: 2 x 3 (or 3 x 2) continuous pixel coordinates (column, row) of the
three vertices, exactly what render_object projects to: column = (x + W/2)/W*N,
row = (H/2 - y)/H*M, with x = focal*x_c/z_c, y = focal*y_c/z_c in camera
coordinates; pixel (i, j) is painted when its centre (j + 0.5, i + 0.5) lies
inside (vertices snapped to 1/256 pixel, top-left rule; outside X is skipped).
verts_n, verts_c: 3 x 3 normals and colours, one vertex per column.
bcoords: the triangle's centroid in world space, where L and V are computed
(the seed's method). cam_pos, mat, lights, light_amb, lighting: as render_object.
These are the C++ library's phongrast::shade_gouraud / shade_phong (seed_fill.hpp),
in double precision: the picture agrees with render_object(mode="seed") to rounding
(about 1e-6), since render_object lights in float camera space. Corners beyond
+-1048576 pixels are a ValueError (the fixed-point coverage test's range).)";

}  // namespace

void bind_seed_fill(py::module_& module) {
    const auto names = [](auto&& function, const char* name, const std::string& summary, py::module_& m) {
        m.def(name, function, py::arg("verts_p"), py::arg("verts_n"), py::arg("verts_c"), py::arg("bcoords"),
              py::arg("cam_pos"), py::arg("mat"), py::arg("lights"), py::arg("light_amb"), py::arg("X"),
              py::arg("lighting") = "full", (summary + fill_doc).c_str());
    };
    names(&shade_gouraud, "shade_gouraud",
          "shade_gouraud(verts_p, verts_n, verts_c, bcoords, cam_pos, mat, lights, light_amb, X, lighting) -> X\n\n"
          "Gouraud: lights the three vertices, interpolates the lit colours linearly in screen space.",
          module);
    names(&shade_phong, "shade_phong",
          "shade_phong(verts_p, verts_n, verts_c, bcoords, cam_pos, mat, lights, light_amb, X, lighting) -> X\n\n"
          "Phong: interpolates normals and colours linearly in screen space, renormalises the normal and "
          "lights every pixel.",
          module);
}

}  // namespace phongrast::python
