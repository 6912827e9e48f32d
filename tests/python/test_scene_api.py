"""The Pythonic layer: scenes from files and dicts, meshes from OBJ and arrays,
render() with its statistics, Renderer, image files, and the docstrings."""
import json
import pydoc

import numpy as np
import pytest

import phongrast
from conftest import SOURCE_DIR, SeedScene, assert_same_bits, run_phongrast

DEFAULT_SCENE = SOURCE_DIR / "assets" / "default.json"


def test_the_default_scene_equals_the_phongrast_command(tmp_path):
    run_phongrast("render", DEFAULT_SCENE, "-o", tmp_path / "cpp.exr")
    scene = phongrast.Scene.load(str(DEFAULT_SCENE))
    image, stats = phongrast.render(scene)
    assert_same_bits(image, phongrast.read_image(str(tmp_path / "cpp.exr")))
    assert stats["triangles_in"] == scene.mesh.triangle_count > 0
    assert stats["triangles_drawn"] + stats["triangles_culled"] + stats["triangles_outside"] + \
        stats["triangles_out_of_range"] + stats["triangles_between_samples"] + stats["triangles_degenerate"] + stats["triangles_dropped"] == stats["triangles_in"]
    assert stats["samples_covered"] > 0 and stats["seconds"] > 0 and stats["nonfinite_values_replaced"] == 0


def test_seed_mode_and_options_match_the_command(tmp_path):
    run_phongrast("render", DEFAULT_SCENE, "--mode", "seed", "--shader", "gouraud", "--samples", "2",
                  "--lighting", "diffuse+specular", "--size", "160x120", "-o", tmp_path / "cpp.exr")
    scene = phongrast.Scene.load(str(DEFAULT_SCENE))
    scene.shader, scene.lighting, scene.size = "gouraud", "diffuse+specular", (120, 160)
    image, _ = phongrast.render(scene, mode="seed", samples=2)
    assert_same_bits(image, phongrast.read_image(str(tmp_path / "cpp.exr")))


def test_a_scene_from_a_dict_equals_the_scene_file(tmp_path):
    seed = SeedScene(M=40, N=56)
    path = seed.write_files(tmp_path)
    from_file, _ = phongrast.render(phongrast.Scene.load(str(path)))
    description = json.loads(path.read_text())
    description["camera"]["eye"] = np.array(description["camera"]["eye"])  # numpy values are fine
    from_dict = phongrast.Scene.from_dict(description, folder=str(tmp_path))
    assert np.array_equal(phongrast.render(from_dict)[0], from_file)
    mesh = phongrast.Mesh(seed.verts.T, seed.faces.T, colors=seed.colors.T)
    with_mesh = phongrast.Scene.from_dict({**description, "mesh": mesh})
    assert np.array_equal(phongrast.render(with_mesh)[0], from_file)
    assert np.array_equal(phongrast.render(phongrast.Scene.load(str(path), mesh=mesh))[0], from_file)
    # render_object of the same arrays in exact mode is the same picture again.
    assert np.array_equal(seed.render("phong", mode="exact"), from_file)


def test_scene_properties_read_and_write():
    scene = phongrast.Scene.load(str(DEFAULT_SCENE))
    assert scene.shader == "phong" and scene.lighting == "full" and scene.size == (512, 512)
    assert len(scene.lights) == 3 and set(scene.lights[0]) == {"position", "intensity"}
    assert set(scene.material) == {"ka", "kd", "ks", "n"}
    scene.size = (30, 40)
    scene.eye = scene.eye * 1.5
    scene.background = [0, 0, 0]
    scene.material = {"ka": 0.5, "kd": [0.1, 0.2, 0.3], "ks": 0, "n": 3}
    scene.lights = [phongrast.PointLight([0, 10, 10], 1)]
    scene.ambient = 0.5
    assert scene.material["kd"].tolist() == pytest.approx([0.1, 0.2, 0.3])
    assert scene.lights[0]["position"].tolist() == [0, 10, 10]
    image, _ = phongrast.render(scene)
    assert image.shape == (30, 40, 3)
    assert image[0, 0].tolist() == [0, 0, 0]


def test_renderer_frames_equal_render_and_stay_independent():
    scene = phongrast.Scene.load(str(DEFAULT_SCENE))
    scene.size = (96, 96)
    renderer = phongrast.Renderer(mode="seed", threads=2)
    frames = []
    for step in range(3):
        scene.eye = np.array([6.0 * np.sin(step), 1.0, 6.0 * np.cos(step)])
        image, stats = renderer.render(scene)
        assert np.array_equal(image, phongrast.render(scene, mode="seed")[0])
        assert stats["triangles_in"] == scene.mesh.triangle_count
        frames.append((image, image.copy()))
    for image, copy in frames:
        assert np.array_equal(image, copy)  # later frames did not overwrite earlier ones
    assert not np.array_equal(frames[0][0], frames[1][0])


