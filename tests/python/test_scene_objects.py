"""Scenes of several objects built in memory and from files, materials with
textures from numpy arrays and image files, the one table of option names
(the same spellings as the phongrast command), all through the library's
scene builder."""
import json

import numpy as np
import pytest

import phongrast
from conftest import run_phongrast, SOURCE_DIR

CAMERA = {"eye": [0.5, 0.5, 6], "lookat": [0.5, 0.5, 0], "focal": 2, "sensor": [2, 2]}
IMAGE = {"height": 24, "width": 32}
TRIANGLE = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"


def triangle_mesh(**keywords):
    return phongrast.Mesh(np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0]], float), np.array([[0, 1, 2]]), **keywords)


def test_objects_in_memory_share_their_mesh_and_keep_transforms_materials_normals():
    mesh = triangle_mesh(normals=np.array([[0, 0, 1]] * 3, float))
    transform = np.eye(4)
    transform[:3, 3] = [2, 0, -1]
    scene = phongrast.Scene.from_dict({
        "objects": [
            {"mesh": mesh, "transform": transform, "material": {"ks": 0.5}, "normals": "file"},
            {"mesh": mesh, "translation": [0, 1, 0], "rotation": [0, 0, 1, 0], "scale": 2},
        ],
        "camera": CAMERA, "image": IMAGE, "material": {"kd": 0.7}})
    objects = scene.objects
    assert len(objects) == 2
    assert np.array_equal(objects[0]["transform"], transform)
    # T * R * S: 180 degrees about z, doubled, moved up by 1.
    expected = np.diag([-2.0, -2.0, 2.0, 1.0])
    expected[1, 3] = 1
    assert np.allclose(objects[1]["transform"], expected, atol=1e-12)
    assert objects[0]["material"] == {"ks": (0.5, 0.5, 0.5)}
    assert objects[0]["normals"] == "file" and objects[1]["normals"] is None
    assert objects[0]["mesh"].triangle_count == 1 and mesh.has_normals
    # One mesh, shared by both objects, and read-only through them.
    assert np.shares_memory(objects[0]["mesh"].positions, objects[1]["mesh"].positions)
    with pytest.raises(ValueError):
        objects[0]["mesh"].positions[0, 0] = 5.0
    assert scene.material["kd"][0] == pytest.approx(0.7)
    assert scene.normals == "computed"
    scene.normals = "file"
    assert scene.normals == "file"
    with pytest.raises(ValueError, match="expected computed or file"):
        scene.normals = "smooth"


def test_objects_from_files_read_each_mesh_once(tmp_path):
    (tmp_path / "tri.obj").write_text(TRIANGLE)
    (tmp_path / "scene.json").write_text(json.dumps({
        "objects": [{"mesh": "tri.obj"}, {"mesh": "tri.obj", "scale": [-1, 1, 1]}],
        "camera": CAMERA, "image": IMAGE}))
    scene = phongrast.Scene.load(str(tmp_path / "scene.json"))
    objects = scene.objects
    assert len(objects) == 2 and objects[1]["transform"][0, 0] == -1
    assert np.shares_memory(objects[0]["mesh"].positions, objects[1]["mesh"].positions)
    assert "material.ka: default used" in scene.warnings


def test_bad_objects_are_errors_naming_the_field():
    with pytest.raises(ValueError, match="/objects/0/rotation: expected a unit quaternion"):
        phongrast.Scene.from_dict({"objects": [{"mesh": triangle_mesh(), "rotation": [0, 0, 0, 3]}],
                                   "camera": CAMERA, "image": IMAGE})
    with pytest.raises(ValueError, match="/objects/0/transform: .*singular"):
        phongrast.Scene.from_dict({"objects": [{"mesh": triangle_mesh(), "transform": np.zeros((4, 4)) + np.diag([0, 0, 0, 1])}],
                                   "camera": CAMERA, "image": IMAGE})
    with pytest.raises(ValueError, match="scene dict: /objects/1/mesh: .*gone.obj: mesh not found"):
        phongrast.Scene.from_dict({"objects": [{"mesh": triangle_mesh()}, {"mesh": "gone.obj"}],
                                   "camera": CAMERA, "image": IMAGE})


