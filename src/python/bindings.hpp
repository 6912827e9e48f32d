// The parts of the phongrast module, each adding its functions and classes.
#ifndef PHONGRAST_PYTHON_BINDINGS_HPP
#define PHONGRAST_PYTHON_BINDINGS_HPP

#include <pybind11/pybind11.h>

namespace phongrast::python {

namespace py = pybind11;

/// PhongMaterial, PointLight, light, calculate_normals, render_object.
void bind_seed_functions(py::module_& module);
/// shade_gouraud and shade_phong: one triangle into a canvas.
void bind_seed_fill(py::module_& module);
/// Camera: look-at, OpenCV and orthographic, numpy matrices in and out.
void bind_camera(py::module_& module);
/// Mesh, Scene, render, Renderer, read_image, write_image.
void bind_scene_api(py::module_& module);
/// Starts oneTBB on a thread of its own (thread_pool_start.cpp), so that the first render does not.
void start_thread_pool();

}  // namespace phongrast::python

#endif  // PHONGRAST_PYTHON_BINDINGS_HPP
