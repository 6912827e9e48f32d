// The seed's per-triangle fill: shade_gouraud and shade_phong paint one
// projected triangle into a canvas, as the seed's render loop calls them.
//
// Coverage follows the contract exactly as the library does: vertices snapped
// to 1/256 pixel, pixel centres tested with 64-bit integer edge functions and
// the top-left rule. Attributes are interpolated linearly in screen space and
// lit with L and V at `bcoords` (the seed's method), in double precision.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include <pybind11/numpy.h>

#include "arrays.hpp"
#include "bindings.hpp"

namespace phongrast::python {
namespace {

constexpr std::int64_t kSubpixels = 256;

struct FixedPoint {
    std::int64_t column = 0;
    std::int64_t row = 0;
};

/// Twice the signed area of (a, b, p) in 1/256-pixel units; > 0 for p inside an a->b->c triangle of positive area.
std::int64_t edge(const FixedPoint& a, const FixedPoint& b, const FixedPoint& p) {
    return (b.column - a.column) * (p.row - a.row) - (b.row - a.row) * (p.column - a.column);
}

std::int64_t floor_div(std::int64_t a, std::int64_t b) {
    const std::int64_t q = a / b;
    return (a % b != 0 && a < 0) ? q - 1 : q;
}

/// Top edge (horizontal, the triangle below it) or left edge, for a triangle of positive area.
bool is_top_left(const FixedPoint& a, const FixedPoint& b) {
    const std::int64_t d_row = b.row - a.row;
    const std::int64_t d_column = b.column - a.column;
    return (d_row == 0 && d_column > 0) || d_row < 0;
}

/// The seed's lighting inputs, read once per triangle.
struct TriangleInputs {
    std::array<FixedPoint, 3> corners;
    std::array<glm::dvec3, 3> normals;
    std::array<glm::dvec3, 3> colors;
    glm::dvec3 centroid{0.0};
    glm::dvec3 eye{0.0};
    PhongMaterial material;
    std::vector<PointLight> lights;
    glm::dvec3 ambient{0.0};
    Lighting lighting;
};

std::array<FixedPoint, 3> read_projected(const py::object& verts_p) {
    const py::array_t<double> array = py::module_::import("numpy").attr("asarray")(verts_p, "float64");
    const bool columns = array.ndim() == 2 && array.shape(0) == 2 && array.shape(1) == 3;
    const bool rows = array.ndim() == 2 && array.shape(0) == 3 && array.shape(1) == 2;
    if (!columns && !rows) throw py::value_error("verts_p: expected a 2 x 3 (or 3 x 2) array of (column, row) pixel coordinates");
    const auto view = array.unchecked<2>();
    std::array<FixedPoint, 3> corners;
    for (py::ssize_t k = 0; k < 3; ++k) {
        const double column = columns ? view(0, k) : view(k, 0);
        const double row = columns ? view(1, k) : view(k, 1);
        if (!std::isfinite(column) || !std::isfinite(row) || std::abs(column) > 1e9 || std::abs(row) > 1e9) {
            throw py::value_error("verts_p: vertex " + std::to_string(k) + " has a non-finite or huge coordinate");
        }
        corners[static_cast<std::size_t>(k)] = {std::llrint(column * kSubpixels), std::llrint(row * kSubpixels)};
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

template <typename Component>
void store(py::array& canvas, py::ssize_t row, py::ssize_t column, const glm::dvec3& value) {
    char* pixel = static_cast<char*>(canvas.mutable_data()) + row * canvas.strides(0) + column * canvas.strides(1);
    for (int c = 0; c < 3; ++c) {
        *reinterpret_cast<Component*>(pixel + c * canvas.strides(2)) = static_cast<Component>(value[c]);
    }
}

/// Calls shade(w0, w1, w2) for every covered pixel centre and stores what it returns.
template <typename Shade>
void fill_triangle(py::array& canvas, std::array<FixedPoint, 3> v, const Shade& shade) {
    std::int64_t area = edge(v[0], v[1], v[2]);
    if (area == 0) return;  // degenerate: covers no pixel centre
    // The edge tests want a positive area: swap two corners, and swap their weights back below.
    const bool swapped = area < 0;
    if (swapped) {
        std::swap(v[1], v[2]);
        area = -area;
    }
    // Pixel (row, column) is a candidate when its centre lies within the triangle's bounds.
    const auto centres_from = [](std::int64_t low) { return floor_div(low - kSubpixels / 2 + kSubpixels - 1, kSubpixels); };
    const auto centres_to = [](std::int64_t high) { return floor_div(high - kSubpixels / 2, kSubpixels); };
    const std::int64_t row0 = std::max<std::int64_t>(0, centres_from(std::min({v[0].row, v[1].row, v[2].row})));
    const std::int64_t row1 = std::min<std::int64_t>(canvas.shape(0) - 1, centres_to(std::max({v[0].row, v[1].row, v[2].row})));
    const std::int64_t column0 = std::max<std::int64_t>(0, centres_from(std::min({v[0].column, v[1].column, v[2].column})));
    const std::int64_t column1 = std::min<std::int64_t>(canvas.shape(1) - 1, centres_to(std::max({v[0].column, v[1].column, v[2].column})));
    const bool biased[3] = {is_top_left(v[1], v[2]), is_top_left(v[2], v[0]), is_top_left(v[0], v[1])};
    const bool double_canvas = canvas.itemsize() == 8;
    for (std::int64_t row = row0; row <= row1; ++row) {
        for (std::int64_t column = column0; column <= column1; ++column) {
            const FixedPoint centre{column * kSubpixels + kSubpixels / 2, row * kSubpixels + kSubpixels / 2};
            const std::int64_t e[3] = {edge(v[1], v[2], centre), edge(v[2], v[0], centre), edge(v[0], v[1], centre)};
            bool inside = true;
            for (int k = 0; k < 3; ++k) inside = inside && (e[k] > 0 || (e[k] == 0 && biased[k]));
            if (!inside) continue;
            const double a = static_cast<double>(area);
            const double w1 = static_cast<double>(e[1]) / a, w2 = static_cast<double>(e[2]) / a;
            const glm::dvec3 value = shade(static_cast<double>(e[0]) / a, swapped ? w2 : w1, swapped ? w1 : w2);
            if (double_canvas) store<double>(canvas, row, column, value);
            else store<float>(canvas, row, column, value);
        }
    }
}

TriangleInputs read_inputs(const py::object& verts_p, const py::object& verts_n, const py::object& verts_c, const py::object& bcoords,
                           const py::object& cam_pos, const py::object& mat, const py::object& lights, const py::object& light_amb,
                           const py::object& lighting) {
    TriangleInputs in;
    in.corners = read_projected(verts_p);
    in.normals = three_vectors(verts_n, "verts_n");
    in.colors = three_vectors(verts_c, "verts_c");
    in.centroid = read_vec3(bcoords, "bcoords");
    in.eye = read_vec3(cam_pos, "cam_pos");
    in.material = read_material(mat, "mat");
    in.lights = read_lights(lights, "lights");
    in.ambient = read_vec3(light_amb, "light_amb", true);
    in.lighting = read_lighting(lighting, "lighting");
    return in;
}

glm::dvec3 light_with(const TriangleInputs& in, const glm::dvec3& normal, const glm::dvec3& color) {
    return phongrast::light<double>(in.centroid, normal, color, in.eye, in.material, in.lights, in.ambient, in.lighting);
}

py::object shade_gouraud(const py::object& verts_p, const py::object& verts_n, const py::object& verts_c, const py::object& bcoords,
                         const py::object& cam_pos, const py::object& mat, const py::object& lights, const py::object& light_amb, const py::object& X,
                         const py::object& lighting) {
    py::array canvas = writable_canvas(X);
    const TriangleInputs in = read_inputs(verts_p, verts_n, verts_c, bcoords, cam_pos, mat, lights, light_amb, lighting);
    const std::array<glm::dvec3, 3> lit = {light_with(in, in.normals[0], in.colors[0]),
                                           light_with(in, in.normals[1], in.colors[1]),
                                           light_with(in, in.normals[2], in.colors[2])};
    fill_triangle(canvas, in.corners, [&lit](double w0, double w1, double w2) {
        return w0 * lit[0] + w1 * lit[1] + w2 * lit[2];
    });
    return py::reinterpret_borrow<py::object>(X);
}

py::object shade_phong(const py::object& verts_p, const py::object& verts_n, const py::object& verts_c, const py::object& bcoords,
                       const py::object& cam_pos, const py::object& mat, const py::object& lights, const py::object& light_amb, const py::object& X,
                       const py::object& lighting) {
    py::array canvas = writable_canvas(X);
    const TriangleInputs in = read_inputs(verts_p, verts_n, verts_c, bcoords, cam_pos, mat, lights, light_amb, lighting);
    fill_triangle(canvas, in.corners, [&in](double w0, double w1, double w2) {
        const glm::dvec3 normal = w0 * in.normals[0] + w1 * in.normals[1] + w2 * in.normals[2];
        const glm::dvec3 color = w0 * in.colors[0] + w1 * in.colors[1] + w2 * in.colors[2];
        return light_with(in, normal, color);
    });
    return py::reinterpret_borrow<py::object>(X);
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
Arithmetic is double precision, so the picture agrees with render_object(mode="seed")
to rounding (about 1e-6), not bit for bit: the library lights in float camera space.)";

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
