// The Pythonic layer: Mesh, Scene, render, Renderer, read_image, write_image, read_aovs.
#include <chrono>
#include <cmath>
#include <cstdint>
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
#include "phongrast/io/scene_load.hpp"
#include "phongrast/material.hpp"
#include "phongrast/texture.hpp"

namespace phongrast::python {
namespace {

/// A mesh owned by C++ (alone, or inside a Scene): the arrays Python sees are
/// views of it, read-only for a mesh that objects of a scene share.
struct PyMesh {
    std::shared_ptr<Mesh> mesh;
    bool writable = true;
};

/// A texture map: the image (shared by every material using it) and its wrap modes.
struct PyTexture {
    TextureMap map;
};

/// A face material: MaterialFields coefficients, colour factor, texture.
struct PyMaterial {
    FaceMaterial material;
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

/// "repeat", "clamp_to_edge" or "mirrored_repeat" as ValueError-raising text.
TextureWrap read_wrap(const std::string& text, const char* name) {
    try {
        return parse_texture_wrap(text);
    } catch (const std::invalid_argument& error) {
        throw py::value_error(std::string(name) + ": " + error.what());
    }
}

PyTexture texture_from_image(Image image, const std::string& name, const std::string& wrap_s,
                             const std::string& wrap_t) {
    auto texels = std::make_shared<TextureImage>();
    texels->rows = image.rows;
    texels->columns = image.columns;
    texels->name = name;
    for (const glm::vec3& texel : image.pixels) {
        if (!std::isfinite(texel.x) || !std::isfinite(texel.y) || !std::isfinite(texel.z)) {
            throw py::value_error(name + ": expected finite texel values");
        }
    }
    texels->texels = std::move(image.pixels);
    PyTexture texture;
    texture.map.image = std::move(texels);
    texture.map.wrap_s = read_wrap(wrap_s, "wrap_s");
    texture.map.wrap_t = read_wrap(wrap_t, "wrap_t");
    return texture;
}

/// Optional coefficients ka, kd, ks (a number or RGB) and n (non-negative).
MaterialFields read_material_fields(const py::object& ka, const py::object& kd, const py::object& ks,
                                    const py::object& n, const std::string& name) {
    MaterialFields fields;
    if (!ka.is_none()) fields.ka = glm::vec3(read_vec3(ka, name + ".ka", true));
    if (!kd.is_none()) fields.kd = glm::vec3(read_vec3(kd, name + ".kd", true));
    if (!ks.is_none()) fields.ks = glm::vec3(read_vec3(ks, name + ".ks", true));
    if (!n.is_none()) {
        const double exponent = read_number(n, name + ".n");
        if (exponent < 0.0) throw py::value_error(name + ".n: expected a non-negative Phong exponent");
        fields.n = static_cast<float>(exponent);
    }
    return fields;
}

py::dict fields_dict(const MaterialFields& fields) {
    py::dict d;
    const auto triple = [](const glm::vec3& v) { return py::make_tuple(v.x, v.y, v.z); };
    if (fields.ka) d["ka"] = triple(*fields.ka);
    if (fields.kd) d["kd"] = triple(*fields.kd);
    if (fields.ks) d["ks"] = triple(*fields.ks);
    if (fields.n) d["n"] = *fields.n;
    return d;
}

/// Per-vertex values given as Nv x K rows become per-corner values indexed like the faces.
std::vector<Triangle> corners_like(const std::vector<Triangle>& triangles) { return triangles; }

PyMesh mesh_from_arrays(const py::object& vertices, const py::object& faces, const py::object& colors,
                        const py::object& texcoords, const py::object& normals, const py::object& material,
                        const py::object& materials, const py::object& face_materials) {
    auto mesh = std::make_shared<Mesh>();
    mesh->positions = read_points(vertices, "vertices", SquareLayout::rows_are_points);
    if (!colors.is_none()) {
        mesh->colors = read_float_points(colors, "colors", SquareLayout::rows_are_points, mesh->positions.size());
    }
    mesh->triangles = read_faces(faces, "faces", mesh->positions.size(), SquareLayout::rows_are_points);
    if (!texcoords.is_none()) {
        const auto array = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(texcoords);
        if (!array || array.ndim() != 2 || array.shape(1) != 2 ||
            static_cast<std::size_t>(array.shape(0)) != mesh->positions.size()) {
            throw py::value_error("texcoords: expected an Nv x 2 array of (s, t), one per vertex (Nv = " +
                                  std::to_string(mesh->positions.size()) + ")");
        }
        for (py::ssize_t i = 0; i < array.shape(0); ++i) {
            const double s = array.at(i, 0), t = array.at(i, 1);
            if (!std::isfinite(s) || !std::isfinite(t)) {
                throw py::value_error("texcoords: row " + std::to_string(i) + " is not finite");
            }
            mesh->texcoords.emplace_back(static_cast<float>(s), static_cast<float>(t));
        }
        mesh->texcoord_triangles = corners_like(mesh->triangles);
    }
    if (!normals.is_none()) {
        mesh->file_normals =
            read_float_points(normals, "normals", SquareLayout::rows_are_points, mesh->positions.size());
        mesh->file_normal_triangles = corners_like(mesh->triangles);
    }
    if (!material.is_none() && !materials.is_none()) {
        throw py::value_error("material, materials: give one material for every face, or materials with face_materials");
    }
    if (!material.is_none()) {
        mesh->materials.push_back(material.cast<const PyMaterial&>().material);
        mesh->face_materials.assign(mesh->triangles.size(), 0u);
    } else if (!materials.is_none()) {
        for (const py::handle item : materials) mesh->materials.push_back(item.cast<const PyMaterial&>().material);
        if (face_materials.is_none()) throw py::value_error("face_materials: expected one index per face with materials");
        const auto indices = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(face_materials);
        if (!indices || indices.ndim() != 1 || static_cast<std::size_t>(indices.shape(0)) != mesh->triangles.size()) {
            throw py::value_error("face_materials: expected " + std::to_string(mesh->triangles.size()) +
                                  " indices (one per face; -1 for none)");
        }
        for (py::ssize_t i = 0; i < indices.shape(0); ++i) {
            const std::int64_t index = indices.at(i);
            if (index < -1 || index >= static_cast<std::int64_t>(mesh->materials.size())) {
                throw py::value_error("face_materials[" + std::to_string(i) + "]: " + std::to_string(index) +
                                      " is not a material index (0 to " + std::to_string(mesh->materials.size() - 1) +
                                      ", or -1 for none)");
            }
            mesh->face_materials.push_back(index < 0 ? kNoIndex : static_cast<std::uint32_t>(index));
        }
    } else if (!face_materials.is_none()) {
        throw py::value_error("face_materials: given without materials");
    }
    return {mesh};
}

/// The builder's warnings and the defaults it used, one line each.
PyScene scene_from_loaded(io::LoadedScene loaded) {
    PyScene result{std::make_shared<Scene>(std::move(loaded.scene)), std::move(loaded.warnings)};
    for (const std::string& field : loaded.defaults_used) result.warnings.push_back("material." + field + ": default used");
    return result;
}

/// The scene file's mesh (or `mesh` when given) and its material, through the
/// library's scene builder, as the command does.
PyScene complete_scene(io::SceneFile file, const std::string& name, const py::object& mesh,
                       std::vector<std::shared_ptr<const Mesh>> object_meshes = {}) {
    io::SceneLoadOptions options;
    if (!mesh.is_none()) options.mesh = mesh.cast<const PyMesh&>().mesh;
    options.object_meshes = std::move(object_meshes);
    if (file.objects.empty() && file.mesh_path.empty() && !options.mesh) {
        throw py::value_error("scene: no \"mesh\" given (a path in the scene, or mesh=phongrast.Mesh(...)), "
                              "and no \"objects\"");
    }
    return scene_from_loaded(io::build_scene(std::move(file), name, options));
}

PyScene scene_from_dict(py::dict description, const std::string& folder) {
    py::dict copy(description);
    py::object mesh = py::none();
    if (copy.contains("mesh") && py::isinstance<PyMesh>(copy["mesh"])) {
        mesh = copy["mesh"];
        PyDict_DelItemString(copy.ptr(), "mesh");
    }
    // Objects whose "mesh" is a phongrast.Mesh: the mesh in memory, a stand-in name in the JSON.
    std::vector<std::shared_ptr<const Mesh>> object_meshes;
    if (copy.contains("objects") && py::isinstance<py::list>(copy["objects"])) {
        py::list objects;
        std::size_t index = 0;
        for (const py::handle item : copy["objects"].cast<py::list>()) {
            if (py::isinstance<py::dict>(item) && item.cast<py::dict>().contains("mesh") &&
                py::isinstance<PyMesh>(item.cast<py::dict>()["mesh"])) {
                py::dict object(item.cast<py::dict>());
                object_meshes.resize(index + 1);
                object_meshes[index] = object["mesh"].cast<const PyMesh&>().mesh;
                object["mesh"] = "phongrast.Mesh in memory";
                objects.append(object);
            } else {
                objects.append(item);
            }
            ++index;
        }
        copy["objects"] = objects;
    }
    const py::module_ json = py::module_::import("json");
    const py::object to_list = py::module_::import("builtins").attr("eval")("lambda o: o.tolist()");
    const std::string text = json.attr("dumps")(copy, py::arg("default") = to_list).cast<std::string>();
    io::SceneFile file = io::parse_scene_json(text, "scene dict", folder);
    if (!mesh.is_none()) file.mesh_path.clear();
    return complete_scene(std::move(file), "scene dict", mesh, std::move(object_meshes));
}

py::tuple render_with_stats(const PyScene& scene, RenderOptions options, py::object progress_callable) {
    const std::shared_ptr<const Scene> keep = scene.scene;
    RenderResult result;
    result.image = take_recycled_image();  // the frame is drawn in it (render(scene, options, out)): no copy
    PythonProgress progress(std::move(progress_callable));  // Ctrl-C and `progress` (interrupts.hpp)
    options.progress = progress.callback();
    progress.run([&] {
        py::gil_scoped_release release;
        render(*keep, options, result);
    });
    py::dict stats = stats_to_dict(result.stats);
    if (options.aovs.any()) {
        return py::make_tuple(image_to_recycling_array(std::move(result.image)), stats,
                              aovs_to_dict(std::move(result.aovs)));
    }
    return py::make_tuple(image_to_recycling_array(std::move(result.image)), stats);
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

Mesh(vertices, faces, colors=None, texcoords=None, normals=None, material=None,
materials=None, face_materials=None): vertices Nv x 3 (or 3 x Nv; a 3 x 3
array counts as Nv x 3 here), float32 or float64, read in place and converted
once to the library's float64 positions; faces NT x 3 (or 3 x NT) 0-based
indices; colors like vertices (RGB in [0, 1]) or None for white; texcoords
Nv x 2 texture coordinates (s, t), t = 0 at the texture's bottom row; normals
Nv x 3, the mesh's own normals (used by objects or scenes with
normals="file"); material a phongrast.Material for every face, or materials
(a list) with face_materials (one index per face, -1 for none).
Mesh.load(path) reads any mesh file (OBJ, PLY, STL, glTF/GLB). positions,
colors and faces are numpy views of the C++ arrays (no copy): writing into
them changes the mesh (read-only for a mesh that a scene's objects share).)")
        .def(py::init(&mesh_from_arrays), py::arg("vertices"), py::arg("faces"), py::arg("colors") = py::none(),
             py::arg("texcoords") = py::none(), py::arg("normals") = py::none(), py::arg("material") = py::none(),
             py::arg("materials") = py::none(), py::arg("face_materials") = py::none())
        .def_static("load", [](const std::string& path) { return PyMesh{std::make_shared<Mesh>(io::read_mesh(path).mesh)}; },
                    py::arg("path"), "Reads a mesh file: OBJ (with its MTL), PLY, STL, glTF or GLB.")
        .def("save", [](const PyMesh& m, const std::string& path) { io::write_obj(*m.mesh, path); }, py::arg("path"),
             "Writes the mesh as OBJ (positions with 17 digits), atomically.")
        .def_property_readonly("positions", [](const PyMesh& m) {
            return view_of(&m.mesh->positions.data()->x, m.mesh->positions.size(), m.mesh, m.writable);
        }, "Nv x 3 float64 view of the vertex positions.")
        .def_property_readonly("colors", [](const PyMesh& m) -> py::object {
            if (m.mesh->colors.empty()) return py::none();
            return view_of(&m.mesh->colors.data()->x, m.mesh->colors.size(), m.mesh, m.writable);
        }, "Nv x 3 float32 view of the vertex colours, or None (white).")
        .def_property_readonly("faces", [](const PyMesh& m) {
            return view_of(m.mesh->triangles.data()->data(), m.mesh->triangles.size(), m.mesh, m.writable);
        }, "NT x 3 uint32 view of the 0-based vertex indices.")
        .def_property_readonly("has_texcoords", [](const PyMesh& m) { return !m.mesh->texcoords.empty(); },
                               "True when the mesh has texture coordinates.")
        .def_property_readonly("has_normals", [](const PyMesh& m) { return !m.mesh->file_normals.empty(); },
                               "True when the mesh carries its own normals (normals=\"file\" uses them).")
        .def_property_readonly("material_count", [](const PyMesh& m) { return m.mesh->materials.size(); },
                               "Materials its faces use (OBJ usemtl, glTF primitives, or given).")
        .def_property_readonly("vertex_count", [](const PyMesh& m) { return m.mesh->positions.size(); }, "Nv.")
        .def_property_readonly("triangle_count", [](const PyMesh& m) { return m.mesh->triangles.size(); }, "NT.")
        .def("__repr__", [](const PyMesh& m) {
            return "<phongrast.Mesh " + std::to_string(m.mesh->positions.size()) + " vertices, " +
                   std::to_string(m.mesh->triangles.size()) + " triangles>";
        });
}

void bind_materials(py::module_& module) {
    py::class_<PyTexture>(module, "Texture", R"(A texture map for a Material (contract "Texture maps").

Texture(texels, wrap_s="repeat", wrap_t="repeat"): texels a (rows, columns, 3)
float array of linear RGB, row 0 the top row, used as given (no transfer
function); wrap "repeat", "clamp_to_edge" or "mirrored_repeat".
Texture.load(path, ...) reads an image file (PNG values k/255, EXR as stored).)")
        .def(py::init([](const py::object& texels, const std::string& wrap_s, const std::string& wrap_t) {
                 return texture_from_image(array_to_image(texels, "texels"), "texels", wrap_s, wrap_t);
             }),
             py::arg("texels"), py::arg("wrap_s") = "repeat", py::arg("wrap_t") = "repeat")
        .def_static("load", [](const std::string& path, const std::string& wrap_s, const std::string& wrap_t) {
                        return texture_from_image(io::read_image(path), path, wrap_s, wrap_t);
                    }, py::arg("path"), py::arg("wrap_s") = "repeat", py::arg("wrap_t") = "repeat",
                    "Reads an image file as a texture.")
        .def_property_readonly("size", [](const PyTexture& t) {
            return py::make_tuple(t.map.image->rows, t.map.image->columns);
        }, "(rows, columns).")
        .def_property_readonly("wrap", [](const PyTexture& t) {
            return py::make_tuple(to_string(t.map.wrap_s), to_string(t.map.wrap_t));
        }, "(wrap_s, wrap_t).")
        .def("sample", [](const PyTexture& t, double s, double tc) {
            const glm::dvec3 v = sample_bilinear(t.map, s, tc);
            return py::make_tuple(v.x, v.y, v.z);
        }, py::arg("s"), py::arg("t"), "The contract's bilinear lookup T(s, t), in double precision.");

    py::class_<PyMaterial>(module, "Material", R"(A face material (contract "Materials").

Material(ka=None, kd=None, ks=None, n=None, texture=None, color_factor=None,
name=""): each coefficient a number or RGB, or None to leave it to the
scene's material or the defaults (the scene's and an object's fields win over
a face's); texture a phongrast.Texture multiplying the surface colour;
color_factor an RGB factor on the colour (glTF baseColorFactor).)")
        .def(py::init([](const py::object& ka, const py::object& kd, const py::object& ks, const py::object& n,
                         const py::object& texture, const py::object& color_factor, const std::string& name) {
                 PyMaterial result;
                 result.material.name = name;
                 result.material.coefficients = read_material_fields(ka, kd, ks, n, "material");
                 if (!texture.is_none()) result.material.texture = texture.cast<const PyTexture&>().map;
                 if (!color_factor.is_none()) {
                     result.material.color_factor = glm::vec3(read_vec3(color_factor, "color_factor", true));
                 }
                 return result;
             }),
             py::arg("ka") = py::none(), py::arg("kd") = py::none(), py::arg("ks") = py::none(),
             py::arg("n") = py::none(), py::arg("texture") = py::none(), py::arg("color_factor") = py::none(),
             py::arg("name") = "")
        .def_property_readonly("fields", [](const PyMaterial& m) { return fields_dict(m.material.coefficients); },
                               "The coefficients it sets, as a dict.")
        .def_property_readonly("has_texture", [](const PyMaterial& m) { return m.material.texture.has_value(); })
        .def_property_readonly("name", [](const PyMaterial& m) { return m.material.name; });
}

/// The objects of a scene as dicts (mesh, transform, material, normals, name).
py::list objects_list(const PyScene& s) {
    py::list list;
    for (const SceneObject& object : s.scene->objects) {
        py::dict d;
        // A read-only view of the shared mesh; kept alive with the scene's objects.
        d["mesh"] = PyMesh{std::const_pointer_cast<Mesh>(object.mesh), false};
        py::array_t<double> transform({4, 4});
        for (int row = 0; row < 4; ++row) {
            for (int column = 0; column < 4; ++column) transform.mutable_at(row, column) = object.transform[column][row];
        }
        d["transform"] = transform;
        d["material"] = fields_dict(object.material);
        d["normals"] = object.normals ? py::object(py::str(to_string(*object.normals))) : py::object(py::none());
        d["name"] = object.name;
        list.append(d);
    }
    return list;
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
    scene.def_property("camera", [](const PyScene& s) { return s.scene->camera; },
                       [](PyScene& s, const Camera& camera) {
                           make_camera_frame(camera, 1, 1);  // validated when set, naming the field
                           s.scene->camera = camera;
                       }, "The camera (a copy): phongrast.Camera. eye, lookat, up, focal and sensor edit a look-at "
                          "or orthographic camera's fields.");
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
                           if (!s.scene->objects.empty()) {
                               throw py::value_error("mesh: this scene places " +
                                                     std::to_string(s.scene->objects.size()) +
                                                     " objects; a scene has one mesh or objects, not both");
                           }
                           // A new Scene, so arrays still viewing the old mesh stay valid.
                           auto replaced = std::make_shared<Scene>(*s.scene);
                           replaced->mesh = *m.mesh;
                           s.scene = std::move(replaced);
                       }, "The scene's mesh (a view: editing its arrays edits the scene). Setting it copies the mesh.");
    scene.def_property_readonly("objects", &objects_list,
                                "The scene's objects (a scene file's \"objects\"): a list of dicts with mesh "
                                "(read-only, shared by the objects placing one file), transform (4 x 4), "
                                "material (the fields it overrides), normals and name. Empty for a one-mesh scene.");
    scene.def_property("normals", [](const PyScene& s) { return std::string(to_string(s.scene->normals)); },
                       [](PyScene& s, const std::string& v) {
                           try {
                               s.scene->normals = parse_normal_source(v);
                           } catch (const std::invalid_argument& error) {
                               throw py::value_error(error.what());
                           }
                       }, "\"computed\" (default) or \"file\": where vertex normals come from.");
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

