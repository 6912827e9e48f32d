"""Bad input raises ValueError or TypeError naming the argument and what was
expected; nothing crashes the interpreter and nothing is printed."""
import json

import numpy as np
import pytest

import phongrast
from conftest import SeedScene


@pytest.fixture
def scene():
    return SeedScene(M=16, N=16)


def call(scene, **changes):
    """render_object with some seed arguments replaced."""
    args = dict(shader="phong", focal=scene.focal, eye=scene.eye, lookat=scene.lookat, up=scene.up, bg_color=scene.bg,
                M=scene.M, N=scene.N, H=scene.H, W=scene.W, verts=scene.verts, vert_colors=scene.colors,
                faces=scene.faces, mat=scene.mat, lights=scene.lights, light_amb=scene.ambient, lighting="full")
    options = {k: changes.pop(k) for k in list(changes) if k not in args}
    args.update(changes)
    return phongrast.render_object(*args.values(), **options)


def with_value(array, index, value):
    changed = np.array(array, dtype=np.float64, order="F")
    changed[index] = value
    return changed


BAD_RENDER_OBJECT_INPUTS = [
    # (changes, exception, words the message must contain)
    (dict(verts=np.zeros((4, 5))), ValueError, ["verts", "3 x N or N x 3", "(4, 5)"]),
    (dict(verts=np.zeros(9)), ValueError, ["verts", "shape (9,)"]),
    (dict(verts="not an array"), TypeError, ["verts"]),
    (dict(verts=[[0, 0, "x"]]), TypeError, ["verts"]),
    (dict(vert_colors=np.ones((3, 7))), ValueError, ["vert_colors", "one per vertex"]),
    ("nan-vertex", ValueError, ["verts", "point 5", "NaN"]),
    ("inf-vertex", ValueError, ["verts", "point 5", "infinite"]),
    ("nan-colour", ValueError, ["vert_colors", "NaN"]),
    ("face-too-big", ValueError, ["faces", "face 3", "expected 0-based indices from 0 to"]),
    ("face-negative", ValueError, ["faces", "-1"]),
    (dict(faces=np.array([[0.5], [1], [2]])), ValueError, ["faces", "whole-number"]),
    (dict(faces=np.zeros((2, 2), int)), ValueError, ["faces", "3 x N or N x 3"]),
    (dict(eye=[0.0, 0.1, 0.0], lookat=[0.0, 0.1, 0.0]), ValueError, ["lookat", "eye"]),
    (dict(up=[-0.8, -1.6, -5.2]), ValueError, ["up", "parallel"]),
    (dict(up=[0, 0, 0]), ValueError, ["up"]),
    (dict(eye=[0, 0]), ValueError, ["eye", "3 numbers"]),
    (dict(eye=[0, np.nan, 1]), ValueError, ["eye", "finite"]),
    (dict(M=0), ValueError, ["M", "from 1"]),
    (dict(N=-4), ValueError, ["N", "from 1"]),
    (dict(M=2.5), ValueError, ["M", "whole number"]),
    (dict(M="16"), TypeError, ["M", "number"]),
    (dict(focal=0), ValueError, ["focal", "positive"]),
    (dict(H=-1), ValueError, ["H", "positive"]),
    (dict(focal=float("inf")), ValueError, ["focal", "finite"]),
    (dict(shader="toon"), ValueError, ["shader", "toon", "gouraud"]),
    (dict(shader=3), TypeError, ["shader"]),
    (dict(lighting="sparkle"), ValueError, ["lighting", "sparkle", "diffusion"]),
    (dict(lighting="ambient+"), ValueError, ["lighting"]),
    (dict(mat=object()), TypeError, ["mat", "ka", "missing"]),
    (dict(mat=phongrast.PhongMaterial.__new__(phongrast.PhongMaterial)), TypeError, ["mat", "missing"]),
    (dict(lights=[{"pos": [0, 0, 1]}]), TypeError, ["lights[0]", "intensity"]),
    (dict(lights=5), TypeError, ["lights"]),
    (dict(light_amb=[1, 2]), ValueError, ["light_amb"]),
    (dict(mode="fast"), ValueError, ["mode", "'seed'", "'exact'"]),
    (dict(samples=0), ValueError, ["samples"]),
    (dict(colour="red"), TypeError, ["colour"]),
]


