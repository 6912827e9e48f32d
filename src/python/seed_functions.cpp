// The seed's functions under their own names and argument order:
// PhongMaterial, PointLight, light, calculate_normals, render_object.
#include <stdexcept>
#include <string>

#include <pybind11/eval.h>
#include <pybind11/numpy.h>

#include "arrays.hpp"
#include "bindings.hpp"
#include "image_array.hpp"
#include "interrupts.hpp"
#include "phongrast/camera.hpp"
#include "phongrast/render.hpp"

namespace phongrast::python {
namespace {

/// A number stays a float; anything else becomes a float64 array of 3.
py::object coefficient(const py::object& value, const std::string& name) {
    const glm::dvec3 v = read_vec3(value, name, true);
    if (v.x == v.y && v.y == v.z && !py::isinstance<py::array>(value) && !py::isinstance<py::list>(value) &&
        !py::isinstance<py::tuple>(value)) {
        return py::float_(v.x);
    }
    return py::array_t<double>(3, &v.x);
}

/// Camera errors of the library ("camera.lookat: must differ from camera.eye") with the seed's argument names.
std::string seed_names(std::string message) {
    for (std::size_t at = message.find("camera."); at != std::string::npos; at = message.find("camera.")) {
        message.erase(at, 7);
    }
    return message;
}

Camera read_seed_camera(const py::object& focal, const py::object& eye, const py::object& lookat, const py::object& up, const py::object& H,
                        const py::object& W) {
    Camera camera;
    camera.focal = read_number(focal, "focal");
    camera.eye = read_vec3(eye, "eye");
    camera.lookat = read_vec3(lookat, "lookat");
    camera.up = read_vec3(up, "up");
    camera.sensor_height = read_number(H, "H");
    camera.sensor_width = read_number(W, "W");
    if (!(camera.focal > 0)) throw py::value_error("focal: expected a positive distance, got " + std::to_string(camera.focal));
    if (!(camera.sensor_height > 0)) throw py::value_error("H: expected a positive sensor height, got " + std::to_string(camera.sensor_height));
    if (!(camera.sensor_width > 0)) throw py::value_error("W: expected a positive sensor width, got " + std::to_string(camera.sensor_width));
    return camera;
}

py::array render_object(const py::object& shader, const py::object& focal, const py::object& eye, const py::object& lookat, const py::object& up,
                        const py::object& bg_color, const py::object& M, const py::object& N, const py::object& H, const py::object& W,
                        const py::object& verts, const py::object& vert_colors, const py::object& faces, const py::object& mat,
                        const py::object& lights, const py::object& light_amb, const py::object& lighting, const py::kwargs& keywords) {
    const SquareLayout layout = SquareLayout::columns_are_points;
    Scene scene;
    scene.shader = read_shader(shader, "shader");
    scene.camera = read_seed_camera(focal, eye, lookat, up, H, W);
    scene.image.rows = read_int(M, "M", 1, kMaxImageSide);
    scene.image.columns = read_int(N, "N", 1, kMaxImageSide);
    scene.image.background = glm::vec3(read_vec3(bg_color, "bg_color", true));
    scene.mesh.positions = read_points(verts, "verts", layout);
    if (!vert_colors.is_none()) {
        scene.mesh.colors = read_float_points(vert_colors, "vert_colors", layout, scene.mesh.positions.size());
    }
    scene.mesh.triangles = read_faces(faces, "faces", scene.mesh.positions.size(), layout);
    scene.material = read_material(mat, "mat");
    scene.lights = read_lights(lights, "lights");
    scene.ambient = glm::vec3(read_vec3(light_amb, "light_amb", true));
    scene.lighting = read_lighting(lighting, "lighting");
    RenderOptions options = options_from_keywords(keywords, "seed");
    try {
        make_camera_frame(scene.camera, scene.image.rows, scene.image.columns);
    } catch (const std::invalid_argument& error) {
        throw py::value_error(seed_names(error.what()));
    }
    RenderResult result;
    result.image = take_recycled_image();  // the frame is drawn in it (render(scene, options, out)): no copy
    PythonProgress progress(progress_keyword(keywords));  // Ctrl-C and `progress` (interrupts.hpp)
    options.progress = progress.callback();
    progress.run([&] {
        py::gil_scoped_release release;
        render(scene, options, result);
    });
    return image_to_recycling_array(std::move(result.image));
}

py::array light_at_point(const py::object& point, const py::object& normal, const py::object& vcolor, const py::object& cam_pos, const py::object& mat,
                         const py::object& lights, const py::object& lighting, const py::object& light_amb) {
    const glm::dvec3 lit = phongrast::light<double>(
        read_vec3(point, "point"), read_vec3(normal, "normal"), read_vec3(vcolor, "vcolor", true),
        read_vec3(cam_pos, "cam_pos"), read_material(mat, "mat"), read_lights(lights, "lights"),
        read_vec3(light_amb, "light_amb", true), read_lighting(lighting, "lighting"));
    return py::array_t<double>(3, &lit.x);
}

py::array normals_of(const py::object& verts, const py::object& faces) {
    const py::array shape_probe = py::module_::import("numpy").attr("asarray")(verts);
    const bool columns = shape_probe.ndim() == 2 && shape_probe.shape(0) == 3;
    const std::vector<glm::dvec3> positions = read_points(verts, "verts", SquareLayout::columns_are_points);
    const std::vector<Triangle> triangles =
        read_faces(faces, "faces", positions.size(), SquareLayout::columns_are_points);
    py::array normals = points_to_array(calculate_normals(positions, triangles));
    return columns ? py::array(normals.attr("T")) : normals;
}

const char* const render_object_doc = R"(render_object(shader, focal, eye, lookat, up, bg_color, M, N, H, W, verts, vert_colors, faces, mat, lights, light_amb, lighting, **options) -> image

The seed's renderer: returns an M x N x 3 float32 image, ROW 0 AT THE TOP of
the picture (as the C++ library; scripts written for row 0 at the bottom use
image[::-1]). The array owns the C++ image buffer (no copy).

shader: "gouraud", "phong" (or "flat"). focal: distance to the image plane.
eye, lookat, up: the look-at camera (up must not be parallel to lookat - eye).
bg_color: background RGB (or one number). M, N: rows and columns of pixels.
H, W: height and width of the image plane in world units.
verts: 3 x Nv (the exercise's layout, Fortran-ordered as numpy.load gives it)
or Nv x 3, float32 or float64, read in place. vert_colors: the same shape as
verts, or None for white. faces: 3 x NT or NT x 3, 0-based vertex indices.
A 3 x 3 array counts as 3 x Nv (columns are vertices or faces).
mat: a PhongMaterial or any object with ka, kd, ks (numbers or RGB triples)
and n_phong (or k_a/k_d/k_s, nphong/n). lights: a PointLight, an object with
pos (or position) and intensity, or a list of them. light_amb: ambient RGB
intensity (or one number). lighting: "ambient", "diffusion" (or "diffuse"),
"specular", "full" (or "all"), or several joined with "+".

By default mode="seed": exactly the seed's three simplifications (L and V at
each triangle's centroid, screen-space interpolation, triangles touching the
border dropped). mode="exact" renders the contract without them.
)";

/// The seed's two data classes, in Python so that they copy, pickle and compare
/// like the exercise's own; their constructors check the values in C++.
const char* const seed_classes_source = R"python(
class PhongMaterial:
    """The seed's material: ka, kd, ks (numbers or RGB triples) and the Phong exponent n_phong.

    Any object with these attributes (or k_a, k_d, k_s, nphong, n) works where a
    material is expected; this class only checks the values when it is made."""

