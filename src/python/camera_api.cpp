// phongrast.Camera: the contract's three cameras (docs/scene-format.md,
// "Camera") with numpy matrices in and out.
#include <array>
#include <string>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "arrays.hpp"
#include "bindings.hpp"
#include "phongrast/camera.hpp"

namespace phongrast::python {
namespace {

/// A rows x columns float64 matrix from any array-like (lists, float32, ...).
py::array_t<double> matrix_of(const py::handle& value, const char* name) {
    py::array_t<double, py::array::c_style | py::array::forcecast> array;
    try {
        array = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(value);
    } catch (const py::error_already_set&) {
        array = {};
    }
    if (!array || array.ndim() != 2) throw py::value_error(std::string(name) + ": expected a 2-d array of numbers");
    return array;
}

Matrix3x3 read_K(const py::handle& value) {
    const py::array_t<double> array = matrix_of(value, "K");
    if (array.shape(0) != 3 || array.shape(1) != 3) {
        throw py::value_error("K: expected a 3 x 3 array [[fx, s, cx], [0, fy, cy], [0, 0, 1]], got " +
                              std::to_string(array.shape(0)) + " x " + std::to_string(array.shape(1)));
    }
    const auto a = array.unchecked<2>();
    Matrix3x3 K{};
    for (py::ssize_t i = 0; i < 3; ++i) {
        for (py::ssize_t j = 0; j < 3; ++j) K[i][j] = a(i, j);
    }
    return K;
}

/// 3 x 4 [R | t] or 4 x 4 with last row [0, 0, 0, 1].
Matrix3x4 read_pose(const py::handle& value, const char* name) {
    const py::array_t<double> array = matrix_of(value, name);
    if ((array.shape(0) != 3 && array.shape(0) != 4) || array.shape(1) != 4) {
        throw py::value_error(std::string(name) + ": expected a 4 x 4 (or 3 x 4) array, got " +
                              std::to_string(array.shape(0)) + " x " + std::to_string(array.shape(1)));
    }
    const auto a = array.unchecked<2>();
    if (array.shape(0) == 4 && !(a(3, 0) == 0.0 && a(3, 1) == 0.0 && a(3, 2) == 0.0 && a(3, 3) == 1.0)) {
        throw py::value_error(std::string(name) + ": expected the last row [0, 0, 0, 1]");
    }
    Matrix3x4 pose{};
    for (py::ssize_t i = 0; i < 3; ++i) {
        for (py::ssize_t j = 0; j < 4; ++j) pose[i][j] = a(i, j);
    }
    return pose;
}

template <std::size_t Rows, std::size_t Columns>
py::array_t<double> to_array(const std::array<std::array<double, Columns>, Rows>& m) {
    py::array_t<double> out({static_cast<py::ssize_t>(Rows), static_cast<py::ssize_t>(Columns)});
    auto a = out.mutable_unchecked<2>();
    for (std::size_t i = 0; i < Rows; ++i) {
        for (std::size_t j = 0; j < Columns; ++j) a(i, j) = m[i][j];
    }
    return out;
}

const char* model_name(CameraModel model) {
    switch (model) {
        case CameraModel::opencv: return "opencv";
        case CameraModel::orthographic: return "orthographic";
        default: return "look_at";
    }
}

const OpenCvCamera& require_opencv(const Camera& camera, const char* what) {
    if (camera.model != CameraModel::opencv) {
        throw py::value_error(std::string(what) + ": this is a " + model_name(camera.model) +
                              " camera; its OpenCV form depends on the image size: camera.to_opencv(rows, columns)");
    }
    return camera.opencv;
}

std::pair<double, double> read_sensor(const py::handle& value) {
    const auto hw = value.cast<std::pair<py::object, py::object>>();
    return {read_number(hw.first, "sensor[0]"), read_number(hw.second, "sensor[1]")};
}

}  // namespace

void bind_camera(py::module_& module) {
    py::class_<Camera>(module, "Camera",
                       "A camera of the scene contract: look-at, OpenCV (K and world_to_camera, OpenCV axes: x right, "
                       "y down, z forward; pixel centres at whole numbers) or orthographic. Build one with the static "
                       "methods; Scene.camera takes it.")
        .def_static("look_at", [](const py::object& eye, const py::object& lookat, const py::object& up,
                                  const py::object& focal, const py::object& sensor) {
                        const auto [h, w] = read_sensor(sensor);
                        Camera camera = Camera::look_at(read_vec3(eye, "eye"), read_vec3(lookat, "lookat"),
                                                        read_vec3(up, "up"), read_number(focal, "focal"), h, w);
                        make_camera_frame(camera, 1, 1);  // validated now, naming the field
                        return camera;
                    }, py::arg("eye"), py::arg("lookat"), py::arg("up") = std::array<double, 3>{0.0, 1.0, 0.0},
                    py::arg("focal") = 1.0, py::arg("sensor") = std::array<double, 2>{1.0, 1.0},
                    "The look-at (pinhole) camera: focal and sensor (H, W) in world units.")
        .def_static("orthographic", [](const py::object& eye, const py::object& lookat, const py::object& up,
                                       const py::object& sensor) {
                        const auto [h, w] = read_sensor(sensor);
                        Camera camera = Camera::orthographic(read_vec3(eye, "eye"), read_vec3(lookat, "lookat"),
                                                             read_vec3(up, "up"), h, w);
                        make_camera_frame(camera, 1, 1);
                        return camera;
                    }, py::arg("eye"), py::arg("lookat"), py::arg("up") = std::array<double, 3>{0.0, 1.0, 0.0},
                    py::arg("sensor") = std::array<double, 2>{1.0, 1.0},
                    "A parallel projection: sensor (H, W) world units of the plane through eye fill the image; "
                    "the viewer is at infinity (V = -f). Points behind the eye's plane are clipped.")
        .def_static("from_opencv", [](const py::object& K, const py::object& world_to_camera) {
                        return Camera::from_opencv(read_K(K), read_pose(world_to_camera, "world_to_camera"));
                    }, py::arg("K"), py::arg("world_to_camera"),
                    "An OpenCV camera: K (3 x 3, pixels) and world_to_camera [R | t] (4 x 4 or 3 x 4); R must be a "
                    "rotation to 1e-6. Raises ValueError naming what is wrong.")
        .def_static("from_opencv_camera_to_world", [](const py::object& K, const py::object& camera_to_world) {
                        return Camera::from_opencv_camera_to_world(read_K(K), read_pose(camera_to_world, "camera_to_world"));
                    }, py::arg("K"), py::arg("camera_to_world"),
                    "The same from the inverse pose, camera_to_world (OpenCV axes).")
        .def_property_readonly("model", [](const Camera& c) { return std::string(model_name(c.model)); },
                               "\"look_at\", \"opencv\" or \"orthographic\".")
        .def_property_readonly("K", [](const Camera& c) { return to_array(require_opencv(c, "K").K()); },
                               "3 x 3 intrinsics of an OpenCV camera (float64).")
        .def_property_readonly("world_to_camera",
                               [](const Camera& c) { return to_array(require_opencv(c, "world_to_camera").world_to_camera_4x4()); },
                               "4 x 4 pose [R | t; 0 0 0 1] of an OpenCV camera (OpenCV axes).")
        .def_property_readonly("camera_to_world",
                               [](const Camera& c) { return to_array(require_opencv(c, "camera_to_world").camera_to_world()); },
                               "4 x 4 inverse pose of an OpenCV camera.")
        .def_property_readonly("eye", [](const Camera& c) {
                                   const glm::dvec3 e = c.model == CameraModel::opencv ? c.opencv.eye() : c.eye;
                                   return std::array<double, 3>{e.x, e.y, e.z};
                               }, "The centre of projection (OpenCV: -R^T t).")
        .def("to_opencv", [](const Camera& c, int rows, int columns) {
                 Camera out;
                 out.model = CameraModel::opencv;
                 out.opencv = opencv_form(c, rows, columns);
                 return out;
             }, py::arg("rows"), py::arg("columns"),
             "The same camera as an OpenCV one for an image of rows x columns (a look-at camera: R's rows are r, "
             "-u, f; fx = focal N / W, fy = focal M / H, (cx, cy) = (N/2 - 0.5, M/2 - 0.5)). Orthographic: ValueError.")
        .def("project", [](const Camera& c, const py::object& points, int rows, int columns) {
                 const std::vector<glm::dvec3> p = read_points(points, "points", SquareLayout::rows_are_points);
                 const CameraFrame frame = make_camera_frame(c, rows, columns);
                 py::array_t<double> out({static_cast<py::ssize_t>(p.size()), py::ssize_t(3)});
                 auto a = out.mutable_unchecked<2>();
                 for (std::size_t i = 0; i < p.size(); ++i) {
                     const ProjectedPoint q = frame.pixel_from_camera(frame.camera_from_world(p[i]));
                     a(i, 0) = q.column;
                     a(i, 1) = q.row;
                     a(i, 2) = q.depth;
                 }
                 return out;
             }, py::arg("points"), py::arg("rows"), py::arg("columns"),
             "The renderer's projection of N x 3 world points for an image of rows x columns: N x 3 (column, row, "
             "z_c) in the contract's pixel coordinates (pixel centres at +0.5). Meaningless where z_c <= 0.")
        .def("__repr__", [](const Camera& c) { return std::string("<phongrast.Camera ") + model_name(c.model) + ">"; });
}

}  // namespace phongrast::python
