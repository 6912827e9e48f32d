// Turntable views of an automatically framed mesh: the first view is the
// framing itself, the camera and lights turn together about the vertical
// axis, and every vertex stays in the picture in every view.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <thread>

#include <glm/geometric.hpp>

#include "batch_views.hpp"
#include "io_test_files.hpp"
#include "phongrast/io/error.hpp"
#include "phongrast/camera.hpp"
#include "phongrast/io/auto_scene.hpp"
#include "phongrast/io/image_file.hpp"
#include "phongrast/io/mesh_file.hpp"
#include "phongrast/render.hpp"

using namespace phongrast;
using namespace phongrast::cli;

namespace {

/// A long thin box: its framing from the front differs from its framing from the side.
Mesh long_box() {
    Mesh mesh;
    for (int i = 0; i < 8; ++i) mesh.positions.push_back({i & 1 ? 3.0 : -3.0, i & 2 ? 0.5 : -0.5, i & 4 ? 0.4 : -0.4});
    mesh.triangles = {{0, 1, 3}, {0, 3, 2}, {4, 6, 7}, {4, 7, 5}};
    return mesh;
}

}  // namespace

TEST_CASE("one view without elevation is exactly the framing of `render mesh.obj`") {
    const Scene framed = io::frame_mesh(long_box(), 48, 64);
    JobScenes scenes;
    make_turntable(framed, 1, 0.0, scenes);
    REQUIRE(scenes.cameras.size() == 1);
    CHECK(scenes.cameras[0].eye == framed.camera.eye);
    CHECK(scenes.cameras[0].sensor_height == framed.camera.sensor_height);
    CHECK(scenes.cameras[0].sensor_width == framed.camera.sensor_width);
    CHECK(scenes.lights[0][0].position == framed.lights[0].position);
}

TEST_CASE("turntable views circle the look-at point with the lights, every vertex in every picture") {
    const Scene framed = io::frame_mesh(long_box(), 48, 64);
    const glm::dvec3 centre = framed.camera.lookat;
    const double distance = glm::length(framed.camera.eye - centre);
    JobScenes scenes;
    make_turntable(framed, 4, 30.0, scenes);
    REQUIRE(scenes.cameras.size() == 4);
    REQUIRE(scenes.lights.size() == 4);
    const double key_light_angle = glm::dot(glm::normalize(scenes.lights[0][0].position - centre),
                                            glm::normalize(scenes.cameras[0].eye - centre));
    for (int view = 0; view < 4; ++view) {
        INFO("view " << view);
        const Camera& camera = scenes.cameras[static_cast<std::size_t>(view)];
        const glm::dvec3 offset = camera.eye - centre;
        CHECK(glm::length(offset) == Approx(distance));
        CHECK(offset.y == Approx(distance * 0.5));  // 30 degrees up
        CHECK(camera.lookat == centre);
        // The key light keeps its place relative to the camera.
        const glm::dvec3 light = scenes.lights[static_cast<std::size_t>(view)][0].position - centre;
        CHECK(glm::dot(glm::normalize(light), glm::normalize(offset)) == Approx(key_light_angle));
        CHECK(glm::length(light) == Approx(glm::length(framed.lights[0].position - centre)));
        CHECK(camera.sensor_height == scenes.cameras[0].sensor_height);  // the same scale in every view
        const CameraFrame frame = make_camera_frame(camera, 48, 64);
        for (const glm::dvec3& vertex : framed.mesh.positions) {
            const ProjectedPoint point = frame.project(vertex);
            CHECK(point.column > 0.0);
            CHECK(point.column < 64.0);
            CHECK(point.row > 0.0);
            CHECK(point.row < 48.0);
        }
    }
    // A quarter turn looks at the box's end: the eye moved from +z to +x.
    CHECK(scenes.cameras[1].eye.x - centre.x == Approx(distance * std::cos(std::acos(-1.0) / 6.0)));
    CHECK(scenes.cameras[1].eye.z - centre.z == Approx(0.0).margin(1e-9));
}

namespace {

/// Every vertex of `framed`'s mesh projects inside the image in every view.
void check_every_vertex_inside(const Scene& framed, const JobScenes& scenes) {
    for (std::size_t view = 0; view < scenes.cameras.size(); ++view) {
        INFO("view " << view);
        const CameraFrame frame = make_camera_frame(scenes.cameras[view], framed.image.rows, framed.image.columns);
        for (const glm::dvec3& vertex : framed.mesh.positions) {
            const ProjectedPoint point = frame.project(vertex);
            CHECK(point.depth > 0.0);
            CHECK(point.column > 0.0);
            CHECK(point.column < framed.image.columns);
            CHECK(point.row > 0.0);
            CHECK(point.row < framed.image.rows);
        }
    }
}

}  // namespace

