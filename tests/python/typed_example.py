"""A script using the phongrast module as a typed user would: checked with
`mypy --strict` against src/python/phongrast.pyi (ctest "python: stubs"),
and run by test_stubs.py so the stubs cannot drift from what works."""
import sys

import numpy as np
import numpy.typing as npt

import phongrast


def render_triangle(rows: int, columns: int) -> tuple[npt.NDArray[np.float32], dict[str, object]]:
    mesh = phongrast.Mesh(np.array([[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]), [[0, 1, 2]])
    scene = phongrast.Scene.from_mesh(mesh, rows, columns)
    scene.shader = "gouraud"
    scene.background = np.full(3, 0.5)
    scene.size = (rows, columns)
    fractions: list[float] = []
    image, stats = phongrast.render(scene, samples=2, precision="double", progress=fractions.append)
    assert fractions[-1] == 1.0
    renderer = phongrast.Renderer(threads=1)
    frame = renderer.render(scene)
    assert frame[0].shape == image.shape
    image_aovs, _, planes = phongrast.render(scene, aovs="depth,id")
    assert "depth" in planes and image_aovs.dtype == np.float32
    return image, dict(stats)


def main(folder: str) -> None:
    image, stats = render_triangle(16, 24)
    assert image.shape == (16, 24, 3)
    assert stats["empty_scene"] is False
    grey: npt.NDArray[np.uint8] = np.full((4, 4, 3), 128, np.uint8)
    phongrast.write_image(grey, folder + "/grey.png")
    back = phongrast.read_image(folder + "/grey.png")
    assert round(float(back[0, 0, 0]) * 255) == 128
    normals = phongrast.calculate_normals([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]])
    assert normals.shape == (3, 3)
    material = phongrast.PhongMaterial(0.1, 0.8, 1.0, 10)
    lights = [phongrast.PointLight([1, 2, 3], 1.0)]
    picture = phongrast.render_object("phong", 1.0, [0, 0, 3], [0, 0, 0], [0, 1, 0], [1, 1, 1], 8, 8, 1.0, 1.0,
                                      [[0, 0, 0], [1, 0, 0], [0, 1, 0]], None, [[0, 1, 2]], material, lights,
                                      0.2, "full")
    assert picture.shape == (8, 8, 3)
    camera = phongrast.Camera.from_opencv(np.array([[50.0, 0.0, 3.5], [0.0, 50.0, 3.5], [0.0, 0.0, 1.0]]), np.eye(4))
    K: npt.NDArray[np.float64] = camera.K
    assert K.shape == (3, 3) and camera.model == "opencv" and camera.camera_to_world.shape == (4, 4)
    assert camera.project([[0.0, 0.0, 1.0]], 8, 8).shape == (1, 3)
    try:
        phongrast.Mesh.load(folder + "/missing.obj")
    except phongrast.FileError as error:
        assert "missing.obj" in str(error)
    print("typed example ran:", phongrast.__version__)


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else ".")
