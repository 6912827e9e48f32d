"""Arrays as the exercise has them (every layout and dtype), numbers as numpy
scalars and 0-d arrays, lighting names, and the user's own material and light classes."""
import collections

import numpy as np
import pytest

import phongrast


@pytest.fixture(scope="module")
def reference(request):
    from conftest import SeedScene
    scene = SeedScene(M=48, N=64)
    return scene, scene.render("phong")


def layouts(array):
    """The same numbers as 3 x N and N x 3, C- and Fortran-ordered, and a strided view."""
    wide = np.empty((array.shape[0], 2 * array.shape[1]), array.dtype)[:, ::2]
    wide[:] = array
    return {"3xN F": np.asfortranarray(array), "3xN C": np.ascontiguousarray(array),
            "Nx3 C": np.ascontiguousarray(array.T), "Nx3 F": np.asfortranarray(array.T), "3xN strided": wide,
            "list": array.T.tolist()}


def test_every_vertex_and_colour_layout_gives_the_same_image(reference):
    scene, expected = reference
    for name, verts in layouts(scene.verts).items():
        for colour_name, colors in layouts(scene.colors).items():
            image = scene.render("phong", verts=verts, colors=colors)
            assert np.array_equal(image, expected), (name, colour_name)


def test_every_face_layout_and_integer_dtype_gives_the_same_image(reference):
    scene, expected = reference
    for dtype in [np.int32, np.int64, np.uint32, np.uint64, np.int16, np.float64]:
        for name, faces in layouts(scene.faces.astype(dtype)).items():
            assert np.array_equal(scene.render("phong", faces=faces), expected), (dtype, name)


def test_float32_vertices_are_their_float64_values(reference):
    scene, _ = reference
    verts32 = scene.verts.astype(np.float32)
    expected = scene.render("phong", verts=verts32.astype(np.float64))
    for name, verts in layouts(verts32).items():
        assert np.array_equal(scene.render("phong", verts=verts, colors=scene.colors.astype(np.float32)), expected), name


def test_no_colours_means_white(reference):
    scene, _ = reference
    white = scene.render("gouraud", colors=np.ones_like(scene.colors))
    assert np.array_equal(scene.render("gouraud", colors=None), white)


def test_numbers_may_be_numpy_scalars_and_zero_d_arrays(reference):
    scene, expected = reference
    image = phongrast.render_object(
        "phong", np.float32(scene.focal), np.array(scene.eye), tuple(scene.lookat), np.array(scene.up),
        np.array(scene.bg), np.int64(scene.M), np.array(scene.N), np.array(scene.H), np.float64(scene.W),
        scene.verts, scene.colors, scene.faces,
        phongrast.PhongMaterial(np.asarray(scene.mat.ka), np.array(scene.mat.kd), scene.mat.ks, np.int32(12)),
        scene.lights, np.asarray(scene.ambient), "full")
    assert np.array_equal(image, expected)


def test_coefficients_may_be_scalars_or_triples(reference):
    scene, _ = reference
    scalar = phongrast.PhongMaterial(0.2, 0.7, 0.5, 8)
    triple = phongrast.PhongMaterial([0.2] * 3, np.full(3, 0.7), (0.5, 0.5, 0.5), 8.0)
    assert np.array_equal(scene.render("phong", mat=scalar), scene.render("phong", mat=triple))
    a = phongrast.render_object("gouraud", 1, scene.eye, scene.lookat, scene.up, 0.5, 20, 20, 1, 1, scene.verts,
                                scene.colors, scene.faces, scalar, scene.lights, 0.3, "full")
    b = phongrast.render_object("gouraud", 1, scene.eye, scene.lookat, scene.up, [0.5] * 3, 20, 20, 1, 1, scene.verts,
                                scene.colors, scene.faces, scalar, scene.lights, [0.3] * 3, "full")
    assert np.array_equal(a, b)


def test_lighting_names_and_combinations(reference):
    scene, expected = reference
    assert np.array_equal(scene.render("phong", "all"), expected)
    assert np.array_equal(scene.render("phong", "ambient+diffusion+specular"), expected)
    assert np.array_equal(scene.render("phong", "diffusion"), scene.render("phong", "diffuse"))
    both = scene.render("phong", "ambient+specular")
    covered = ~np.all(both == np.float32(scene.bg), axis=2)
    parts = scene.render("phong", "ambient")[covered] + scene.render("phong", "specular")[covered]
    assert np.allclose(both[covered], parts, atol=1e-6)
    assert not np.array_equal(both, expected)


class ExerciseMaterial:
    def __init__(self, ka, kd, ks, n_phong):
        self.ka, self.kd, self.ks, self.n_phong = ka, kd, ks, n_phong


class OtherMaterial:
    k_a, k_d, k_s, nphong = [0.3, 0.25, 0.2], 0.7, [0.9, 0.8, 0.7], 12


class ExerciseLight:
    def __init__(self, position, intensity):
        self.position, self.intensity = position, intensity


