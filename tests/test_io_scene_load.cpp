// io::load_scene, the one scene builder: each mesh file read once however
// many objects place it, the contract's material precedence, a mesh alone
// framed with its file's normals, a version-1 scene exactly as before, and
// the errors that name the scene file and the object.
#include <cmath>

#include <catch2/catch.hpp>

#include "io_test_files.hpp"
#include "phongrast/camera.hpp"
#include "phongrast/io/auto_scene.hpp"
#include "phongrast/io/error.hpp"
#include "phongrast/io/mesh_file.hpp"
#include "phongrast/io/scene_file.hpp"
#include "phongrast/io/scene_load.hpp"

using Catch::Matchers::Contains;
using namespace phongrast;

namespace {

const char* const triangle_obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
const char* const square_obj = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n";
const char* const camera_and_image = R"(
  "camera": { "eye": [0.3, 0.3, 5], "lookat": [0.3, 0.3, 0], "focal": 2, "sensor": [1, 1] },
  "image": { "height": 16, "width": 16 },
  "lights": [{ "position": [0, 0, 5], "intensity": [1, 1, 1] }])";

std::string scene_text(const std::string& fields) { return "{" + fields + "," + camera_and_image + "}"; }

/// The material a face ends up with, by the contract's precedence: the
/// object's fields, the scene's, the face's own, the base.
PhongMaterial effective(const Scene& scene, const Mesh& mesh, const MaterialFields& object, std::size_t triangle) {
    MaterialFields fields = object.or_else(scene.material_fields);
    if (triangle < mesh.face_materials.size() && mesh.face_materials[triangle] != kNoIndex) {
        fields = fields.or_else(mesh.materials[mesh.face_materials[triangle]].coefficients);
    }
    return fields.over(scene.material);
}

}  // namespace

TEST_CASE("the same mesh file placed many times is read once and shared") {
    TemporaryFolder folder;
    folder.write("tri.obj", triangle_obj);
    folder.write("square.obj", square_obj);
    const std::string path = folder.write(
        "scene.json", scene_text(R"("objects": [{ "mesh": "tri.obj" }, { "mesh": "./tri.obj", "translation": [1, 0, 0] },
                                                { "mesh": "square.obj" }, { "mesh": "tri.obj", "scale": -1 }])"));
    int reads = 0;
    io::SceneLoadOptions options;
    options.read_mesh = [&reads](const std::string& file) {
        ++reads;
        return std::make_shared<const io::MeshFile>(io::read_mesh(file));
    };
    const io::LoadedScene loaded = io::load_scene(path, options);
    const Scene& scene = loaded.scene;
    REQUIRE(scene.objects.size() == 4);
    CHECK(reads == 2);
    CHECK(loaded.meshes_read == 2);
    CHECK(scene.objects[0].mesh.get() == scene.objects[1].mesh.get());
    CHECK(scene.objects[0].mesh.get() == scene.objects[3].mesh.get());
    CHECK(scene.objects[0].mesh.get() != scene.objects[2].mesh.get());
    CHECK(scene.objects[2].mesh->triangles.size() == 2);
    CHECK(scene.objects[1].transform[3] == glm::dvec4(1, 0, 0, 1));
    CHECK(scene.objects[3].transform[0][0] == -1.0);
    CHECK(scene.mesh.positions.empty());  // a scene of objects leaves `mesh` empty
    CHECK(loaded.mesh_path.empty());
    CHECK(loaded.name == "scene");
}

