// phongrast::Image <-> numpy, without copying where the layout allows.
#ifndef PHONGRAST_PYTHON_IMAGE_ARRAY_HPP
#define PHONGRAST_PYTHON_IMAGE_ARRAY_HPP

#include <string>
#include <vector>

#include <glm/vec3.hpp>
#include <pybind11/numpy.h>

#include "phongrast/image.hpp"
#include "phongrast/render.hpp"

namespace phongrast::python {

namespace py = pybind11;

/// An M x N x 3 float32 array that takes over the image's pixel buffer: no copy,
/// and the buffer is freed when the last array (or view) using it goes away.
py::array image_to_array(Image&& image);
/// A one-off render call's image memory: the buffer of a rendered image whose
/// arrays are all gone (image_to_recycling_array()), or an empty one. A
/// render call hands it to phongrast::render(scene, options, out) as the
/// thread's next working image, so that a loop of calls (`img =
/// render_object(...)`, the previous array freed as `img` is rebound)
/// renders with no copy of its image and no fresh pages.
Image take_recycled_image();
/// image_to_array() whose buffer, when its last array goes away, is kept
/// for take_recycled_image() (two buffers at most, none over 64 MiB).
py::array image_to_recycling_array(Image&& image);
/// An Nv x 3 array that takes over `values` (float32 for vec3, float64 for dvec3).
py::array points_to_array(std::vector<glm::vec3>&& values);
/// Copies an M x N x 3 array into an Image (for writing files): uint8 values
/// are 0 to 255 and divided by 255, float values are 0 to 1 and kept as they
/// are; other dtypes raise TypeError, a size past the limit ValueError.
Image array_to_image(py::handle value, const std::string& name);
/// A numpy view of `count` x 3 values at `data`, kept alive by `owner`.
template <typename Component>
py::array view_rows_of_three(Component* data, std::size_t count, py::handle owner, bool writable) {
    py::array view(py::dtype::of<Component>(),
                   {static_cast<py::ssize_t>(count), py::ssize_t{3}},
                   {static_cast<py::ssize_t>(3 * sizeof(Component)), static_cast<py::ssize_t>(sizeof(Component))},
                   data, owner);
    if (!writable) {
        py::detail::array_proxy(view.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
    }
    return view;
}
/// RenderStats as a dict of plain Python numbers (and the effect set as a string).
py::dict stats_to_dict(const RenderStats& stats);
/// The extra outputs that were asked for, as a dict of arrays that take over
/// their buffers: depth (M x N float32), distance (M x N float32), normal
/// (M x N x 3 float32), id (M x N int32, -1 on the background), alpha (M x N
/// float32). (uv is not handed to Python.)
py::dict aovs_to_dict(AovPlanes&& aovs);

}  // namespace phongrast::python

#endif  // PHONGRAST_PYTHON_IMAGE_ARRAY_HPP