TEST_CASE("a sphere layout spreads its views evenly over every direction, deterministically") {
    const Scene framed = io::frame_mesh(long_box(), 48, 64);
    const glm::dvec3 centre = framed.camera.lookat;
    const double distance = glm::length(framed.camera.eye - centre);
    JobScenes scenes;
    make_views(framed, lattice_directions(50, false), scenes);
    REQUIRE(scenes.cameras.size() == 50);
    std::vector<glm::dvec3> directions;
    glm::dvec3 mean(0.0);
    for (const Camera& camera : scenes.cameras) {
        CHECK(glm::length(camera.eye - centre) == Approx(distance));
        CHECK(camera.lookat == centre);
        CHECK(camera.sensor_height == scenes.cameras[0].sensor_height);  // the same scale in every view
        directions.push_back(glm::normalize(camera.eye - centre));
        mean += directions.back() / 50.0;
    }
    CHECK(glm::length(mean) < 0.02);  // balanced: no side of the object favoured
    // Even: every view's nearest neighbour is about as far as any other's
    // (for 50 points, about sqrt(4 pi / 50) = 0.5 radians).
    double closest = 10.0, farthest = 0.0;
    for (std::size_t i = 0; i < directions.size(); ++i) {
        double nearest = 10.0;
        for (std::size_t j = 0; j < directions.size(); ++j) {
            if (i != j) nearest = std::min(nearest, std::acos(std::min(1.0, glm::dot(directions[i], directions[j]))));
        }
        closest = std::min(closest, nearest);
        farthest = std::max(farthest, nearest);
    }
    CHECK(closest > 0.3);
    CHECK(farthest < 0.6);
    check_every_vertex_inside(framed, scenes);
    // No seed: the same layout again gives the same cameras, bit for bit.
    JobScenes again;
    make_views(framed, lattice_directions(50, false), again);
    for (std::size_t i = 0; i < 50; ++i) CHECK(again.cameras[i].eye == scenes.cameras[i].eye);
}

TEST_CASE("a hemisphere layout stays above the horizontal, one view of any layout is the framing") {
    const Scene framed = io::frame_mesh(long_box(), 48, 64);
    const glm::dvec3 centre = framed.camera.lookat;
    REQUIRE(framed.camera.eye.y == Approx(centre.y));  // the framing looks horizontally
    JobScenes scenes;
    make_views(framed, lattice_directions(20, true), scenes);
    REQUIRE(scenes.cameras.size() == 20);
    for (const Camera& camera : scenes.cameras) CHECK(camera.eye.y > centre.y);
    check_every_vertex_inside(framed, scenes);
    for (const ViewDirection& direction : lattice_directions(100000, false)) {
        REQUIRE(std::abs(direction.elevation) < std::acos(-1.0) / 2.0);  // never straight up or down
    }
    JobScenes one;
    make_views(framed, lattice_directions(1, false), one);
    CHECK(one.cameras[0].eye == framed.camera.eye);
    CHECK(one.cameras[0].sensor_height == framed.camera.sensor_height);
}

TEST_CASE("elevation rings: one turntable per elevation, ring after ring") {
    const Scene framed = io::frame_mesh(long_box(), 48, 64);
    const glm::dvec3 centre = framed.camera.lookat;
    const double distance = glm::length(framed.camera.eye - centre);
    JobScenes scenes;
    make_views(framed, turntable_directions(4, {-30.0, 0.0, 30.0}), scenes);
    REQUIRE(scenes.cameras.size() == 12);
    for (std::size_t view = 0; view < 12; ++view) {
        INFO("view " << view);
        const double expected_height = distance * std::sin((static_cast<double>(view / 4) - 1.0) * std::acos(-1.0) / 6.0);
        CHECK(scenes.cameras[view].eye.y - centre.y == Approx(expected_height).margin(1e-9));
    }
    check_every_vertex_inside(framed, scenes);
    // Within a ring, views 90 degrees apart: the horizontal offsets turn by a quarter.
    const glm::dvec3 first = scenes.cameras[4].eye - centre, second = scenes.cameras[5].eye - centre;
    CHECK(first.x * second.x + first.z * second.z == Approx(0.0).margin(1e-9));
}

