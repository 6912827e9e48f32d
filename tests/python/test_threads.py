"""The GIL is released while rendering: Python threads render in parallel and
give the same pictures as one after the other."""
import concurrent.futures
import threading
import time

import numpy as np

import phongrast
from conftest import SOURCE_DIR, SeedScene


def scenes():
    default = phongrast.Scene.load(str(SOURCE_DIR / "assets" / "default.json"))
    default.size = (192, 192)
    gouraud = default.copy()
    gouraud.shader = "gouraud"
    return default, gouraud


def test_two_threads_render_the_same_images_as_one_after_the_other():
    a, b = scenes()
    seed = SeedScene(M=160, N=160)
    jobs = [lambda: phongrast.render(a)[0], lambda: phongrast.render(b, mode="seed")[0],
            lambda: seed.render("phong"), lambda: phongrast.render(a, samples=2)[0]]
    sequential = [job() for job in jobs]
    with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
        for _ in range(3):
            parallel = list(pool.map(lambda job: job(), jobs + jobs))
            for i, image in enumerate(parallel):
                assert np.array_equal(image, sequential[i % len(jobs)]), i


def test_one_renderer_shared_by_two_threads_waits_its_turn():
    a, b = scenes()
    renderer = phongrast.Renderer(threads=1)
    expected = {id(a): phongrast.render(a)[0], id(b): phongrast.render(b)[0]}
    barrier = threading.Barrier(2)
    failures = []

    def work(scene):
        barrier.wait()
        for _ in range(4):
            image, _ = renderer.render(scene)
            if not np.array_equal(image, expected[id(scene)]):
                failures.append(id(scene))

    threads = [threading.Thread(target=work, args=(s,)) for s in (a, b)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert failures == []


def test_python_code_runs_while_a_render_is_in_progress():
    """This thread notes the time at each step while another renders. With the
    GIL held during the render, this thread could run only before the render
    really starts (the worker may hand over the GIL once, for the 5 ms switch
    interval, after noting its start time) and not at all in its middle."""
    scene, _ = scenes()
    scene.size = (512, 512)
    span, finished = [], threading.Event()

    def render():
        begin = time.perf_counter()
        phongrast.render(scene, samples=3, threads=1)
        span.extend([begin, time.perf_counter()])
        finished.set()

    steps = []
    worker = threading.Thread(target=render)
    worker.start()
    while not finished.is_set():
        steps.append(time.perf_counter())
    worker.join()
    begin, end = span
    middle = (begin + 0.3 * (end - begin), end - 0.3 * (end - begin))
    during = sum(1 for t in steps if middle[0] < t < middle[1])
    assert during > 100, f"{during} steps of this thread in the middle of a {end - begin:.3f} s render"
