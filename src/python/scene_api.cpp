// The Pythonic layer: Mesh, Scene, render, Renderer, read_image, write_image, read_aovs.
#include <chrono>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "arrays.hpp"
#include "bindings.hpp"
#include "image_array.hpp"
#include "interrupts.hpp"
#include "phongrast/io/aov_file.hpp"
#include "phongrast/io/auto_scene.hpp"
#include "phongrast/io/error.hpp"
#include "phongrast/io/image_file.hpp"
#include "phongrast/io/obj_file.hpp"
#include "phongrast/io/scene_file.hpp"

namespace phongrast::python {
namespace {

/// A mesh owned by C++ (alone, or inside a Scene): the arrays Python sees are views of it.
struct PyMesh {
    std::shared_ptr<Mesh> mesh;
};

struct PyScene {
    std::shared_ptr<Scene> scene;
    std::vector<std::string> warnings;
};

/// A view of `data` that keeps `owner` (the mesh or scene holding the vector) alive.
template <typename Component, typename Owner>
py::array view_of(Component* data, std::size_t count, const std::shared_ptr<Owner>& owner, bool writable) {
    auto* keep = new std::shared_ptr<Owner>(owner);
    const py::capsule base(keep, [](void* pointer) { delete static_cast<std::shared_ptr<Owner>*>(pointer); });
    return view_rows_of_three(data, count, base, writable);
}

PyMesh mesh_from_arrays(const py::object& vertices, const py::object& faces, const py::object& colors) {
    auto mesh = std::make_shared<Mesh>();
    mesh->positions = read_points(vertices, "vertices", SquareLayout::rows_are_points);
    if (!colors.is_none()) {
        mesh->colors = read_float_points(colors, "colors", SquareLayout::rows_are_points, mesh->positions.size());
    }
    mesh->triangles = read_faces(faces, "faces", mesh->positions.size(), SquareLayout::rows_are_points);
    return {mesh};
}

/// The scene file's mesh (or `mesh` when given) and its material, resolved as the command does.
PyScene complete_scene(io::SceneFile file, const py::object& mesh) {
    PyScene result{std::make_shared<Scene>(std::move(file.scene)), std::move(file.warnings)};
    std::optional<PhongMaterial> from_mtl;
    if (!mesh.is_none()) {
        result.scene->mesh = *mesh.cast<const PyMesh&>().mesh;
    } else if (!file.mesh_path.empty()) {
        io::ObjFile obj = io::read_obj(file.mesh_path);
        result.scene->mesh = std::move(obj.mesh);
        from_mtl = obj.material;
        for (std::string& warning : obj.warnings) result.warnings.push_back(std::move(warning));
    } else {
        throw py::value_error("scene: no \"mesh\" given (a path in the scene, or mesh=phongrast.Mesh(...))");
    }
    std::vector<std::string> defaults_used;
    result.scene->material = io::resolve_material(file.material, from_mtl, &defaults_used);
    for (const std::string& field : defaults_used) result.warnings.push_back("material." + field + ": default used");
    return result;
}

PyScene scene_from_dict(py::dict description, const std::string& folder) {
    py::dict copy(description);
    py::object mesh = py::none();
    if (copy.contains("mesh") && py::isinstance<PyMesh>(copy["mesh"])) {
        mesh = copy["mesh"];
        PyDict_DelItemString(copy.ptr(), "mesh");
    }
    const py::module_ json = py::module_::import("json");
    const py::object to_list = py::module_::import("builtins").attr("eval")("lambda o: o.tolist()");
    const std::string text = json.attr("dumps")(copy, py::arg("default") = to_list).cast<std::string>();
    io::SceneFile file = io::parse_scene_json(text, "scene dict", folder);
    if (!mesh.is_none()) file.mesh_path.clear();
    return complete_scene(std::move(file), mesh);
}

py::tuple render_with_stats(const PyScene& scene, RenderOptions options, py::object progress_callable) {
    const std::shared_ptr<const Scene> keep = scene.scene;
    RenderResult result;
    PythonProgress progress(std::move(progress_callable));  // Ctrl-C and `progress` (interrupts.hpp)
    options.progress = progress.callback();
    progress.run([&] {
        py::gil_scoped_release release;
        result = render(*keep, options);
    });
    py::dict stats = stats_to_dict(result.stats);
    if (options.aovs.any()) {
        return py::make_tuple(image_to_array(std::move(result.image)), stats, aovs_to_dict(std::move(result.aovs)));
    }
    return py::make_tuple(image_to_array(std::move(result.image)), stats);
}

/// Wall times of `repeats` calls of `call`, timed in C++ (for bench/python_overhead.py's baseline).
template <typename Call>
std::vector<double> time_calls(int repeats, const Call& call) {
    std::vector<double> seconds;
    for (int i = 0; i < repeats; ++i) {
        const auto start = std::chrono::steady_clock::now();
        call();
        seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    return seconds;
}

/// One Renderer, one frame at a time: the lock is taken with the GIL released.
struct PyRenderer {
    Renderer renderer;
    std::mutex busy;
    py::object progress = py::none();  ///< the `progress` keyword, or None

    py::tuple render_frame(const PyScene& scene) {
        const std::shared_ptr<const Scene> keep = scene.scene;
        Image image;
        RenderStats stats;
        AovPlanes aovs;
        PythonProgress reports(progress);  // Ctrl-C and `progress` (interrupts.hpp)
        reports.run([&] {
            py::gil_scoped_release release;
            const std::lock_guard<std::mutex> lock(busy);
            // The callback lives for this frame only: take it out again however the frame ends.
            struct FrameProgress {
                Renderer& renderer;
                FrameProgress(Renderer& r, ProgressCallback callback) : renderer(r) { set(std::move(callback)); }
                ~FrameProgress() { set(nullptr); }
                void set(ProgressCallback callback) {
                    RenderOptions options = renderer.options();
                    options.progress = std::move(callback);
                    renderer.set_options(options);
                }
            } frame_progress(renderer, reports.callback());
            const RenderResult& result = renderer.render(*keep);
            image = result.image;  // the Renderer reuses its buffers for the next frame
            stats = result.stats;
            aovs = result.aovs;
        });
        if (renderer.options().aovs.any()) {
            return py::make_tuple(image_to_array(std::move(image)), stats_to_dict(stats), aovs_to_dict(std::move(aovs)));
        }
        return py::make_tuple(image_to_array(std::move(image)), stats_to_dict(stats));
    }

    std::vector<double> time_frames(const PyScene& scene, int repeats) {
        const std::shared_ptr<const Scene> keep = scene.scene;
        py::gil_scoped_release release;
        const std::lock_guard<std::mutex> lock(busy);
        return time_calls(repeats, [&] { renderer.render(*keep); });
    }
};

py::array vec3_array(const glm::dvec3& v) { return py::array_t<double>(3, &v.x); }

py::dict material_dict(const PhongMaterial& m) {
    py::dict d;
    d["ka"] = vec3_array(m.ka);
    d["kd"] = vec3_array(m.kd);
    d["ks"] = vec3_array(m.ks);
    d["n"] = m.n;
    return d;
}

py::list lights_list(const std::vector<PointLight>& lights) {
    py::list list;
    for (const PointLight& light : lights) {
        py::dict d;
        d["position"] = vec3_array(light.position);
        d["intensity"] = vec3_array(light.intensity);
        list.append(d);
    }
    return list;
}

void bind_mesh(py::module_& module) {
    py::class_<PyMesh>(module, "Mesh", R"(A triangle mesh held by the C++ library.

Mesh(vertices, faces, colors=None): vertices Nv x 3 (or 3 x Nv; a 3 x 3 array
counts as Nv x 3 here), float32 or float64, read in place and converted once
to the library's float64 positions; faces NT x 3 (or 3 x NT) 0-based indices;
colors like vertices (RGB in [0, 1]) or None for white.
Mesh.load(path) reads an OBJ file. positions, colors and faces are numpy
views of the C++ arrays (no copy): writing into them changes the mesh.)")
        .def(py::init(&mesh_from_arrays), py::arg("vertices"), py::arg("faces"), py::arg("colors") = py::none())
        .def_static("load", [](const std::string& path) { return PyMesh{std::make_shared<Mesh>(io::read_obj(path).mesh)}; },
                    py::arg("path"), "Reads an OBJ file (v x y z [r g b], faces triangulated as fans).")
        .def("save", [](const PyMesh& m, const std::string& path) { io::write_obj(*m.mesh, path); }, py::arg("path"),
             "Writes the mesh as OBJ (positions with 17 digits), atomically.")
        .def_property_readonly("positions", [](const PyMesh& m) {
            return view_of(&m.mesh->positions.data()->x, m.mesh->positions.size(), m.mesh, true);
        }, "Nv x 3 float64 view of the vertex positions.")
        .def_property_readonly("colors", [](const PyMesh& m) -> py::object {
            if (m.mesh->colors.empty()) return py::none();
            return view_of(&m.mesh->colors.data()->x, m.mesh->colors.size(), m.mesh, true);
        }, "Nv x 3 float32 view of the vertex colours, or None (white).")
        .def_property_readonly("faces", [](const PyMesh& m) {
            return view_of(m.mesh->triangles.data()->data(), m.mesh->triangles.size(), m.mesh, true);
        }, "NT x 3 uint32 view of the 0-based vertex indices.")
        .def_property_readonly("vertex_count", [](const PyMesh& m) { return m.mesh->positions.size(); }, "Nv.")
        .def_property_readonly("triangle_count", [](const PyMesh& m) { return m.mesh->triangles.size(); }, "NT.")
        .def("__repr__", [](const PyMesh& m) {
            return "<phongrast.Mesh " + std::to_string(m.mesh->positions.size()) + " vertices, " +
                   std::to_string(m.mesh->triangles.size()) + " triangles>";
        });
}

/// A 3-vector property; colours (`rgb`) may also be set from one number.
template <typename Getter, typename Setter>
void vector_property(py::class_<PyScene>& scene, const char* name, Getter get, Setter set, const char* doc,
                     bool rgb = false) {
    scene.def_property(name, [get](const PyScene& s) { return vec3_array(get(*s.scene)); },
                       [set, name, rgb](PyScene& s, const py::object& value) { set(*s.scene, read_vec3(value, name, rgb)); },
                       doc);
}

void bind_scene_camera(py::class_<PyScene>& scene) {
    vector_property(scene, "eye", [](const Scene& s) { return s.camera.eye; },
                    [](Scene& s, const glm::dvec3& v) { s.camera.eye = v; }, "Camera position.");
    vector_property(scene, "lookat", [](const Scene& s) { return s.camera.lookat; },
                    [](Scene& s, const glm::dvec3& v) { s.camera.lookat = v; }, "The point the camera looks at.");
    vector_property(scene, "up", [](const Scene& s) { return s.camera.up; },
                    [](Scene& s, const glm::dvec3& v) { s.camera.up = v; }, "Up direction (not parallel to the view).");
    vector_property(scene, "background", [](const Scene& s) { return glm::dvec3(s.image.background); },
                    [](Scene& s, const glm::dvec3& v) { s.image.background = glm::vec3(v); }, "Background RGB.", true);
    vector_property(scene, "ambient", [](const Scene& s) { return glm::dvec3(s.ambient); },
                    [](Scene& s, const glm::dvec3& v) { s.ambient = glm::vec3(v); }, "Ambient intensity Ia (RGB).", true);
    scene.def_property("focal", [](const PyScene& s) { return s.scene->camera.focal; },
                       [](PyScene& s, const py::object& v) { s.scene->camera.focal = read_number(v, "focal"); },
                       "Distance from the eye to the image plane.");
    scene.def_property("sensor", [](const PyScene& s) { return py::make_tuple(s.scene->camera.sensor_height, s.scene->camera.sensor_width); },
                       [](PyScene& s, std::pair<py::object, py::object> hw) {
                           s.scene->camera.sensor_height = read_number(hw.first, "sensor[0]");
                           s.scene->camera.sensor_width = read_number(hw.second, "sensor[1]");
                       }, "(H, W): height and width of the image plane in world units.");
    scene.def_property("size", [](const PyScene& s) { return py::make_tuple(s.scene->image.rows, s.scene->image.columns); },
                       [](PyScene& s, std::pair<py::object, py::object> mn) {
                           s.scene->image.rows = read_int(mn.first, "size[0]", 1, kMaxImageSide);
                           s.scene->image.columns = read_int(mn.second, "size[1]", 1, kMaxImageSide);
                       }, "(M, N): rows and columns of pixels.");
}

void bind_scene_look(py::class_<PyScene>& scene) {
    scene.def_property("shader", [](const PyScene& s) { return std::string(to_string(s.scene->shader)); },
                       [](PyScene& s, const py::object& v) { s.scene->shader = read_shader(v, "shader"); },
                       "\"flat\", \"gouraud\" or \"phong\".");
    scene.def_property("lighting", [](const PyScene& s) { return to_string(s.scene->lighting); },
                       [](PyScene& s, const py::object& v) { s.scene->lighting = read_lighting(v, "lighting"); },
                       "\"ambient\", \"diffuse\", \"specular\", \"full\", or several joined with \"+\".");
    scene.def_property("material", [](const PyScene& s) { return material_dict(s.scene->material); },
                       [](PyScene& s, const py::object& v) { s.scene->material = read_material(v, "material"); },
                       "dict ka, kd, ks, n (set it from a dict or any object with those attributes).");
    scene.def_property("lights", [](const PyScene& s) { return lights_list(s.scene->lights); },
                       [](PyScene& s, const py::object& v) { s.scene->lights = read_lights(v, "lights"); },
                       "List of dicts position, intensity (set from dicts or objects with pos/position, intensity).");
    scene.def_property("mesh", [](const PyScene& s) { return PyMesh{std::shared_ptr<Mesh>(s.scene, &s.scene->mesh)}; },
                       [](PyScene& s, const PyMesh& m) {
                           // A new Scene, so arrays still viewing the old mesh stay valid.
                           auto replaced = std::make_shared<Scene>(*s.scene);
                           replaced->mesh = *m.mesh;
                           s.scene = std::move(replaced);
                       }, "The scene's mesh (a view: editing its arrays edits the scene). Setting it copies the mesh.");
    scene.def_readonly("warnings", &PyScene::warnings, "Unknown fields and defaults used, one line each.");
}

/// render, Renderer, and the C++ timings bench/python_overhead.py compares them with.
void bind_rendering(py::module_& module) {
    module.def("render", [](const PyScene& s, const py::kwargs& keywords) {
        return render_with_stats(s, options_from_keywords(keywords, "exact"), progress_keyword(keywords));
    }, py::arg("scene"), (std::string("render(scene, **options) -> (image, stats)\n\n"
        "Renders the scene: image is M x N x 3 float32, row 0 at the top, owning the C++ buffer (no copy); "
        "stats is a dict (triangles drawn, dropped, clipped, samples, seconds, ...). mode=\"exact\" by default.\n\n") +
        option_keywords_doc).c_str());

    py::class_<PyRenderer>(module, "Renderer", (std::string(R"(Renders frame after frame, keeping its buffers and worker threads.

Renderer(**options); renderer.render(scene) -> (image, stats), the same pictures
as render(). Each returned image is a copy of the renderer's buffer (which the
next frame reuses). One frame at a time: concurrent calls on one Renderer wait.

)") + option_keywords_doc).c_str())
        .def(py::init([](const py::kwargs& keywords) {
            auto renderer = std::make_unique<PyRenderer>();
            renderer->renderer.set_options(options_from_keywords(keywords, "exact"));
            renderer->progress = progress_keyword(keywords);
            return renderer;
        }))
        .def("render", &PyRenderer::render_frame, py::arg("scene"), "Renders one frame: (image, stats).")
        .def("_cpp_render_seconds", &PyRenderer::time_frames, py::arg("scene"), py::arg("repeats"),
             "For bench/python_overhead.py: wall times of `repeats` frames of this Renderer, timed in C++.");

    module.def("_cpp_render_seconds", [](const PyScene& s, int repeats, const py::kwargs& keywords) {
        const RenderOptions options = options_from_keywords(keywords, "exact");
        const std::shared_ptr<const Scene> keep = s.scene;
        py::gil_scoped_release release;
        return time_calls(repeats, [&] { render(*keep, options); });
    }, py::arg("scene"), py::arg("repeats"),
       "For bench/python_overhead.py: wall times of `repeats` calls of the C++ render(scene, options), timed in "
       "C++ (no Python in between), the baseline the Python calls are compared with.");
}

}  // namespace

void bind_scene_api(py::module_& module) {
    bind_mesh(module);
    py::class_<PyScene> scene(module, "Scene", R"(Everything a scene file describes, with its mesh loaded.

Scene.load(path) reads a scene file (../shared/scene-format.md) and its OBJ;
Scene.from_dict(d, folder=".") the same fields as a dict ("mesh" may be a
path relative to folder, or a phongrast.Mesh); Scene.from_mesh(mesh, rows,
columns) frames a mesh automatically. Every field is a property.)");
    scene.def_static("load", [](const std::string& path, py::object mesh) {
                         return complete_scene(io::read_scene_file(path), mesh);
                     }, py::arg("path"), py::arg("mesh") = py::none(), "Reads a scene file and its mesh (or uses `mesh`).")
        .def_static("from_dict", &scene_from_dict, py::arg("description"), py::arg("folder") = ".",
                    "A scene from a dict with the scene file's fields; numpy arrays are fine as values.")
        .def_static("from_mesh", [](const PyMesh& mesh, int rows, int columns) {
                        return PyScene{std::make_shared<Scene>(io::frame_mesh(*mesh.mesh, rows, columns)), {}};
                    }, py::arg("mesh"), py::arg("rows") = 512, py::arg("columns") = 512,
                    "Frames the mesh as `phongrast render mesh.obj` does (camera, three lights, neutral material).")
        .def("copy", [](const PyScene& s) { return PyScene{std::make_shared<Scene>(*s.scene), s.warnings}; },
             "An independent copy (mesh included).");
    bind_scene_camera(scene);
    bind_scene_look(scene);

    bind_rendering(module);
    module.def("read_image", [](const std::string& path) { return image_to_array(io::read_image(path)); },
               py::arg("path"), "Reads an image (PNG values become value / 255; EXR as stored) as M x N x 3 float32.");
    module.def("write_image", [](const py::object& image, const std::string& path) {
        io::write_image(array_to_image(image, "image"), path);
    }, py::arg("image"), py::arg("path"),
       "Writes an M x N x 3 image: .png (8 bits, clamped to [0, 1], no gamma) or .exr (32-bit float), "
       "through a temporary file renamed into place. A uint8 array holds 0 to 255 (128 is 128/255 grey); a float "
       "array holds 0 to 1; other dtypes raise TypeError.");
    module.def("read_aovs", [](const std::string& path) {
        Image image;
        AovPlanes planes;
        io::read_exr_with_aovs(path, image, planes);
        return py::make_tuple(image_to_array(std::move(image)), aovs_to_dict(std::move(planes)));
    }, py::arg("path"),
       "Reads an EXR written with extra outputs (phongrast render --aov): (image, planes), planes a dict with "
       "the depth, normal, id and alpha arrays the file holds, as render(..., aovs=...) returns them.");
}

}  // namespace phongrast::python