TEST_CASE("materials: the object's fields, the scene's, the face's own, then the defaults") {
    TemporaryFolder folder;
    folder.write("plain.obj", triangle_obj);
    folder.write("shiny.mtl", "newmtl shiny\nKa 0.5 0.5 0.5\nKd 0.25 0.25 0.25\nKs 0.75 0.75 0.75\nNs 64\n");
    folder.write("shiny.obj", std::string("mtllib shiny.mtl\nusemtl shiny\n") + triangle_obj);
    const std::string path = folder.write(
        "scene.json", scene_text(R"("material": { "kd": 0.6 },
            "objects": [{ "mesh": "plain.obj" }, { "mesh": "shiny.obj" },
                        { "mesh": "shiny.obj", "material": { "kd": 0.1, "n": 5 } }])"));
    const io::LoadedScene loaded = io::load_scene(path);
    const Scene& scene = loaded.scene;
    REQUIRE(scene.objects.size() == 3);
    // Scene::material_fields: the scene's own fields; Scene::material: the base.
    CHECK(*scene.material_fields.kd == glm::vec3(0.6f));
    CHECK_FALSE(scene.material_fields.ka);
    CHECK(scene.material.kd == glm::vec3(0.6f));
    CHECK(scene.material.ka == io::default_material().ka);

    const PhongMaterial plain = effective(scene, *scene.objects[0].mesh, scene.objects[0].material, 0);
    CHECK(plain.ka == io::default_material().ka);
    CHECK(plain.kd == glm::vec3(0.6f));
    CHECK(plain.n == io::default_material().n);
    const PhongMaterial shiny = effective(scene, *scene.objects[1].mesh, scene.objects[1].material, 0);
    CHECK(shiny.ka == glm::vec3(0.5f));   // the MTL's
    CHECK(shiny.kd == glm::vec3(0.6f));   // the scene's wins over the MTL's
    CHECK(shiny.ks == glm::vec3(0.75f));
    CHECK(shiny.n == 64.0f);
    const PhongMaterial overridden = effective(scene, *scene.objects[2].mesh, scene.objects[2].material, 0);
    CHECK(overridden.kd == glm::vec3(0.1f));  // the object's wins over the scene's
    CHECK(overridden.n == 5.0f);
    CHECK(overridden.ka == glm::vec3(0.5f));
    // plain.obj's face has no material: ka, ks and n came from the defaults.
    CHECK(loaded.defaults_used == std::vector<std::string>{"ka", "ks", "n"});
    CHECK_THAT(loaded.defaults_note, Contains("no ka, ks, n in " + path) && Contains("using the defaults"));
}

TEST_CASE("a version-1 scene builds exactly as the parts assembled by hand") {
    TemporaryFolder folder;
    folder.write("m.mtl", "newmtl a\nKa 0.2 0.2 0.2\nKd 0.5 0.5 0.5\n");
    folder.write("m.obj", std::string("mtllib m.mtl\nusemtl a\n") + square_obj);
    const std::string path = folder.write("scene.json", scene_text(R"("mesh": "m.obj", "material": { "ks": 0.4 })"));
    const io::LoadedScene loaded = io::load_scene(path);
    io::SceneFile file = io::read_scene_file(path);
    io::MeshFile mesh = io::read_mesh(file.mesh_path);
    Scene by_hand = file.scene;
    by_hand.mesh = mesh.mesh;
    by_hand.material = io::resolve_material(file.material, mesh.material, nullptr);
    CHECK(loaded.scene.objects.empty());
    CHECK(loaded.mesh_path == file.mesh_path);
    CHECK(loaded.scene.mesh.positions == by_hand.mesh.positions);
    CHECK(loaded.scene.mesh.triangles == by_hand.mesh.triangles);
    if (loaded.scene.mesh.face_materials.empty()) {
        // The reader gives the file's material alone: it is the base, under the scene's fields.
        CHECK(loaded.scene.material.ka == by_hand.material.ka);
        CHECK(loaded.scene.material.kd == by_hand.material.kd);
        CHECK(loaded.scene.material.ks == glm::vec3(0.4f));
        CHECK(loaded.scene.material.n == by_hand.material.n);
        CHECK(loaded.defaults_used.empty());
        REQUIRE(mesh.material);
        CHECK(render(loaded.scene).image.pixels == render(by_hand).image.pixels);
    }
    // Either way, every face ends up with the same coefficients.
    const PhongMaterial face = effective(loaded.scene, loaded.scene.mesh, {}, 0);
    CHECK(face.ka == glm::vec3(0.2f));
    CHECK(face.kd == glm::vec3(0.5f));
    CHECK(face.ks == glm::vec3(0.4f));
}

TEST_CASE("the defaults used are said, naming the scene file") {
    TemporaryFolder folder;
    folder.write("m.obj", triangle_obj);
    const std::string path = folder.write("scene.json", scene_text(R"("mesh": "m.obj")"));
    const io::LoadedScene loaded = io::load_scene(path);
    CHECK(loaded.defaults_used == std::vector<std::string>{"ka", "kd", "ks", "n"});
    CHECK_THAT(loaded.defaults_note, Contains("no ka, kd, ks, n in " + path + " (and the mesh has no MTL); using the "
                                              "defaults, material: ka 0.1, kd 0.8, ks 1, n 1"));
}

TEST_CASE("a mesh alone is framed, and uses its file's normals when it has them") {
    TemporaryFolder folder;
    const std::string path = folder.write("tri.obj", triangle_obj);
    io::LoadedScene plain = io::load_scene(path);
    CHECK(plain.framed);
    CHECK(plain.name == "tri");
    CHECK(plain.scene.image.rows == 512);
    CHECK(plain.scene.normals == NormalSource::computed);
    CHECK(plain.scene.camera.lookat == glm::dvec3(0.5, 0.5, 0.0));

    // A reader that gives normals (as OBJ vn, glTF NORMAL, PLY nx ny nz do).
    io::SceneLoadOptions options;
    options.rows = 30;
    options.columns = 40;
    options.read_mesh = [](const std::string& file) {
        auto mesh = std::make_shared<io::MeshFile>(io::read_mesh(file));
        mesh->mesh.file_normals = {glm::vec3(0, 0, 1)};
        mesh->mesh.file_normal_triangles = {{0, 0, 0}};
        return std::shared_ptr<const io::MeshFile>(mesh);
    };
    const io::LoadedScene with_normals = io::load_scene(path, options);
    CHECK(with_normals.scene.normals == NormalSource::file);
    CHECK(with_normals.scene.image.rows == 30);
    CHECK(with_normals.scene.image.columns == 40);
    CHECK_THAT(io::scene_to_json(with_normals.scene, path), Contains("\"normals\": \"file\""));
    CHECK_THAT(io::scene_to_json(plain.scene, path), !Contains("\"normals\""));
}

TEST_CASE("a scene from text resolves meshes against the folder given, and takes a size") {
    TemporaryFolder folder;
    folder.write("m.obj", triangle_obj);
    io::SceneLoadOptions options;
    options.rows = 9;
    options.columns = 7;
    const io::LoadedScene loaded =
        io::load_scene_text(scene_text(R"("objects": [{ "mesh": "m.obj", "normals": "file" }], "extra": 1)"),
                            "line 3", folder.file(""), options);
    REQUIRE(loaded.scene.objects.size() == 1);
    CHECK(*loaded.scene.objects[0].normals == NormalSource::file);
    CHECK(loaded.scene.image.rows == 9);
    CHECK(loaded.scene.image.columns == 7);
    REQUIRE(loaded.warnings.size() == 1);
    CHECK_THAT(loaded.warnings[0], Contains("line 3: ignoring unknown field /extra"));
}

TEST_CASE("meshes in memory stand in for files") {
    auto mesh = std::make_shared<Mesh>();
    mesh->positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    mesh->triangles = {{0, 1, 2}};
    io::SceneLoadOptions options;
    options.object_meshes = {mesh, nullptr, mesh};
    TemporaryFolder folder;
    folder.write("m.obj", square_obj);
    const io::LoadedScene loaded = io::load_scene_text(
        scene_text(R"("objects": [{ "mesh": "memory" }, { "mesh": "m.obj" }, { "mesh": "memory", "scale": 2 }])"),
        "dict", folder.file(""), options);
    REQUIRE(loaded.scene.objects.size() == 3);
    CHECK(loaded.scene.objects[0].mesh.get() == mesh.get());
    CHECK(loaded.scene.objects[2].mesh.get() == mesh.get());
    CHECK(loaded.scene.objects[1].mesh->triangles.size() == 2);
    CHECK(loaded.meshes_read == 1);

    io::SceneLoadOptions single;
    single.mesh = mesh;
    const io::LoadedScene replaced = io::load_scene_text(scene_text(R"("mesh": "nowhere.obj")"), "dict", "", single);
    CHECK(replaced.scene.mesh.positions == mesh->positions);
}

TEST_CASE("bad inputs name the scene file, the object and what was expected") {
    TemporaryFolder folder;
    folder.write("m.obj", triangle_obj);
    folder.write("broken.obj", "v 0 0 0\nf 1 2 3\n");
    const std::string missing =
        folder.write("missing.json", scene_text(R"("objects": [{ "mesh": "m.obj" }, { "mesh": "gone.obj" }])"));
    CHECK_THROWS_WITH(io::load_scene(missing),
                      Contains("missing.json: /objects/1/mesh: ") && Contains("gone.obj: mesh not found"));
    const std::string broken = folder.write("broken.json", scene_text(R"("objects": [{ "mesh": "broken.obj" }])"));
    CHECK_THROWS_WITH(io::load_scene(broken), Contains("broken.json: /objects/0/mesh: ") && Contains("broken.obj:2"));
    const std::string no_mesh = folder.write("none.json", scene_text(R"("shader": "flat")"));
    CHECK_THROWS_WITH(io::load_scene(no_mesh), Contains("none.json: /mesh: missing required field"));
    const std::string single_missing = folder.write("single.json", scene_text(R"("mesh": "gone.obj")"));
    CHECK_THROWS_WITH(io::load_scene(single_missing), Contains("single.json: /mesh: ") && Contains("gone.obj: mesh not found"));

    const std::string objects = folder.write("objects.json", scene_text(R"("objects": [{ "mesh": "m.obj" }])"));
    io::SceneLoadOptions override_mesh;
    override_mesh.mesh_override = folder.file("m.obj");
    CHECK_THROWS_WITH(io::load_scene(objects, override_mesh),
                      Contains("objects.json: /objects: the scene places several objects; a replacement mesh"));
    CHECK_THROWS_AS(io::load_scene(folder.file("no_such.json")), io::FileError);
}

TEST_CASE("frame_scene frames every object in world space, on one mesh it is frame_mesh") {
    TemporaryFolder folder;
    folder.write("tri.obj", triangle_obj);
    const std::string path = folder.write(
        "scene.json", scene_text(R"("objects": [{ "mesh": "tri.obj" }, { "mesh": "tri.obj", "translation": [40, -3, 2] },
                                                { "mesh": "tri.obj", "scale": [-5, 1, 1] }])"));
    Scene scene = io::load_scene(path).scene;
    io::frame_scene(scene, 60, 80);
    CHECK(scene.image.rows == 60);
    CHECK(scene.image.columns == 80);
    const CameraFrame frame = make_camera_frame(scene.camera, 60, 80);
    for (const SceneObject& object : scene.objects) {
        for (const glm::dvec3& p : object.mesh->positions) {
            const glm::dvec3 c = frame.camera_from_world(glm::dvec3(object.transform * glm::dvec4(p, 1.0)));
            REQUIRE(c.z > 0.0);
            const double x = scene.camera.focal * c.x / c.z;
            const double y = scene.camera.focal * c.y / c.z;
            CHECK(std::abs(x) <= scene.camera.sensor_width / 2);   // inside, with the 10% margin
            CHECK(std::abs(y) <= scene.camera.sensor_height / 2);
        }
    }
    CHECK(scene.camera.lookat.x == Approx((41.0 + -5.0) / 2));  // the box of every object's vertices

    Mesh mesh = io::read_mesh(folder.file("tri.obj")).mesh;
    Scene single;
    single.mesh = mesh;
    io::frame_scene(single, 30, 40);
    const Scene framed = io::frame_mesh(mesh, 30, 40);
    CHECK(single.camera.eye == framed.camera.eye);
    CHECK(single.camera.sensor_height == framed.camera.sensor_height);
    CHECK(single.lights.size() == framed.lights.size());

    Scene empty;
    CHECK_THROWS_AS(io::frame_scene(empty, 8, 8), std::invalid_argument);
}