    module.def("release_render_memory", [] { release_render_memory(); },
               "release_render_memory() -> None\n\n"
               "Frees the working memory that render() and render_object() keep for the calling thread's next call "
               "(kept after frames of at most 262,144 triangles and 2048 x 2048 samples; freed anyway when the "
               "thread ends). The pictures do not depend on it.");

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
    bind_materials(module);
    py::class_<PyScene> scene(module, "Scene", R"(Everything a scene file describes, with its meshes loaded.

Scene.load(path) reads a scene file (docs/scene-format.md) and its meshes, or
frames a mesh file alone, through the library's scene builder (the one the
phongrast command uses); Scene.from_dict(d, folder=".") the same fields as a
dict ("mesh" may be a path relative to folder, or a phongrast.Mesh; so may
each of "objects"' meshes, with "transform" a 4 x 4 array or translation,
rotation, scale); Scene.from_mesh(mesh, rows, columns) frames a mesh
automatically. Every field is a property.)");
    scene.def_static("load", [](const std::string& path, py::object mesh) {
                         if (mesh.is_none()) return scene_from_loaded(io::load_scene(path));
                         return complete_scene(io::read_scene_file(path), path, mesh);
                     }, py::arg("path"), py::arg("mesh") = py::none(),
                     "Reads a scene file and its meshes (or uses `mesh` for its \"mesh\"), or frames a mesh file.")
        .def_static("from_dict", &scene_from_dict, py::arg("description"), py::arg("folder") = ".",
                    "A scene from a dict with the scene file's fields; numpy arrays are fine as values.")
        .def_static("from_mesh", [](const PyMesh& mesh, int rows, int columns) {
                        return PyScene{std::make_shared<Scene>(io::frame_mesh(*mesh.mesh, rows, columns)), {}};
                    }, py::arg("mesh"), py::arg("rows") = 512, py::arg("columns") = 512,
                    "Frames the mesh as `phongrast render mesh.obj` does (camera, three lights, neutral material).")
        .def("frame", [](PyScene& s, const py::object& rows, const py::object& columns) {
                 const int m = rows.is_none() ? s.scene->image.rows : read_int(rows, "rows", 1, 32768);
                 const int n = columns.is_none() ? s.scene->image.columns : read_int(columns, "columns", 1, 32768);
                 auto framed = std::make_shared<Scene>(*s.scene);
                 try {
                     io::frame_scene(*framed, m, n);
                 } catch (const std::invalid_argument& error) {
                     throw py::value_error(error.what());
                 }
                 s.scene = std::move(framed);
             }, py::arg("rows") = py::none(), py::arg("columns") = py::none(),
             "Frames every object (in world space) as phongrast render frames a mesh alone: camera, image size, "
             "ambient, three lights and the neutral base material. Meshes, objects, shader and lighting stay.")
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
       "the depth, distance, normal, id and alpha arrays the file holds, as render(..., aovs=...) returns them.");
}

}  // namespace phongrast::python
