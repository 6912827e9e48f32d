"""render_object and render keep the calling thread's working memory for the
next call (phongrast.release_render_memory() frees it): the pictures are those
of a call from fresh memory, whatever was rendered before, in any thread."""
import threading

import numpy as np
import pytest

import phongrast
from conftest import SeedScene, assert_same_bits, bumpy_sphere


def calls():
    """Different meshes, sizes, shaders, modes and options, one after another."""
    small = SeedScene(M=40, N=30)
    large = SeedScene(M=150, N=200)
    verts, colors, faces = bumpy_sphere(rings=10, segments=14)
    return [
        lambda: large.render("phong", mode="exact"),
        lambda: small.render("gouraud", mode="seed"),
        lambda: large.render("flat", lighting="diffusion", samples=2),
        lambda: small.render("phong", verts=verts, colors=colors, faces=faces, mode="exact", threads=1),
        lambda: large.render("gouraud", colors=None, precision="double"),
        lambda: small.render("phong", mode="exact", visibility="depth-buffer"),
        lambda: large.render("phong", mode="exact"),
    ]


def test_each_call_paints_what_a_call_from_fresh_memory_paints():
    phongrast.release_render_memory()
    for index, call in enumerate(calls()):
        warm = call()  # finds the memory of the call before: another scene, size and options
        phongrast.release_render_memory()
        fresh = call()
        assert_same_bits(warm, fresh)


def test_a_mesh_changed_in_place_is_drawn_anew():
    scene = SeedScene(M=60, N=80)
    before = scene.render("phong", mode="exact")
    scene.verts[1] *= 0.7  # the same array, changed in place
    after = scene.render("phong", mode="exact")
    phongrast.release_render_memory()
    fresh = scene.render("phong", mode="exact")
    assert not np.array_equal(before, after)
    assert_same_bits(after, fresh)


def test_render_scene_after_render_object_and_back():
    scene = phongrast.Scene.from_mesh(phongrast.Mesh(*[a.T for a in bumpy_sphere()[::2]]), 70, 90)
    phongrast.release_render_memory()
    fresh, _ = phongrast.render(scene)
    SeedScene(M=120, N=100).render("gouraud")
    warm, _ = phongrast.render(scene)
    assert_same_bits(warm, fresh)


def test_threads_each_keep_their_own_memory():
    expected = [call() for call in calls()]
    results, errors = {}, []

    def work(order):
        try:
            for index in order:
                results[(tuple(order), index)] = calls()[index]()
        except Exception as error:  # reported below
            errors.append(error)

    orders = [list(range(len(expected))), list(reversed(range(len(expected))))]
    threads = [threading.Thread(target=work, args=(order,)) for order in orders]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    assert not errors
    for (order, index), image in results.items():
        assert_same_bits(image, expected[index])
    assert len(results) == 2 * len(expected)


def test_images_still_referenced_are_never_rendered_into():
    """A freed image's memory becomes the next call's working image (no copy
    of the picture on return); one still referenced, or viewed, must keep
    its pixels whatever is rendered after it."""
    scene = SeedScene(M=64, N=48)
    phongrast.release_render_memory()
    first = scene.render("phong", mode="exact")
    first_pixels = first.copy()
    view = first[10:20]
    second = scene.render("gouraud", mode="seed")
    second_pixels = second.copy()
    del first  # the view still holds its memory
    for shader in ["flat", "phong", "gouraud", "phong"]:
        latest = scene.render(shader, mode="exact")  # rebinding frees the previous one for the next call
        scene_image, _ = phongrast.render(phongrast.Scene.from_mesh(phongrast.Mesh(*[a.T for a in bumpy_sphere()[::2]]), 30, 20))
    assert_same_bits(view, first_pixels[10:20])
    assert_same_bits(second, second_pixels)
    phongrast.release_render_memory()
    assert_same_bits(latest, scene.render("phong", mode="exact"))
    assert scene_image.shape == (30, 20, 3)
