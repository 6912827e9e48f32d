"""A long render can be stopped: Ctrl-C (SIGINT) raises KeyboardInterrupt
while it runs, not when it returns; the progress callable sees the fraction
done and can cancel; the Renderer stays usable afterwards."""
import os
import signal
import threading
import time

import numpy as np
import pytest

import phongrast


def long_scene():
    """A few hundred thousand small triangles filling a large image: seconds of work."""
    rng = np.random.default_rng(1)
    count = 300_000
    centres = rng.uniform(-1.0, 1.0, (count, 3))
    corners = np.repeat(centres, 3, axis=0) + rng.uniform(-0.05, 0.05, (3 * count, 3))
    faces = np.arange(3 * count, dtype=np.uint32).reshape(count, 3)
    scene = phongrast.Scene.from_mesh(phongrast.Mesh(corners, faces), 1024, 1024)
    return scene


def small_scene():
    mesh = phongrast.Mesh([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]])
    return phongrast.Scene.from_mesh(mesh, 16, 16)


def interrupt_after(seconds):
    """Sends SIGINT to this process from another thread after `seconds`; returns the time it was sent."""
    sent = {}

    def send():
        sent["at"] = time.monotonic()
        os.kill(os.getpid(), signal.SIGINT)

    timer = threading.Timer(seconds, send)
    timer.start()
    return timer, sent


@pytest.mark.parametrize("with_renderer", [False, True])
def test_sigint_from_a_thread_during_a_long_render_raises_keyboard_interrupt(with_renderer):
    """No progress callable: the module checks for signals by itself."""
    scene = long_scene()
    renderer = phongrast.Renderer(samples=2) if with_renderer else None
    timer, sent = interrupt_after(0.3)
    with pytest.raises(KeyboardInterrupt):
        if renderer is not None:
            renderer.render(scene)
        else:
            phongrast.render(scene, samples=2)
    stopped = time.monotonic()
    timer.join()
    print(f"KeyboardInterrupt {(stopped - sent['at']) * 1000:.1f} ms after SIGINT")
    # The renderer (and the module) render normally afterwards.
    image, stats = (renderer.render(small_scene()) if renderer is not None else phongrast.render(small_scene()))
    assert stats["triangles_drawn"] == 1
    assert np.isfinite(image).all()


def test_sigint_stops_the_render_midway_at_the_next_progress_report():
    """SIGINT sent (from another thread) once the render has started: the
    render never reaches its end, and KeyboardInterrupt comes at the next
    report (about 20 ms later on a quiet machine; the time is printed)."""
    fractions = []
    sent = {}

    def progress(fraction):
        fractions.append((time.monotonic(), fraction))
        if fraction > 0.0 and "at" not in sent:
            sent["at"] = time.monotonic()
            sender = threading.Thread(target=os.kill, args=(os.getpid(), signal.SIGINT))
            sender.start()
            sender.join()

    renderer = phongrast.Renderer(samples=2, progress=progress)
    with pytest.raises(KeyboardInterrupt):
        renderer.render(long_scene())
    stopped = time.monotonic()
    assert "at" in sent
    assert max(f for _, f in fractions) < 1.0  # cancelled midway, not at the end
    print(f"KeyboardInterrupt {(stopped - sent['at']) * 1000:.1f} ms after SIGINT, at {fractions[-1][1]:.3f} of the render")
    assert renderer.render(small_scene())[1]["triangles_drawn"] == 1


def test_progress_callable_sees_fractions_and_can_cancel():
    seen = []
    image, stats = phongrast.render(small_scene(), progress=lambda f: seen.append(f))
    assert seen and seen[-1] == 1.0
    assert all(0.0 <= f <= 1.0 for f in seen)

    calls = []

    def stop(fraction):
        calls.append(fraction)
        return False

    with pytest.raises(phongrast.RenderCancelled):
        phongrast.render(long_scene(), progress=stop)
    assert len(calls) == 1


def test_an_exception_in_the_progress_callable_stops_the_render_and_propagates():
    def fail(fraction):
        raise ZeroDivisionError("from the callback")

    renderer = phongrast.Renderer(progress=fail)
    with pytest.raises(ZeroDivisionError, match="from the callback"):
        renderer.render(small_scene())
    with pytest.raises(TypeError, match="progress"):
        phongrast.render(small_scene(), progress=3)


def test_render_object_takes_progress_too():
    seen = []
    image = phongrast.render_object("phong", 1.0, [0, 0, 3], [0, 0, 0], [0, 1, 0], [1, 1, 1], 8, 8, 1.0, 1.0,
                                    [[0, 0, 0], [1, 0, 0], [0, 1, 0]], None, [[0, 1, 2]],
                                    phongrast.PhongMaterial(0.1, 0.8, 1.0, 10),
                                    [phongrast.PointLight([1, 2, 3], 1.0)], 0.2, "full", progress=seen.append)
    assert image.shape == (8, 8, 3)
    assert seen and seen[-1] == 1.0