@pytest.mark.parametrize("changes, exception, words", BAD_RENDER_OBJECT_INPUTS)
def test_bad_render_object_input(scene, capfd, changes, exception, words):
    if isinstance(changes, str):
        changes = {
            "nan-vertex": dict(verts=with_value(scene.verts, (1, 5), np.nan)),
            "inf-vertex": dict(verts=with_value(scene.verts, (2, 5), -np.inf)),
            "nan-colour": dict(vert_colors=with_value(scene.colors, (0, 2), np.nan)),
            "face-too-big": dict(faces=with_value(scene.faces, (1, 3), scene.verts.shape[1]).astype(int)),
            "face-negative": dict(faces=with_value(scene.faces, (0, 0), -1).astype(int)),
        }[changes]
    with pytest.raises(exception) as raised:
        call(scene, **changes)
    for word in words:
        assert word in str(raised.value)
    assert capfd.readouterr() == ("", "")  # no C++ trace, no warning printed


def test_bad_material_and_light_constructors():
    with pytest.raises(ValueError, match="n_phong"):
        phongrast.PhongMaterial(0.1, 0.5, 0.5, -1)
    with pytest.raises(ValueError, match="ka"):
        phongrast.PhongMaterial([0.1, 0.2], 0.5, 0.5, 1)
    with pytest.raises(ValueError, match="pos"):
        phongrast.PointLight([0, 0, np.inf], 1)


def test_bad_shade_input():
    mat = phongrast.PhongMaterial(0.1, 0.5, 0.5, 1)
    good = dict(verts_p=[[0, 4, 0], [0, 0, 4]], verts_n=np.eye(3), verts_c=np.ones((3, 3)), bcoords=[0, 0, 0],
                cam_pos=[0, 0, 5], mat=mat, lights=[], light_amb=1.0, X=np.zeros((4, 4, 3)), lighting="ambient")
    for change, exception, word in [
        (dict(X=np.zeros((4, 4))), ValueError, "X"),
        (dict(X=np.zeros((4, 4, 3), int)), TypeError, "X"),
        (dict(X=[[0.0] * 3] * 4), TypeError, "X"),
        (dict(verts_p=[[0, 4], [0, 0]]), ValueError, "verts_p"),
        (dict(verts_p=[[0, 4, np.nan], [0, 0, 4]]), ValueError, "verts_p"),
        (dict(verts_n=np.eye(3)[:, :2]), ValueError, "verts_n"),
        (dict(lighting="glow"), ValueError, "lighting"),
    ]:
        with pytest.raises(exception, match=word):
            phongrast.shade_phong(**{**good, **change})
    frozen = np.zeros((4, 4, 3))
    frozen.flags.writeable = False
    with pytest.raises(ValueError, match="read-only"):
        phongrast.shade_gouraud(**{**good, "X": frozen})


def test_bad_files_name_the_file(tmp_path):
    with pytest.raises(phongrast.FileError, match="no_such.json"):
        phongrast.Scene.load(str(tmp_path / "no_such.json"))
    (tmp_path / "broken.json").write_text('{"mesh": "m.obj",, }')
    with pytest.raises(ValueError, match="broken.json:1:"):
        phongrast.Scene.load(str(tmp_path / "broken.json"))
    with pytest.raises(ValueError, match="/camera/eye"):
        phongrast.Scene.from_dict({"mesh": "m.obj", "camera": {"eye": [0, 0], "lookat": [0, 0, 0], "focal": 1,
                                   "sensor": [1, 1]}, "image": {"height": 4, "width": 4}})
    with pytest.raises(phongrast.FileError, match="no_mesh.obj"):
        phongrast.Mesh.load(str(tmp_path / "no_mesh.obj"))