def test_materials_with_textures_from_arrays_and_files(tmp_path):
    texels = np.zeros((2, 2, 3), np.float32)
    texels[0, 0] = [1, 0, 0]  # top left
    texels[1, 1] = [0, 0, 1]  # bottom right
    texture = phongrast.Texture(texels, wrap_s="clamp_to_edge")
    assert texture.size == (2, 2) and texture.wrap == ("clamp_to_edge", "repeat")
    # Texel centres: (s, t) = (0.25, 0.75) is the top-left texel, (0.75, 0.25) the bottom-right one.
    assert texture.sample(0.25, 0.75) == pytest.approx((1, 0, 0))
    assert texture.sample(0.75, 0.25) == pytest.approx((0, 0, 1))
    assert texture.sample(0.5, 0.5) == pytest.approx((0.25, 0, 0.25))
    material = phongrast.Material(kd=0.9, texture=texture, name="checker")
    assert material.fields == {"kd": pytest.approx((0.9, 0.9, 0.9))} and material.has_texture
    mesh = triangle_mesh(texcoords=np.array([[0, 0], [1, 0], [0, 1]], float), material=material)
    assert mesh.has_texcoords and mesh.material_count == 1

    phongrast.write_image(texels, str(tmp_path / "checker.png"))
    from_file = phongrast.Texture.load(str(tmp_path / "checker.png"), wrap_t="mirrored_repeat")
    assert from_file.size == (2, 2) and from_file.sample(0.25, 0.75) == pytest.approx((1, 0, 0))
    two = phongrast.Mesh(np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0]], float), np.array([[0, 1, 2], [1, 3, 2]]),
                         materials=[material, phongrast.Material(ks=0.1)], face_materials=[1, -1])
    assert two.material_count == 2

    with pytest.raises(ValueError, match="texels: expected an M x N x 3 array"):
        phongrast.Texture(np.zeros((2, 2)))
    with pytest.raises(ValueError, match="wrap_s: .*clamp"):
        phongrast.Texture(texels, wrap_s="clamp")
    with pytest.raises(ValueError, match="texcoords: expected an Nv x 2 array"):
        triangle_mesh(texcoords=np.zeros((2, 2)))
    with pytest.raises(ValueError, match="face_materials\\[0\\]: 4 is not a material index"):
        triangle_mesh(materials=[material], face_materials=[4])


def test_option_names_are_the_commands(tmp_path):
    scene_path = SOURCE_DIR / "assets" / "default.json"
    scene = phongrast.Scene.load(str(scene_path))
    scene.size = (24, 32)
    # depth_buffer (Python's spelling) and depth-buffer are one name, here and on the command line.
    for spelling in ("depth_buffer", "depth-buffer"):
        run_phongrast("render", scene_path, "--visibility", spelling, "--size", "32x24", "-o", tmp_path / "cli.exr")
        cli = phongrast.read_image(str(tmp_path / "cli.exr"))
        image, _ = phongrast.render(scene, visibility=spelling)
        assert np.array_equal(image, cli)
    image, _ = phongrast.render(scene, texture_filter="nearest", overdraw="visible", precision="double")
    assert image.shape == (24, 32, 3)
    with pytest.raises(ValueError, match="visibility: unknown 'zbuffer'; expected 'painter' or 'depth-buffer'"):
        phongrast.render(scene, visibility="zbuffer")
    with pytest.raises(ValueError, match="texture_filter: unknown 'cubic'"):
        phongrast.render(scene, texture_filter="cubic")


def test_a_mesh_file_alone_is_framed_as_the_command_frames_it(tmp_path):
    (tmp_path / "tri.obj").write_text(TRIANGLE)
    scene = phongrast.Scene.load(str(tmp_path / "tri.obj"))
    assert scene.size == (512, 512) and scene.objects == [] and scene.mesh.triangle_count == 1
    assert scene.normals == "computed"  # the file has no normals


def test_the_docs_example_of_objects_in_memory_runs():
    text = (SOURCE_DIR / "docs" / "python.md").read_text()
    section = text.split("A scene of several objects in memory:", 1)[1]
    code = section.split("```python\n", 1)[1].split("```", 1)[0]
    namespace = {"__name__": "docs"}
    exec(compile(code, "docs/python.md", "exec"), namespace)
    assert len(namespace["scene"].objects) == 2


def test_a_scene_of_objects_takes_no_single_mesh():
    scene = phongrast.Scene.from_dict({"objects": [{"mesh": triangle_mesh()}], "camera": CAMERA, "image": IMAGE})
    with pytest.raises(ValueError, match="mesh: this scene places 1 objects; a scene has one mesh or objects"):
        scene.mesh = triangle_mesh()
    with pytest.raises(ValueError, match="both \"mesh\" and \"objects\""):
        phongrast.Scene.from_dict({"mesh": "a.obj", "objects": [{"mesh": "a.obj"}], "camera": CAMERA, "image": IMAGE})


def test_frame_fits_every_object():
    mesh = triangle_mesh()
    scene = phongrast.Scene.from_dict({"objects": [{"mesh": mesh}, {"mesh": mesh, "translation": [30, 0, 0]}],
                                       "camera": CAMERA, "image": IMAGE})
    scene.frame(40, 60)
    assert scene.size == (40, 60) and len(scene.lights) == 3
    assert scene.lookat[0] == pytest.approx(15.5)
    image, stats = phongrast.render(scene)
    assert image.shape == (40, 60, 3)