def test_the_users_own_material_and_light_classes_work(reference):
    scene, expected = reference
    mat = ExerciseMaterial([0.3, 0.25, 0.2], 0.7, [0.9, 0.8, 0.7], 12)
    lights = [ExerciseLight(l.pos, l.intensity) for l in scene.lights]
    assert np.array_equal(scene.render("phong", mat=mat, lights=lights), expected)
    assert np.array_equal(scene.render("phong", mat=OtherMaterial()), expected)
    Material = collections.namedtuple("Material", "ka kd ks n")
    assert np.array_equal(scene.render("phong", mat=Material([0.3, 0.25, 0.2], 0.7, [0.9, 0.8, 0.7], 12)), expected)
    as_dicts = [{"pos": l.pos, "intensity": l.intensity} for l in scene.lights]
    assert np.array_equal(scene.render("phong", lights=as_dicts), expected)
    one = scene.render("phong", lights=scene.lights[0])
    assert np.array_equal(one, scene.render("phong", lights=[ExerciseLight(scene.lights[0].pos, scene.lights[0].intensity)]))


def test_row_zero_is_the_top_of_the_picture():
    verts = np.array([[-1.0, 0.2, 0.0], [1.0, 0.2, 0.0], [0.0, 1.0, 0.0]]).T  # above the view's centre
    image = phongrast.render_object("gouraud", 1, [0, 0, 2], [0, 0, 0], [0, 1, 0], 0, 20, 20, 2, 2, verts, None,
                                    [[0], [1], [2]], phongrast.PhongMaterial(1, 0, 0, 1), [], 1, "ambient")
    rows = np.nonzero(image.any(axis=(1, 2)))[0]
    assert len(rows) > 0 and rows.max() < 10


def test_seed_classes_copy_and_pickle_like_plain_python_objects(reference):
    import copy
    import pickle
    scene, expected = reference
    mat = pickle.loads(pickle.dumps(copy.deepcopy(scene.mat)))
    lights = [pickle.loads(pickle.dumps(copy.copy(light))) for light in scene.lights]
    assert np.array_equal(scene.render("phong", mat=mat, lights=lights), expected)
    assert repr(mat).startswith("PhongMaterial(ka=") and lights[0].position is lights[0].pos


def render_with(scene, eye=None, up=None):
    """render_object of `scene` (Phong) with its eye or up given in another form."""
    return phongrast.render_object("phong", scene.focal, scene.eye if eye is None else eye, scene.lookat,
                                   scene.up if up is None else up, scene.bg, scene.M, scene.N, scene.H, scene.W,
                                   scene.verts, scene.colors, scene.faces, scene.mat, scene.lights, scene.ambient, "full")


def test_triples_in_every_form_read_the_same(reference):
    # Lists, tuples and 1-d float arrays are read without numpy's help; every other form (big-endian,
    # 2-d, integer, strided) through numpy: all of them must read the same three numbers.
    scene, expected = reference
    eye = [float(v) for v in scene.eye]
    strided = np.empty(6)[::2]
    strided[:] = eye
    forms = {"list": eye, "tuple": tuple(eye), "float64": np.array(eye),
             "big-endian": np.array(eye, ">f8"), "2-d": np.array([eye]), "strided": strided,
             "object list": [np.float64(v) for v in eye]}
    for name, form in forms.items():
        assert np.array_equal(render_with(scene, eye=form), expected), name
    rounded = [float(np.float32(v)) for v in eye]
    assert rounded != eye  # the float32 form below must really round
    assert np.array_equal(render_with(scene, eye=np.array(rounded, np.float32)), render_with(scene, eye=rounded))
    assert np.array_equal(render_with(scene, up=[0, 1, 0]), render_with(scene, up=np.array([0.0, 1.0, 0.0])))


def test_numbers_too_large_or_not_finite_in_a_triple_are_refused(reference):
    scene, _ = reference
    for bad in ([0.0, 10 ** 400, 1.0], (0.0, float("inf"), 1.0), np.array([0.0, np.nan, 1.0], np.float32)):
        with pytest.raises((ValueError, TypeError, OverflowError)) as raised:
            render_with(scene, eye=bad)
        assert "eye" in str(raised.value), bad


def test_arrays_at_an_odd_address_read_the_same(reference):
    # A buffer at an odd offset holds values off their alignment: read value by value, same image.
    scene, expected = reference

    def unaligned(array):
        data = np.ascontiguousarray(array)
        raw = np.frombuffer(b"\0" + data.tobytes(), dtype=data.dtype, offset=1).reshape(data.shape)
        assert not raw.flags.aligned
        return raw

    image = phongrast.render_object("phong", scene.focal, scene.eye, scene.lookat, scene.up, scene.bg, scene.M, scene.N,
                                    scene.H, scene.W, unaligned(scene.verts.T), unaligned(scene.colors.T),
                                    unaligned(scene.faces.T), scene.mat, scene.lights, scene.ambient, "full")
    assert np.array_equal(image, expected)