    def __init__(self, ka, kd, ks, n_phong):
        self.ka, self.kd, self.ks = _coefficient(ka, "ka"), _coefficient(kd, "kd"), _coefficient(ks, "ks")
        self.n_phong = _exponent(n_phong)

    def __repr__(self):
        return f"PhongMaterial(ka={self.ka!r}, kd={self.kd!r}, ks={self.ks!r}, n_phong={self.n_phong!r})"


class PointLight:
    """The seed's point light: world position pos (also readable as position) and RGB intensity (or one number)."""

    def __init__(self, pos, intensity):
        self.pos, self.intensity = _position(pos), _coefficient(intensity, "intensity")

    @property
    def position(self):
        """Alias of pos."""
        return self.pos

    def __repr__(self):
        return f"PointLight(pos={self.pos!r}, intensity={self.intensity!r})"
)python";

void bind_seed_classes(py::module_& module) {
    module.def("_coefficient", &coefficient, "A checked number or RGB triple (for PhongMaterial and PointLight).");
    module.def("_exponent", [](const py::object& n_phong) {
        const double n = read_number(n_phong, "n_phong");
        if (n < 0) throw py::value_error("n_phong: expected a non-negative Phong exponent, got " + std::to_string(n));
        return n;
    }, "A checked Phong exponent (for PhongMaterial).");
    module.def("_position", [](const py::object& pos) {
        const glm::dvec3 p = read_vec3(pos, "pos");
        return py::array_t<double>(3, &p.x);
    }, "A checked position (for PointLight).");
    py::exec(seed_classes_source, module.attr("__dict__"));
    module.attr("PhongMaterial").attr("__module__") = "phongrast";
    module.attr("PointLight").attr("__module__") = "phongrast";
}

}  // namespace

void bind_seed_functions(py::module_& module) {
    bind_seed_classes(module);
    module.def("light", &light_at_point, py::arg("point"), py::arg("normal"), py::arg("vcolor"), py::arg("cam_pos"),
               py::arg("mat"), py::arg("lights"), py::arg("lighting") = "full", py::kw_only(),
               py::arg("light_amb") = 0.2,
               R"(light(point, normal, vcolor, cam_pos, mat, lights, lighting="full", *, light_amb=0.2) -> RGB

The Phong formula at one point, in double precision (float64 array of 3):
ka*Ia*c + sum over lights of Ip*kd*c*max(0, N.L) + Ip*ks*max(0, R.V)^n (if N.L > 0),
with L and V computed at `point` (the seed passes the triangle's centroid).
`normal` is normalised here; a zero normal gets ambient light only.
light_amb is the ambient intensity Ia (a number or RGB), 0.2 by default as in scene files.)");
    module.def("calculate_normals", &normals_of, py::arg("verts"), py::arg("faces"),
               R"(calculate_normals(verts, faces) -> normals

Area-weighted unit vertex normals (float32), in the layout of verts: 3 x Nv in,
3 x Nv out (a Fortran-ordered view); Nv x 3 in, Nv x 3 out. faces are 0-based.
Faces are counter-clockwise seen from outside for outward normals. A vertex
whose faces cancel takes its largest face's normal; one with no usable face
gets (0, 0, 0), never NaN.)");
    module.def("render_object", &render_object, py::arg("shader"), py::arg("focal"), py::arg("eye"), py::arg("lookat"),
               py::arg("up"), py::arg("bg_color"), py::arg("M"), py::arg("N"), py::arg("H"), py::arg("W"),
               py::arg("verts"), py::arg("vert_colors"), py::arg("faces"), py::arg("mat"), py::arg("lights"),
               py::arg("light_amb"), py::arg("lighting"),
               (std::string(render_object_doc) + "\n" + option_keywords_doc).c_str());
}

}  // namespace phongrast::python