def test_a_mesh_framed_automatically_equals_the_command_on_the_obj(tmp_path):
    seed = SeedScene()
    mesh = phongrast.Mesh(seed.verts.T, seed.faces.T, colors=seed.colors.T)
    mesh.save(str(tmp_path / "mesh.obj"))
    loaded = phongrast.Mesh.load(str(tmp_path / "mesh.obj"))
    assert np.array_equal(loaded.positions, mesh.positions) and np.array_equal(loaded.faces, mesh.faces)
    run_phongrast("render", tmp_path / "mesh.obj", "--size", "64x48", "-o", tmp_path / "cpp.exr")
    image, _ = phongrast.render(phongrast.Scene.from_mesh(loaded, 48, 64))
    assert_same_bits(image, phongrast.read_image(str(tmp_path / "cpp.exr")))


def test_images_written_and_read_back(tmp_path):
    image, _ = phongrast.render(phongrast.Scene.load(str(DEFAULT_SCENE)), samples=1)
    phongrast.write_image(image, str(tmp_path / "out.exr"))
    assert_same_bits(phongrast.read_image(str(tmp_path / "out.exr")), image)
    phongrast.write_image(image.astype(np.float64), str(tmp_path / "out.png"))
    png = phongrast.read_image(str(tmp_path / "out.png"))
    assert np.abs(png - np.clip(image, 0, 1)).max() <= 0.5 / 255 + 1e-6
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out.exr", "out.png"]


def test_help_documents_everything():
    text = pydoc.render_doc(phongrast, renderer=pydoc.plaintext)
    for name in ["PhongMaterial", "PointLight", "light", "calculate_normals", "render_object", "shade_gouraud",
                 "shade_phong", "Mesh", "Scene", "render", "Renderer", "read_image", "write_image", "FileError",
                 "row 0 at the top", "mode=\"seed\""]:
        assert name in text, name
    public = [getattr(phongrast, n) for n in dir(phongrast) if not n.startswith("_")]
    for item in public:
        if callable(item):
            assert item.__doc__ and len(item.__doc__.strip()) > 30, item
    for cls in [phongrast.Mesh, phongrast.Scene, phongrast.PhongMaterial, phongrast.PointLight]:
        for name, member in vars(cls).items():
            if not name.startswith("_") and isinstance(member, property):
                assert member.__doc__, f"{cls.__name__}.{name}"


def test_write_image_takes_uint8_as_0_to_255_and_floats_as_0_to_1(tmp_path):
    grey = np.full((4, 5, 3), 128, np.uint8)
    phongrast.write_image(grey, str(tmp_path / "grey.png"))
    back = phongrast.read_image(str(tmp_path / "grey.png"))
    assert back.shape == (4, 5, 3)
    assert np.all(np.round(back * 255) == 128)  # 128/255 grey, not white
    phongrast.write_image(grey, str(tmp_path / "grey.exr"))
    assert np.allclose(phongrast.read_image(str(tmp_path / "grey.exr")), 128 / 255)
    phongrast.write_image(np.full((4, 5, 3), 0.25, np.float64), str(tmp_path / "quarter.exr"))
    assert np.all(phongrast.read_image(str(tmp_path / "quarter.exr")) == np.float32(0.25))
    with pytest.raises(TypeError, match="uint8"):
        phongrast.write_image(np.full((4, 5, 3), 128, np.int64), str(tmp_path / "ints.png"))
    with pytest.raises(ValueError, match="GiB"):
        phongrast.write_image(np.broadcast_to(np.float32(0), (40000, 4, 3)), str(tmp_path / "tall.png"))
    assert sorted(p.name for p in tmp_path.iterdir()) == ["grey.exr", "grey.png", "quarter.exr"]


def test_render_statistics_report_an_empty_mesh_and_sizes_past_the_limit_name_the_memory():
    mesh = phongrast.Mesh(np.zeros((3, 3)), np.zeros((0, 3), np.uint32))
    scene = phongrast.Scene.from_mesh(phongrast.Mesh([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]]), 8, 8)
    assert phongrast.render(scene)[1]["empty_scene"] is False
    scene.mesh = mesh
    image, stats = phongrast.render(scene)
    assert stats["empty_scene"] is True
    assert stats["triangles_in"] == 0
    scene.size = (20000, 20000)
    with pytest.raises(ValueError, match="GiB"):
        phongrast.render(scene)
    with pytest.raises(ValueError, match="32768"):
        scene.size = (40000, 10)
