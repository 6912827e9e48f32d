"""Every seed function against the C++ library, bit for bit, through a different path:
light and calculate_normals against a small C++ program calling the library
(python_reference.cpp); render_object against the `phongrast` executable
rendering the same scene file to EXR (read back through phongrast::io)."""
import itertools
import subprocess

import numpy as np
import pytest

import phongrast
from conftest import REFERENCE_EXE, assert_same_bits, run_phongrast, run_reference

LIGHTINGS = ["ambient", "diffusion", "specular", "full", "ambient+specular", "diffuse+specular"]


def test_light_matches_the_library_bit_for_bit():
    rng = np.random.default_rng(7)
    lines, calls = [], []
    for case in range(300):
        point, normal, color, eye = rng.normal(size=3), rng.normal(size=3), rng.random(3), rng.normal(size=3) * 4
        ka, kd, ks = rng.random(3), rng.random(3), rng.random(3)
        n = float(rng.integers(0, 40))
        ambient = rng.random(3)
        lighting = LIGHTINGS[case % len(LIGHTINGS)]
        lights = [(rng.normal(size=3) * 3, rng.random(3)) for _ in range(case % 4)]
        material = phongrast.PhongMaterial(ka, kd, ks, n)
        calls.append(phongrast.light(point, normal, color, eye, material,
                                     [phongrast.PointLight(p, i) for p, i in lights], lighting, light_amb=ambient))
        # The reference receives float32 material and intensities, as the library stores them.
        f32 = lambda v: " ".join(repr(float(x)) for x in np.asarray(v, np.float32))
        f64 = lambda v: " ".join(repr(float(x)) for x in v)
        reference_lighting = lighting.replace("diffusion", "diffuse")
        lines.append(" ".join([f64(point), f64(normal), f64(color), f64(eye), f32(ka), f32(kd), f32(ks),
                               repr(n), f64(ambient), reference_lighting, str(len(lights))] +
                              [f64(p) + " " + f32(i) for p, i in lights]))
    expected = run_reference("light", "\n".join(lines) + "\n")
    assert_same_bits(np.array(calls), expected)
    assert np.ptp(expected) > 0.5  # the cases are not all alike


def test_calculate_normals_matches_the_library_bit_for_bit(seed_scene):
    verts, faces = seed_scene.verts, seed_scene.faces
    text = f"{verts.shape[1]} {faces.shape[1]}\n" + "\n".join(" ".join(repr(float(x)) for x in v) for v in verts.T)
    text += "\n" + "\n".join(" ".join(str(i) for i in f) for f in faces.T) + "\n"
    expected = run_reference("normals", text).astype(np.float32)
    normals = phongrast.calculate_normals(verts, faces)
    assert normals.shape == verts.shape and normals.dtype == np.float32  # 3 x Nv in, 3 x Nv out
    assert_same_bits(np.ascontiguousarray(normals.T), expected)
    assert_same_bits(phongrast.calculate_normals(verts.T, faces.T), expected)  # Nv x 3 in, Nv x 3 out
    assert np.allclose(np.linalg.norm(expected, axis=1), 1.0, atol=1e-6)


@pytest.mark.parametrize("mode, shader", itertools.product(["seed", "exact"], ["gouraud", "phong"]))
def test_render_object_equals_the_cpp_render(seed_scene, tmp_path, mode, shader):
    scene_path = seed_scene.write_files(tmp_path)
    run_phongrast("render", scene_path, "--mode", mode, "--shader", shader, "-o", tmp_path / "cpp.exr")
    expected = phongrast.read_image(str(tmp_path / "cpp.exr"))
    image = seed_scene.render(shader, mode=mode)
    assert image.shape == (seed_scene.M, seed_scene.N, 3)
    assert_same_bits(image, expected)
    # The picture is not trivial: the object covers a good part of it, with shading.
    background = np.all(image == np.float32(seed_scene.bg), axis=2)
    assert 0.2 < 1.0 - background.mean() < 0.9
    assert len(np.unique(image.reshape(-1, 3), axis=0)) > 500


def test_seed_and_exact_modes_differ(seed_scene):
    assert not np.array_equal(seed_scene.render("phong"), seed_scene.render("phong", mode="exact"))


