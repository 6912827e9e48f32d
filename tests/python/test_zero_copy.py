"""No copies where the layout allows. numpy reports every buffer it allocates to
tracemalloc, so the peak traced memory during a call shows whether a numpy copy
was made; the control cases (an int32 array, an explicit copy) show the probe sees one."""
import gc
import tracemalloc

import numpy as np
import pytest

import phongrast

COUNT = 400_000  # vertices: 4.8 MB as float32, 9.6 MB as float64


def numpy_bytes_allocated_by(function):
    """Peak memory numpy (and Python) allocated while `function` ran."""
    gc.collect()
    tracemalloc.start()
    try:
        before = tracemalloc.get_traced_memory()[0]
        tracemalloc.reset_peak()
        result = function()
        return tracemalloc.get_traced_memory()[1] - before, result
    finally:
        tracemalloc.stop()


@pytest.fixture(scope="module")
def vertices():
    rng = np.random.default_rng(3)
    return rng.random((COUNT, 3)).astype(np.float32)


FACES = np.array([[0, 1, 2], [2, 1, 3]], np.int64)


@pytest.mark.parametrize("layout", ["float32 Nv x 3 C", "float32 3 x Nv F", "float64 Nv x 3 C", "float64 3 x Nv F",
                                    "float32 strided view"])
def test_vertex_arrays_are_read_in_place(vertices, layout):
    array = {"float32 Nv x 3 C": vertices, "float32 3 x Nv F": np.asfortranarray(vertices.T),
             "float64 Nv x 3 C": vertices.astype(np.float64), "float64 3 x Nv F": np.asfortranarray(vertices.T, np.float64),
             "float32 strided view": np.repeat(vertices, 2, axis=0)[::2]}[layout]
    allocated, mesh = numpy_bytes_allocated_by(lambda: phongrast.Mesh(array, FACES, colors=array))
    assert allocated < array.nbytes / 100, f"{allocated} bytes allocated reading {array.nbytes} bytes"
    assert np.array_equal(mesh.positions, np.asarray(array if array.shape[1] == 3 else array.T, np.float64))
    assert np.array_equal(mesh.colors, np.asarray(array if array.shape[1] == 3 else array.T, np.float32))


def test_the_probe_sees_a_converting_copy(vertices):
    as_int = (vertices * 100).astype(np.int32)
    allocated, _ = numpy_bytes_allocated_by(lambda: phongrast.Mesh(as_int, FACES))
    assert allocated >= as_int.nbytes * 2  # converted to float64 first: a copy, as documented


def test_render_object_reads_the_seed_arrays_in_place(vertices):
    verts = np.asfortranarray(vertices.T)  # 3 x Nv, as numpy.load gives the exercise's data
    faces = np.asfortranarray(np.arange(COUNT - COUNT % 3).reshape(-1, 3).T)
    mat = phongrast.PhongMaterial(0.2, 0.5, 0.5, 4)
    allocated, image = numpy_bytes_allocated_by(lambda: phongrast.render_object(
        "gouraud", 1, [0.5, 0.5, 3], [0.5, 0.5, 0.5], [0, 1, 0], 0, 64, 64, 0.5, 0.5, verts, verts, faces, mat,
        [], 0.5, "ambient", threads=1))
    assert allocated < verts.nbytes / 100
    assert image.any()


def test_the_returned_image_owns_the_cpp_buffer():
    mesh = phongrast.Mesh([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]])
    scene = phongrast.Scene.from_mesh(mesh, 1024, 768)
    allocated, (image, stats) = numpy_bytes_allocated_by(lambda: phongrast.render(scene))
    assert image.nbytes == 1024 * 768 * 3 * 4
    assert allocated < image.nbytes / 100  # no numpy buffer was made for it
    assert not image.flags.owndata and type(image.base).__name__ == "PyCapsule"
    assert image.flags.c_contiguous and image.flags.writeable
    expected = image.copy()
    del scene, mesh
    gc.collect()
    other, _ = phongrast.render(phongrast.Scene.from_mesh(phongrast.Mesh([[0, 0, 0], [2, 0, 0], [0, 1, 0]], [[0, 1, 2]]), 1024, 768))
    assert not np.shares_memory(image, other)
    assert np.array_equal(image, expected)  # still valid, not overwritten by a later render


def test_mesh_arrays_are_views_of_the_cpp_mesh():
    mesh = phongrast.Mesh(np.array([[0.0, 0, 0], [1, 0, 0], [0, 1, 0]]), [[0, 1, 2]], colors=np.ones((3, 3)))
    first, second = mesh.positions, mesh.positions
    assert first.__array_interface__["data"][0] == second.__array_interface__["data"][0]
    assert np.shares_memory(mesh.colors, mesh.colors) and np.shares_memory(mesh.faces, mesh.faces)
    first[1, 0] = 5.0
    assert mesh.positions[1, 0] == 5.0
    positions = phongrast.Mesh([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]]).positions  # the mesh is gone
    gc.collect()
    assert positions.tolist() == [[0, 0, 0], [1, 0, 0], [0, 1, 0]]


def test_editing_the_scene_mesh_in_place_changes_the_next_render():
    verts = np.array([[-1.0, -1, 0], [1, -1, 0], [0, 1, 0], [1, 1, -0.5]])
    faces = [[0, 1, 2], [2, 1, 3]]
    scene = phongrast.Scene.from_mesh(phongrast.Mesh(verts, faces), 40, 40)
    before, _ = phongrast.render(scene)
    view = scene.mesh.positions
    view[:, 0] += 0.25  # in place: no new mesh, no copy
    assert np.shares_memory(view, scene.mesh.positions)
    after, _ = phongrast.render(scene)
    moved = scene.copy()
    moved.mesh = phongrast.Mesh(verts + [0.25, 0, 0], faces)
    assert not np.array_equal(before, after)
    assert np.array_equal(after, phongrast.render(moved)[0])
    assert not np.shares_memory(view, moved.mesh.positions)  # setting a mesh copies it
    scene.mesh = phongrast.Mesh(verts, faces)
    assert view[0, 0] == -0.75  # the old view stays valid (and keeps the old mesh)
