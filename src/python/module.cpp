// The phongrast Python module: pybind11 bindings over the public C++ API.
#include <pybind11/pybind11.h>

#include "bindings.hpp"
#include "signatures.hpp"
#include "phongrast/io/error.hpp"
#include "phongrast/progress.hpp"
#include "phongrast/version.hpp"

PYBIND11_MODULE(phongrast, module) {
    namespace py = pybind11;
    module.doc() = R"(phongrast: a C++ software renderer (Phong lighting, painter's order) for numpy.

Two ways in:

* The seed's own functions, same names and argument order as the course
  exercise, on the arrays it uses (3 x Nv or Nv x 3, float32 or float64):
  PhongMaterial, PointLight, light, calculate_normals, render_object,
  shade_gouraud, shade_phong. render_object follows the seed's method by
  default (mode="seed").

* A Pythonic layer: Scene (from a scene file, a dict or a mesh), Mesh (from
  OBJ or arrays), render(scene) -> (image, stats), Renderer for frame after
  frame, read_image / write_image (PNG, EXR). It renders the contract exactly
  by default (mode="exact").

Images are M x N x 3 float32 arrays, row 0 at the top of the picture (scripts
written for row 0 at the bottom flip them: image[::-1]). The GIL is released
while rendering, so Python threads render in parallel.

Bad input raises ValueError or TypeError naming the argument; unreadable or
malformed files raise phongrast.FileError (a ValueError) naming the file.)";
    module.attr("__version__") = PHONGRAST_VERSION_STRING;

    // A file that cannot be read or written, or is malformed: the message names the file and the line or field.
    py::register_exception<phongrast::io::FileError>(module, "FileError", PyExc_ValueError);
    module.attr("FileError").attr("__doc__") =
        "A file could not be read or written, or is malformed; the message names the file and the line or field.";
    // The progress callable returned False: the render stopped (Ctrl-C raises KeyboardInterrupt instead).
    py::register_exception<phongrast::RenderCancelled>(module, "RenderCancelled", PyExc_RuntimeError);
    module.attr("RenderCancelled").attr("__doc__") =
        "The render's progress callable returned False; a Renderer stays usable.";
    phongrast::python::bind_seed_functions(module);
    phongrast::python::bind_seed_fill(module);
    phongrast::python::bind_camera(module);
    phongrast::python::bind_scene_api(module);
    phongrast::python::add_text_signatures(module);  // last: inspect.signature() for everything above
    phongrast::python::start_thread_pool();
}