def test_the_eight_seed_figures_from_python(seed_scene, tmp_path):
    scene_path = seed_scene.write_files(tmp_path)
    run_phongrast("sheet", scene_path, "--mode", "seed", "--figures", tmp_path, "-o", tmp_path / "sheet.exr")
    figures = {}
    for shader in ["gouraud", "phong"]:
        for lighting in ["ambient", "diffusion", "specular", "full"]:
            image = seed_scene.render(shader, lighting)
            stem = f"{shader}-{lighting.replace('diffusion', 'diffuse')}"
            assert_same_bits(image, phongrast.read_image(str(tmp_path / f"{stem}.exr")))
            figures[stem] = image
    # Eight different pictures, and full lighting is the sum of its three terms.
    assert len({f.tobytes() for f in figures.values()}) == 8
    for shader in ["gouraud", "phong"]:
        covered = ~np.all(figures[f"{shader}-full"] == np.float32(seed_scene.bg), axis=2)
        parts = sum(figures[f"{shader}-{t}"][covered] for t in ["ambient", "diffuse", "specular"])
        assert np.allclose(parts, figures[f"{shader}-full"][covered], atol=1e-5)


def project(scene, points):
    """The contract's camera (scene-format.md), in numpy: (column, row) and depth z_c."""
    eye = np.asarray(scene.eye, float)
    f = np.asarray(scene.lookat, float) - eye
    f /= np.linalg.norm(f)
    r = np.cross(f, scene.up)
    r /= np.linalg.norm(r)
    u = np.cross(r, f)
    d = points.T - eye
    xc, yc, zc = d @ r, d @ u, d @ f
    x, y = scene.focal * xc / zc, scene.focal * yc / zc
    return np.stack([(x + scene.W / 2) / scene.W * scene.N, (scene.H / 2 - y) / scene.H * scene.M]), zc


@pytest.mark.parametrize("shader", ["gouraud", "phong"])
def test_the_seed_render_loop_with_shade_functions_equals_render_object(seed_scene, shader):
    """The seed's own render loop in Python (painter's order, the border rule,
    one shade_* call per triangle) paints what render_object(mode="seed") paints."""
    s = seed_scene
    normals = phongrast.calculate_normals(s.verts, s.faces).astype(np.float64)
    projected, depth = project(s, s.verts)
    order = np.argsort(-depth[s.faces].mean(axis=0), kind="stable")
    X = np.empty((s.M, s.N, 3), np.float32)
    X[:] = s.bg
    shade = phongrast.shade_gouraud if shader == "gouraud" else phongrast.shade_phong
    for t in order:
        face = s.faces[:, t]
        p = projected[:, face]
        if np.any(depth[face] <= 0) or np.any(p < 0) or np.any(p[0] > s.N) or np.any(p[1] > s.M):
            continue  # the seed's border rule
        assert shade(p, normals[:, face], s.colors[:, face], s.verts[:, face].mean(axis=1), s.eye, s.mat,
                     s.lights, s.ambient, X, "full") is X
    expected = s.render(shader)
    same_coverage = np.all(X == np.float32(s.bg), axis=2) == np.all(expected == np.float32(s.bg), axis=2)
    assert same_coverage.mean() > 0.999
    covered = ~np.all(expected == np.float32(s.bg), axis=2) & same_coverage
    # The library lights in float camera space, shade_* in double world space.
    assert np.abs(X[covered] - expected[covered]).max() < 1e-5