def test_bad_image_writes_leave_nothing_behind(tmp_path):
    image = np.zeros((4, 4, 3), np.float32)
    with pytest.raises(phongrast.FileError, match="picture.jpg"):
        phongrast.write_image(image, str(tmp_path / "picture.jpg"))
    with pytest.raises(ValueError, match="image"):
        phongrast.write_image(np.zeros((4, 4)), str(tmp_path / "picture.png"))
    with pytest.raises(phongrast.FileError):
        phongrast.write_image(image, str(tmp_path / "missing" / "picture.png"))
    assert list(tmp_path.iterdir()) == []


def test_bad_scene_properties_and_keywords():
    scene = phongrast.Scene.from_mesh(phongrast.Mesh([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]]), 8, 8)
    with pytest.raises(ValueError, match="shader"):
        scene.shader = "toon"
    with pytest.raises(ValueError, match="size"):
        scene.size = (0, 8)
    scene.lookat = scene.eye
    with pytest.raises(ValueError, match="lookat"):
        phongrast.render(scene)
    with pytest.raises(TypeError, match="unexpected keyword argument 'sample'"):
        phongrast.render(scene, sample=2)
    with pytest.raises(ValueError, match="faces"):
        phongrast.Mesh([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 3]])


def index_layouts(faces):
    """The same indices packed (3 x N Fortran-, N x 3 C-ordered: read in blocks of four) and strided."""
    strided = np.empty((faces.shape[0], 2 * faces.shape[1]), faces.dtype)[:, ::2]
    strided[:] = faces
    return {"3xN F": np.asfortranarray(faces), "Nx3 C": np.ascontiguousarray(faces.T), "3xN strided": strided}


@pytest.mark.parametrize("dtype", [np.int32, np.int64, np.uint32, np.uint64])
@pytest.mark.parametrize("where", ["first", "middle", "last"])
def test_every_bad_index_is_caught_in_every_layout(scene, dtype, where):
    # The packed reads check indices four at a time and then the rest one by one: a bad index in
    # either part, in any integer type, must still name its face.
    all_faces = scene.faces[:, :-1] if scene.faces.shape[1] % 4 == 0 else scene.faces  # 3 x count not a multiple of 4
    count = all_faces.shape[1]
    assert (3 * count) % 4 != 0
    face = {"first": 0, "middle": count // 2, "last": count - 1}[where]
    bad_values = [scene.verts.shape[1], np.iinfo(dtype).max]
    if np.issubdtype(dtype, np.signedinteger):
        bad_values += [-1, np.iinfo(dtype).min]
    for value in bad_values:
        faces = all_faces.astype(dtype)
        faces[2, face] = value
        for name, laid_out in index_layouts(faces).items():
            with pytest.raises(ValueError) as raised:
                call(scene, faces=laid_out)
            assert f"face {face} has vertex index {value}" in str(raised.value), (name, value)


@pytest.mark.parametrize("dtype", [np.float32, np.float64])
@pytest.mark.parametrize("value", [np.nan, np.inf, -np.inf])
def test_a_non_finite_last_value_is_caught_in_every_layout(scene, dtype, value):
    # The last component lies past the packed reads' blocks of four when 3 x Nv is not a multiple of four.
    verts = scene.verts.astype(dtype)
    last = verts.shape[1] - 1
    assert (3 * verts.shape[1]) % 4 != 0
    verts[2, last] = value
    strided = np.empty((3, 2 * verts.shape[1]), dtype)[:, ::2]
    strided[:] = verts
    for laid_out in [np.asfortranarray(verts), np.ascontiguousarray(verts.T), strided]:
        with pytest.raises(ValueError) as raised:
            call(scene, verts=laid_out)
        assert f"point {last}" in str(raised.value)
        colors = scene.colors.astype(dtype)
        colors[0, last] = value
        with pytest.raises(ValueError, match="vert_colors"):
            call(scene, vert_colors=np.asfortranarray(colors))