TEST_CASE("parsed meshes are kept across jobs in any order, and read again when the file changes") {
    TemporaryFolder folder;
    const std::string a = folder.write("a.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    const std::string b = folder.write("b.obj", "v 0 0 0\nv 2 0 0\nv 0 2 0\nv 2 2 0\nf 1 2 3\nf 2 4 3\n");
    MeshFileCache meshes;
    const auto first_a = meshes.read(a);
    const auto first_b = meshes.read(b);
    CHECK(first_a->mesh.positions.size() == 3);
    CHECK(first_b->mesh.positions.size() == 4);
    // A, B, A, B: never the same mesh twice in a row, still each parsed once.
    CHECK(meshes.read(a).get() == first_a.get());
    CHECK(meshes.read(b).get() == first_b.get());
    CHECK(meshes.read(folder.file("./a.obj")).get() == first_a.get());  // the same file by another name
    CHECK(meshes.parses() == 2);
    CHECK(meshes.files() == 2);
    CHECK(meshes.bytes() == mesh_file_bytes(*first_a) + mesh_file_bytes(*first_b));

    folder.write("a.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 2 4 3\n");
    CHECK(meshes.read(a)->mesh.positions.size() == 4);
    CHECK(meshes.parses() == 3);
    CHECK(meshes.files() == 2);  // the old a.obj is gone, not kept beside the new one
    folder.write("a.obj", "v 0 0 0\nf 1 2 3\n");
    CHECK_THROWS_AS(meshes.read(a), phongrast::io::FileError);
    CHECK(meshes.files() == 1);  // the stale a.obj was dropped, the failure not kept
    CHECK_THROWS_AS(meshes.read(folder.file("missing.obj")), phongrast::io::FileError);
    CHECK(meshes.read(b).get() == first_b.get());
}

TEST_CASE("a cached OBJ is read again when its MTL file or texture changes, or a missing MTL appears") {
    TemporaryFolder folder;
    const std::string obj = folder.write("m.obj",
                                         "mtllib m.mtl\nmtllib later.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\n"
                                         "vt 0 0\nvt 1 0\nvt 0 1\nusemtl red\nf 1/1 2/2 3/3\n");
    folder.write("m.mtl", "newmtl red\nKd 1 0 0\nmap_Kd t.png\n");
    io::write_image(Image(1, 2, glm::vec3(0.0f, 1.0f, 0.0f)), folder.file("t.png"));
    MeshFileCache meshes;
    const auto first = meshes.read(obj);
    REQUIRE(first->mesh.materials.size() == 1);
    CHECK(first->mesh.materials[0].coefficients.kd == glm::vec3(1, 0, 0));
    REQUIRE(first->mesh.materials[0].texture->image);
    CHECK(first->mesh.materials[0].texture->image->at(0, 1) == glm::vec3(0, 1, 0));
    CHECK(meshes.read(obj).get() == first.get());

    // Edits change the size: file times may not tick between two quick writes.
    folder.write("m.mtl", "newmtl red\nKd 0 0 0.5\nmap_Kd t.png\n");
    const auto edited_mtl = meshes.read(obj);
    CHECK(edited_mtl->mesh.materials[0].coefficients.kd == glm::vec3(0, 0, 0.5f));
    CHECK(meshes.read(obj).get() == edited_mtl.get());

    io::write_image(Image(1, 3, glm::vec3(1.0f, 1.0f, 0.0f)), folder.file("t.png"));
    const auto edited_texture = meshes.read(obj);
    CHECK(edited_texture.get() != edited_mtl.get());
    CHECK(edited_texture->mesh.materials[0].texture->image->at(0, 1) == glm::vec3(1, 1, 0));

    folder.write("later.mtl", "newmtl blue\nKd 0 0 1\n");  // named by the OBJ, missing until now
    CHECK(meshes.read(obj).get() != edited_texture.get());
    CHECK(meshes.parses() == 4);
    CHECK(meshes.files() == 1);
}

TEST_CASE("past the memory budget the least recently used meshes are dropped, the newest always kept") {
    TemporaryFolder folder;
    const std::string a = folder.write("a.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    const std::string b = folder.write("b.obj", "v 0 0 0\nv 2 0 0\nv 0 2 0\nf 1 2 3\n");
    const std::string c = folder.write("c.obj", "v 0 0 0\nv 3 0 0\nv 0 3 0\nf 1 2 3\n");
    const std::size_t one = mesh_file_bytes(io::read_mesh(a));
    MeshFileCache two_fit(2 * one + one / 2);
    two_fit.read(a);
    two_fit.read(b);
    two_fit.read(a);  // a is now more recent than b
    two_fit.read(c);  // over the budget: b goes
    CHECK(two_fit.files() == 2);
    CHECK(two_fit.parses() == 3);
    two_fit.read(a);
    two_fit.read(c);
    CHECK(two_fit.parses() == 3);
    two_fit.read(b);
    CHECK(two_fit.parses() == 4);
    CHECK(two_fit.bytes() <= 2 * one + one / 2);

    MeshFileCache none_fit(1);  // each mesh alone is over the budget: the last one stays, like a last-mesh cache
    const auto kept = none_fit.read(a);
    CHECK(none_fit.read(a).get() == kept.get());
    none_fit.read(b);
    CHECK(none_fit.files() == 1);
    none_fit.read(a);
    CHECK(none_fit.parses() == 3);
}

TEST_CASE("a plain mesh's jobs get the normals the renderer computes, computed once per mesh, the same pictures") {
    TemporaryFolder folder;
    // A cone: smooth sides, one apex shared by every side, a degenerate face
    // and an unused vertex (whose computed normal is zero).
    std::string obj = "v 0 2 0\n";
    const int sides = 12;
    for (int i = 0; i < sides; ++i) {
        const double angle = 2.0 * 3.141592653589793 * i / sides;
        obj += "v " + std::to_string(std::cos(angle)) + " 0 " + std::to_string(std::sin(angle)) + "\n";
    }
    obj += "v 5 5 5\n";
    for (int i = 0; i < sides; ++i) obj += "f 1 " + std::to_string(2 + (i + 1) % sides) + " " + std::to_string(2 + i) + "\n";
    obj += "f 2 2 3\n";
    folder.write("cone.obj", obj);
    folder.write("textured.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\n");
    const Manifest manifest =
        parse_manifest("{\"mesh\": \"cone.obj\", \"size\": \"40x30\"}\n"
                       "{\"mesh\": \"cone.obj\", \"views\": 3, \"elevation\": 20, \"size\": \"40x30\", \"output\": \"t{view}.png\"}\n"
                       "{\"mesh\": \"cone.obj\", \"size\": \"40x30\", \"shader\": \"gouraud\", \"output\": \"g.png\"}\n"
                       "{\"mesh\": \"textured.obj\", \"size\": \"40x30\"}\n",
                       "jobs.jsonl", folder.file(""), JobSettings{});
    MeshFileCache meshes;
    Renderer renderer;
    for (std::size_t j = 0; j < 3; ++j) {
        INFO("job " << j);
        JobScenes scenes = load_job(manifest.jobs[j], 0, &meshes);
        const Mesh& mesh = scenes.prepared.scene.mesh;
        REQUIRE(mesh.normals == calculate_normals(mesh));
        CHECK(mesh.normals.back() == glm::vec3(0.0f));  // the unused vertex
        // Each view's picture is the one drawn from the mesh without normals, bit for bit.
        Scene without = scenes.prepared.scene;
        without.mesh.normals.clear();
        renderer.set_options(scenes.prepared.options);
        for (std::size_t view = 0; view < scenes.cameras.size(); ++view) {
            scenes.prepared.scene.camera = without.camera = scenes.cameras[view];
            scenes.prepared.scene.lights = without.lights = scenes.lights[view];
            const Image given = renderer.render(scenes.prepared.scene).image;
            const Image computed = renderer.render(without).image;
            CHECK(given.pixels == computed.pixels);
        }
    }
    CHECK(meshes.parses() == 1);
    CHECK(meshes.normals_computed() == 1);
    // Contract version 2 (here texture coordinates): assembly computes its own, none are given.
    CHECK(load_job(manifest.jobs[3], 0, &meshes).prepared.scene.mesh.normals.empty());
    CHECK(meshes.normals_computed() == 1);
    // Without the cache the renderer computes them, as `render` does.
    CHECK(load_job(manifest.jobs[0], 0).prepared.scene.mesh.normals.empty());
}

TEST_CASE("loaders reading at once parse each mesh once, and get the same parsed file") {
    TemporaryFolder folder;
    std::string big = "v 0 0 0\n";  // a few thousand faces, so that the parses overlap
    for (int i = 1; i <= 3000; ++i) big += "v " + std::to_string(i) + " 1 0\nf 1 " + std::to_string(i) + " " + std::to_string(i + 1) + "\n";
    big += "v 0 2 0\n";
    const std::string a = folder.write("a.obj", big);
    const std::string b = folder.write("b.obj", big + "v 5 5 5\n");
    MeshFileCache meshes;
    std::vector<std::shared_ptr<const io::MeshFile>> got(8);
    std::vector<std::thread> loaders;
    for (std::size_t i = 0; i < got.size(); ++i) {
        loaders.emplace_back([&, i] { got[i] = meshes.read(i % 2 == 0 ? a : b); });
    }
    for (std::thread& loader : loaders) loader.join();
    CHECK(meshes.parses() == 2);
    CHECK(meshes.files() == 2);
    for (std::size_t i = 2; i < got.size(); ++i) CHECK(got[i].get() == got[i % 2].get());
    CHECK(got[0]->mesh.positions.size() == 3002);
    CHECK(got[1]->mesh.positions.size() == 3003);
}

TEST_CASE("a mesh job asking what an earlier one asked gets its scenes again, made again when the mesh changes") {
    TemporaryFolder folder;
    folder.write("a.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0.5\nf 1 2 3\nf 2 4 3\n");
    folder.write("b.obj", "v 0 0 0\nv 2 0 0\nv 0 2 0\nf 1 2 3\n");
    const Manifest manifest =
        parse_manifest("{\"mesh\": \"a.obj\", \"size\": \"40x30\", \"views\": 2, \"output\": \"a1-{view}.png\"}\n"
                       "{\"mesh\": \"b.obj\", \"size\": \"40x30\", \"output\": \"b1.png\"}\n"
                       "{\"mesh\": \"a.obj\", \"size\": \"40x30\", \"views\": 2, \"output\": \"a2-{view}.png\"}\n"
                       "{\"mesh\": \"a.obj\", \"size\": \"40x30\", \"views\": 3, \"output\": \"a3-{view}.png\"}\n"
                       "{\"mesh\": \"a.obj\", \"size\": \"40x30\", \"views\": 2, \"shader\": \"gouraud\", \"output\": \"a4-{view}.png\"}\n"
                       "{\"mesh\": \"a.obj\", \"size\": \"40x30\", \"views\": 2, \"elevation\": 30, \"output\": \"a5-{view}.png\"}\n",
                       "jobs.jsonl", folder.file(""), JobSettings{});
    MeshFileCache meshes;
    JobScenesMemo memo(meshes);
    const auto same = [](const JobScenes& x, const JobScenes& y) {
        return x.prepared.scene.mesh.positions == y.prepared.scene.mesh.positions &&
               x.prepared.scene.mesh.normals == y.prepared.scene.mesh.normals &&
               x.prepared.scene.mesh.triangles == y.prepared.scene.mesh.triangles &&
               x.prepared.scene.shader == y.prepared.scene.shader && x.cameras.size() == y.cameras.size() &&
               std::equal(x.cameras.begin(), x.cameras.end(), y.cameras.begin(),
                          [](const Camera& c, const Camera& d) { return c.eye == d.eye && c.lookat == d.lookat && c.sensor_height == d.sensor_height; });
    };
    for (std::size_t j = 0; j < manifest.jobs.size(); ++j) {
        INFO("job " << j);
        const JobScenes remembered = *memo.load(manifest.jobs[j], 0);
        MeshFileCache fresh;
        CHECK(same(remembered, load_job(manifest.jobs[j], 0, &fresh)));  // what a fresh load makes
    }
    CHECK(memo.reuses() == 1);  // only line 3 asks what line 1 asked
    CHECK(memo.kept() == 5);
    CHECK(memo.load(manifest.jobs[1], 0)->prepared.scene.mesh.positions.size() == 3);
    CHECK(memo.reuses() == 2);

    // An edited mesh: made again, from the new file, and kept instead of the old.
    folder.write("b.obj", "v 0 0 0\nv 2 0 0\nv 0 2 0\nv 2 2 1\nf 1 2 3\nf 2 4 3\n");
    const JobScenes edited = *memo.load(manifest.jobs[1], 0);
    CHECK(edited.prepared.scene.mesh.positions.size() == 4);
    MeshFileCache fresh;
    CHECK(same(edited, load_job(manifest.jobs[1], 0, &fresh)));
    CHECK(memo.reuses() == 2);
    CHECK(memo.kept() == 5);
    // A broken mesh fails with load_job's error, and a job with it is not kept.
    folder.write("b.obj", "v 0 0 0\nf 1 2 3\n");
    CHECK_THROWS_AS(memo.load(manifest.jobs[1], 0), phongrast::io::FileError);
    CHECK_THROWS_AS(load_job(manifest.jobs[1], 0), phongrast::io::FileError);
    CHECK(memo.reuses() == 2);
}

TEST_CASE("kept scenes are lent: given back as made, made again while lent, valid when dropped while lent") {
    TemporaryFolder folder;
    folder.write("a.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0.5\nf 1 2 3\nf 2 4 3\n");
    const Manifest manifest =
        parse_manifest("{\"mesh\": \"a.obj\", \"size\": \"40x30\", \"views\": 2, \"output\": \"a1-{view}.png\"}\n"
                       "{\"mesh\": \"a.obj\", \"size\": \"40x30\", \"views\": 2, \"output\": \"a2-{view}.png\"}\n",
                       "jobs.jsonl", folder.file(""), JobSettings{});
    MeshFileCache meshes;
    MeshFileCache fresh_meshes;
    const JobScenes fresh = load_job(manifest.jobs[0], 0, &fresh_meshes);
    // Everything a holder may change, and the mesh it may not.
    const auto as_made = [&](const JobScenes& scenes) {
        const Scene& scene = scenes.prepared.scene;
        const Scene& made = fresh.prepared.scene;
        bool lights = scene.lights.size() == made.lights.size();
        for (std::size_t i = 0; lights && i < scene.lights.size(); ++i) {
            lights = scene.lights[i].position == made.lights[i].position && scene.lights[i].intensity == made.lights[i].intensity;
        }
        return scene.camera.eye == made.camera.eye && scene.camera.lookat == made.camera.lookat &&
               scene.camera.up == made.camera.up && scene.camera.sensor_height == made.camera.sensor_height && lights &&
               scenes.prepared.options.threads == fresh.prepared.options.threads &&
               scenes.prepared.options.aovs.any() == fresh.prepared.options.aovs.any() &&
               scene.mesh.positions == made.mesh.positions && scene.mesh.normals == made.mesh.normals &&
               scenes.cameras.size() == fresh.cameras.size();
    };
    JobScenesMemo memo(meshes);
    const JobScenes* first = nullptr;
    {
        const std::shared_ptr<JobScenes> held = memo.load(manifest.jobs[0], 0);
        first = held.get();
        REQUIRE(as_made(*held));
        // Held: the other job asking the same gets scenes of its own, made again, as made.
        const std::shared_ptr<JobScenes> other = memo.load(manifest.jobs[1], 0);
        CHECK(other.get() != held.get());
        CHECK(as_made(*other));
        CHECK(memo.reuses() == 0);
        CHECK(memo.kept() == 2);
        // What a render lane changes.
        held->prepared.scene.camera = held->cameras[1];
        held->prepared.scene.lights = held->lights[1];
        held->prepared.scene.lights.push_back(PointLight{});
        held->prepared.options.threads = 1;
        held->prepared.options.aovs = AovRequest::all();
        CHECK_FALSE(as_made(*held));
    }
    // Given back as made, and lent again (the same object, no copy).
    const std::shared_ptr<JobScenes> again = memo.load(manifest.jobs[1], 0);
    CHECK(memo.reuses() == 1);
    CHECK(as_made(*again));
    const bool same_object = again.get() == first;
    const std::shared_ptr<JobScenes> second = memo.load(manifest.jobs[0], 0);  // the other kept one
    CHECK(memo.reuses() == 2);
    CHECK((same_object || second.get() == first));
    CHECK(as_made(*second));

    // Dropped from the memo while lent (the budget is too small for two): the
    // holder's scenes stay valid, and are not kept again when given back.
    JobScenesMemo small(meshes, 1);
    std::shared_ptr<JobScenes> kept_one = small.load(manifest.jobs[0], 0);
    const std::shared_ptr<JobScenes> made_again = small.load(manifest.jobs[1], 0);  // lent: made again, the other dropped
    CHECK(small.kept() == 1);
    kept_one->prepared.scene.camera = kept_one->cameras[1];
    CHECK(kept_one->prepared.scene.mesh.positions == fresh.prepared.scene.mesh.positions);
    kept_one.reset();
    CHECK(small.kept() == 1);
    CHECK(as_made(*made_again));
}