def test_shade_gouraud_interpolates_the_lit_vertices():
    X = np.zeros((4, 6, 3))
    mat = phongrast.PhongMaterial(1.0, 0.0, 0.0, 1)
    colors = np.array([[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]).T
    phongrast.shade_gouraud([[0, 6, 0], [0, 0, 4]], np.eye(3), colors, [0, 0, 0], [0, 0, 5], mat, [], 1.0, X, "ambient")
    # Pixel (0, 0) is at (0.5, 0.5): weights 1 - 0.5/6 - 0.5/4, 0.5/6, 0.5/4 of red, green, blue.
    assert np.allclose(X[0, 0], [1 - 0.5 / 6 - 0.5 / 4, 0.5 / 6, 0.5 / 4])
    assert np.all(X[3, 5] == 0)  # outside the triangle
    assert np.count_nonzero(X.any(axis=2)) == 12  # the pixel centres below the diagonal


def test_shade_functions_handle_degenerate_input_on_purpose():
    mat = phongrast.PhongMaterial(0.2, 0.7, 0.5, 0)
    lights = [phongrast.PointLight([0, 0, 0], 1.0), phongrast.PointLight([3, 3, 3], 1.0)]  # one at bcoords
    X = np.full((6, 6, 3), -1.0)
    # Zero area (three collinear corners): nothing painted.
    phongrast.shade_phong([[0, 3, 6], [0, 3, 6]], np.eye(3), np.ones((3, 3)), [0, 0, 0], [0, 0, 5], mat, lights,
                          0.5, X, "full")
    assert np.all(X == -1.0)
    # Normals that cancel at some pixels, the eye at bcoords, a light at bcoords: finite everywhere.
    normals = np.array([[0, 0, 1.0], [0, 0, -1.0], [0, 1.0, 0]]).T
    for shade in (phongrast.shade_phong, phongrast.shade_gouraud):
        X[:] = -1.0
        shade([[0, 6, 0], [0, 0, 6]], normals, np.ones((3, 3)), [0, 0, 0], [0, 0, 0], mat, lights, 0.5, X, "full")
        painted = X[..., 0] != -1.0
        assert painted.sum() == 15 and np.all(np.isfinite(X))  # centres on the hypotenuse (a right edge) excluded


@pytest.mark.parametrize("shader", ["gouraud", "phong"])
def test_shade_functions_equal_the_library_bit_for_bit(shader):
    """shade_gouraud/shade_phong are the C++ library's phongrast::shade_gouraud/shade_phong:
    every painted pixel equal bit for bit (python_reference.cpp calls the library)."""
    rng = np.random.default_rng(7)
    shade = phongrast.shade_gouraud if shader == "gouraud" else phongrast.shade_phong
    f32 = lambda v: " ".join(repr(float(x)) for x in np.asarray(v, np.float32))
    f64 = lambda v: " ".join(repr(float(x)) for x in np.ravel(v))
    lines, canvases = [], []
    for case in range(12):
        M, N = 24, 32
        p = rng.uniform(-4, [N + 4, M + 4], size=(3, 2)).T  # 2 x 3, corners partly off the canvas
        normals, colors = rng.normal(size=(3, 3)), rng.random((3, 3))
        centroid, eye = rng.normal(size=3), rng.normal(size=3) * 4
        ka, kd, ks, n, ambient = rng.random(3), rng.random(3), rng.random(3), float(rng.integers(1, 30)), rng.random(3)
        lights = [(rng.normal(size=3) * 3, rng.random(3)) for _ in range(1 + case % 3)]
        lighting = LIGHTINGS[case % len(LIGHTINGS)]
        X = np.zeros((M, N, 3))
        shade(p, normals, colors, centroid, eye, phongrast.PhongMaterial(ka, kd, ks, n),
              [phongrast.PointLight(q, i) for q, i in lights], ambient, X, lighting)
        canvases.append(X)
        corners = " ".join(f"{p[0, k]!r} {p[1, k]!r} {f64(normals[:, k])} {f64(colors[:, k])}" for k in range(3))
        lines.append(" ".join([shader, str(M), str(N), corners, f64(centroid), f64(eye), f32(ka), f32(kd), f32(ks),
                               repr(n), f64(ambient), lighting.replace("diffusion", "diffuse"), str(len(lights))] +
                              [f64(q) + " " + f32(i) for q, i in lights]))
    completed = subprocess.run([REFERENCE_EXE, "shade"], input="\n".join(lines) + "\n", capture_output=True, text=True)
    assert completed.returncode == 0, completed.stderr
    painted_total = 0
    for X, block in zip(canvases, completed.stdout.split("\n\n")):
        expected = np.zeros_like(X)
        for line in block.strip().splitlines():
            row, column, *rgb = line.split()
            expected[int(row), int(column)] = [float(v) for v in rgb]
            painted_total += 1
        assert_same_bits(X, expected)
    assert painted_total > 100
