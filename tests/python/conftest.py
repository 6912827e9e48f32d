"""Shared fixtures: a test scene as the seed's arrays and as files the
`phongrast` executable renders, and the C++ reference program."""
import json
import os
import pathlib
import subprocess

import numpy as np
import pytest

import phongrast

PHONGRAST_EXE = os.environ.get("PHONGRAST_EXE", "")
REFERENCE_EXE = os.environ.get("PHONGRAST_REFERENCE", "")
SOURCE_DIR = pathlib.Path(os.environ.get("PHONGRAST_SOURCE_DIR", pathlib.Path(__file__).parents[2]))


def bumpy_sphere(rings=24, segments=36):
    """A closed sphere with a bumpy radius and a colour gradient: 3 x Nv
    vertices and colours (Fortran-ordered, as numpy.load gives them), 3 x NT faces."""
    theta = np.linspace(0.0, np.pi, rings + 1)[1:-1]
    phi = np.linspace(0.0, 2.0 * np.pi, segments, endpoint=False)
    t, p = np.meshgrid(theta, phi, indexing="ij")
    radius = 1.0 + 0.15 * np.sin(3 * p) * np.sin(2 * t)
    ring = np.stack([radius * np.sin(t) * np.cos(p), radius * np.cos(t), radius * np.sin(t) * np.sin(p)], -1)
    verts = np.concatenate([[[0.0, 1.0, 0.0]], ring.reshape(-1, 3), [[0.0, -1.0, 0.0]]])
    faces = []
    last = len(verts) - 1
    for j in range(segments):
        k = (j + 1) % segments
        faces.append([0, 1 + k, 1 + j])
        faces.append([last, 1 + (rings - 2) * segments + j, 1 + (rings - 2) * segments + k])
        for i in range(rings - 2):
            a, b = 1 + i * segments + j, 1 + i * segments + k
            c, d = a + segments, b + segments
            faces += [[a, b, d], [a, d, c]]
    colors = np.stack([0.5 + 0.5 * verts[:, 0], 0.5 + 0.5 * verts[:, 1], 0.6 - 0.3 * verts[:, 2]], -1)
    colors = np.clip(colors, 0.0, 1.0).astype(np.float32).astype(np.float64)
    return (np.asfortranarray(verts.T), np.asfortranarray(colors.T), np.asfortranarray(np.array(faces).T))


class SeedScene:
    """The arguments of render_object, and the same scene as a scene file."""

    def __init__(self, M=96, N=128):
        self.verts, self.colors, self.faces = bumpy_sphere()
        self.focal, self.H, self.W = 1.0, 0.75, 1.0
        self.eye, self.lookat, self.up = [0.4, 0.9, 2.6], [0.0, 0.1, 0.0], [0.0, 1.0, 0.1]
        self.bg = [0.1, 0.2, 0.3]
        self.M, self.N = M, N
        self.mat = phongrast.PhongMaterial([0.3, 0.25, 0.2], 0.7, [0.9, 0.8, 0.7], 12)
        self.lights = [phongrast.PointLight([2.0, 3.0, 2.0], [1.0, 0.9, 0.8]),
                       phongrast.PointLight([-2.0, 0.5, 1.5], [0.2, 0.3, 0.6])]
        self.ambient = [0.3, 0.3, 0.35]

    def render(self, shader, lighting="full", verts=None, colors="scene", faces=None, mat=None, lights=None,
               **options):
        """render_object of this scene; any argument given replaces the scene's (colors=None: white)."""
        return phongrast.render_object(
            shader, self.focal, self.eye, self.lookat, self.up, self.bg, self.M, self.N, self.H, self.W,
            self.verts if verts is None else verts, self.colors if isinstance(colors, str) else colors,
            self.faces if faces is None else faces, self.mat if mat is None else mat,
            self.lights if lights is None else lights, self.ambient, lighting, **options)

    def write_files(self, folder):
        """mesh.obj (every number written exactly) and scene.json; returns the scene path."""
        folder = pathlib.Path(folder)
        lines = ["v %r %r %r %r %r %r" % (*map(float, v), *map(float, c)) for v, c in zip(self.verts.T, self.colors.T)]
        lines += ["f %d %d %d" % tuple(f + 1) for f in self.faces.T]
        (folder / "mesh.obj").write_text("\n".join(lines) + "\n")
        mat = self.mat
        scene = {
            "mesh": "mesh.obj",
            "camera": {"eye": self.eye, "lookat": self.lookat, "up": self.up, "focal": self.focal,
                       "sensor": [self.H, self.W]},
            "image": {"height": self.M, "width": self.N, "background": self.bg},
            "material": {"ka": np.asarray(mat.ka).tolist(), "kd": float(mat.kd), "ks": np.asarray(mat.ks).tolist(),
                         "n": float(mat.n_phong)},
            "ambient": self.ambient,
            "lights": [{"position": l.pos.tolist(), "intensity": np.asarray(l.intensity).tolist()} for l in self.lights],
        }
        path = folder / "scene.json"
        path.write_text(json.dumps(scene))
        return path


@pytest.fixture
def seed_scene():
    return SeedScene()


def run_phongrast(*arguments):
    """Runs the phongrast executable (quietly) and fails the test on a non-zero exit."""
    if not PHONGRAST_EXE:
        pytest.fail("PHONGRAST_EXE is not set (run the tests through ctest)")
    completed = subprocess.run([PHONGRAST_EXE, *map(str, arguments), "--quiet"], capture_output=True, text=True)
    assert completed.returncode == 0, completed.stderr
    return completed


def run_reference(mode, text):
    """Runs the C++ reference program (python_reference.cpp) on `text`; returns its stdout as numbers."""
    if not REFERENCE_EXE:
        pytest.fail("PHONGRAST_REFERENCE is not set (run the tests through ctest)")
    completed = subprocess.run([REFERENCE_EXE, mode], input=text, capture_output=True, text=True)
    assert completed.returncode == 0, completed.stderr
    return np.array([[float(x) for x in line.split()] for line in completed.stdout.splitlines()])


def assert_same_bits(actual, expected):
    """Equal bit for bit (not just numerically): same shape, dtype and bytes."""
    actual, expected = np.asarray(actual), np.asarray(expected)
    assert actual.shape == expected.shape and actual.dtype == expected.dtype
    differing = np.count_nonzero(actual.view(np.uint32) != expected.view(np.uint32)) if actual.dtype == np.float32 \
        else np.count_nonzero(actual != expected)
    assert differing == 0, f"{differing} values differ (max abs difference {np.max(np.abs(actual - expected))})"
