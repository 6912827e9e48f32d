"""Extra outputs from Python: render(..., aovs=...) and Renderer return the
library's planes (the same bits as the phongrast command's EXR channels), as
arrays that own their buffers, and asking for them leaves the image alone."""
import numpy as np
import pytest

import phongrast
from conftest import SOURCE_DIR, assert_same_bits, run_phongrast

DEFAULT_SCENE = SOURCE_DIR / "assets" / "default.json"


def test_planes_equal_the_command_exr_channels(tmp_path):
    run_phongrast("render", DEFAULT_SCENE, "--size", "96x80", "--samples", "2", "--aov", "all",
                  "-o", tmp_path / "cpp.exr")
    scene = phongrast.Scene.load(str(DEFAULT_SCENE))
    scene.size = (80, 96)
    image, stats, planes = phongrast.render(scene, samples=2, aovs="all")
    cpp_image, cpp_planes = phongrast.read_aovs(str(tmp_path / "cpp.exr"))
    assert_same_bits(image, cpp_image)
    assert sorted(planes) == ["alpha", "depth", "distance", "id", "normal"]
    assert planes["depth"].shape == (80, 96) and planes["depth"].dtype == np.float32
    assert planes["distance"].shape == (80, 96) and planes["distance"].dtype == np.float32
    assert planes["normal"].shape == (80, 96, 3) and planes["normal"].dtype == np.float32
    assert planes["id"].shape == (80, 96) and planes["id"].dtype == np.int32
    assert planes["alpha"].shape == (80, 96) and planes["alpha"].dtype == np.float32
    for name in planes:
        assert planes[name].tobytes() == cpp_planes[name].tobytes(), name
    background = planes["id"] == -1
    assert background.any() and (~background).any()
    assert np.all(np.isinf(planes["depth"][background]))
    assert np.all(np.isinf(planes["distance"][background]))
    # From the eye, not along the axis: never less than the depth, more off the axis.
    assert np.all(planes["distance"][~background] >= planes["depth"][~background])
    assert np.all(planes["alpha"][background] == 0.0)
    assert np.all(planes["id"][~background] < stats["triangles_in"])
    lengths = np.linalg.norm(planes["normal"][~background], axis=-1)
    assert np.allclose(lengths, 1.0, atol=1e-5)


def test_only_what_is_asked_for_and_the_image_unchanged():
    scene = phongrast.Scene.load(str(DEFAULT_SCENE))
    scene.size = (64, 64)
    plain, _ = phongrast.render(scene)
    image, _, planes = phongrast.render(scene, aovs="depth,id")
    assert sorted(planes) == ["depth", "id"]
    assert_same_bits(image, plain)
    # The arrays own the C++ buffers: no copy, and they outlive everything else.
    assert planes["depth"].base is not None and planes["depth"].flags["C_CONTIGUOUS"]


def test_renderer_returns_planes_per_frame():
    scene = phongrast.Scene.load(str(DEFAULT_SCENE))
    scene.size = (48, 64)
    renderer = phongrast.Renderer(aovs="id,alpha")
    _, _, first = renderer.render(scene)
    _, _, second = renderer.render(scene)
    assert np.array_equal(first["id"], second["id"])
    _, _, expected = phongrast.render(scene, aovs="id,alpha")
    assert np.array_equal(first["id"], expected["id"]) and np.array_equal(first["alpha"], expected["alpha"])


def test_unknown_aov_names_the_keyword():
    scene = phongrast.Scene.load(str(DEFAULT_SCENE))
    with pytest.raises(ValueError, match="aovs: .*unknown output 'colour'"):
        phongrast.render(scene, aovs="depth,colour")
