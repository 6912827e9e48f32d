#!/usr/bin/env python3
"""What calling phongrast from Python adds to the C++ render (docs/python.md).

For each scene, alternately: the Python call (render(scene), render_object
with the seed's arrays, Renderer.render), timed around the call in Python, and
the C++ render(scene) of the same scene (for Renderer.render, and for
render_object a second time: a C++ Renderer's frame, what `phongrast render
--repeat` times) timed inside C++ with no Python in between
(_cpp_render_seconds), in the same process. Reports the medians, the
overhead (difference of the medians) and the ratio, and checks the budget: the
Python call adds at most 5% or 0.2 ms, whichever is larger.

Scenes: the default scene (assets/default.json, 512x512, Phong), the same on
a 1x1 image (the per-call cost with almost no fill), and a generated torus of
1,048,576 triangles at 512x512 (no shared asset needed).

    PYTHONPATH=build/release/python /usr/bin/python3 bench/python_overhead.py [--repeats 201] [--big-repeats 15] [--threads 1]
"""
import argparse
import os
import pathlib
import statistics
import sys
import time

import numpy as np

import phongrast

ROOT = pathlib.Path(__file__).resolve().parents[1]


def torus(rings=1024, sides=512, radius=1.0, tube=0.35):
    """A closed torus grid: rings x sides vertices, 2 x rings x sides triangles, rainbow colours."""
    u = np.linspace(0, 2 * np.pi, rings, endpoint=False)[:, None]
    v = np.linspace(0, 2 * np.pi, sides, endpoint=False)[None, :]
    verts = np.stack([(radius + tube * np.cos(v)) * np.cos(u), tube * np.sin(v) * np.ones_like(u),
                      (radius + tube * np.cos(v)) * np.sin(u)], -1).reshape(-1, 3)
    colors = np.stack([0.5 + 0.5 * np.cos(u + 0 * v), 0.5 + 0.5 * np.cos(u + 2.1 + 0 * v),
                       0.5 + 0.5 * np.cos(u + 4.2 + 0 * v)], -1).reshape(-1, 3)
    i, j = np.meshgrid(np.arange(rings), np.arange(sides), indexing="ij")
    a, b = i * sides + j, ((i + 1) % rings) * sides + j
    c, d = ((i + 1) % rings) * sides + (j + 1) % sides, i * sides + (j + 1) % sides
    faces = np.concatenate([np.stack([a, d, c], -1).reshape(-1, 3), np.stack([a, c, b], -1).reshape(-1, 3)])
    return verts, colors, faces


def seed_arguments(scene):
    """render_object's arguments for `scene`: the exercise's 3 x Nv Fortran-ordered arrays."""
    mesh = scene.mesh
    colors = mesh.colors if mesh.colors is not None else np.ones_like(mesh.positions)
    m = scene.material
    material = phongrast.PhongMaterial(m["ka"], m["kd"], m["ks"], m["n"])
    lights = [phongrast.PointLight(l["position"], l["intensity"]) for l in scene.lights]
    (M, N), (H, W) = scene.size, scene.sensor
    return (scene.shader, scene.focal, scene.eye, scene.lookat, scene.up, scene.background, M, N, H, W,
            np.asfortranarray(mesh.positions.T), np.asfortranarray(colors.T), np.asfortranarray(mesh.faces.T),
            material, lights, scene.ambient, scene.lighting)


def measure(python_call, cpp_call, repeats):
    """Python-call and C++-render times (seconds) in pairs, after one warm-up of each;
    which of the two goes first alternates, so neither always finds the caches as the other left them."""
    python_call()
    cpp_call()
    python_times, cpp_times = [], []

    def time_python():
        start = time.perf_counter()
        python_call()
        python_times.append(time.perf_counter() - start)

    for repeat in range(repeats):
        if repeat % 2 == 0:
            time_python()
            cpp_times.extend(cpp_call())
        else:
            cpp_times.extend(cpp_call())
            time_python()
    return python_times, cpp_times


def report(name, python_times, cpp_times):
    """One table row: medians, their difference and ratio, the median of the paired
    differences (each Python call minus the C++ render next to it: steadier on a busy
    machine), and the budget, max(5% of the C++ median, 0.2 ms), checked against both."""
    py, cpp = statistics.median(python_times), statistics.median(cpp_times)
    overhead = py - cpp
    paired = statistics.median(p - c for p, c in zip(python_times, cpp_times))
    budget = max(0.05 * cpp, 0.2e-3)
    within = overhead <= budget and paired <= budget
    print(f"| {name} | {cpp * 1e3:.2f} | {py * 1e3:.2f} | {overhead * 1e3:+.3f} | {py / cpp:.3f} | "
          f"{paired * 1e3:+.3f} | {budget * 1e3:.2f} | {'yes' if within else 'NO'} |", flush=True)
    return within


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=201, help="pairs for the default scene (default 201)")
    parser.add_argument("--big-repeats", type=int, default=15, help="pairs for the 1M-triangle torus (default 15)")
    parser.add_argument("--threads", type=int, default=1, help="render threads (default 1: the steadiest timing)")
    args = parser.parse_args()
    options = {"threads": args.threads}

    default = phongrast.Scene.load(str(ROOT / "assets" / "default.json"))
    # The same scene on one pixel: almost no fill, so what remains is the per-call cost.
    one_pixel = default.copy()
    one_pixel.size = (1, 1)
    verts, colors, faces = torus()
    big = phongrast.Scene.from_mesh(phongrast.Mesh(verts, faces, colors=colors), 512, 512)
    print(f"phongrast {phongrast.__version__}, Python {sys.version.split()[0]}, numpy {np.__version__}, "
          f"{args.repeats}/{args.big_repeats} pairs, threads={args.threads}, load average {os.getloadavg()[0]:.1f}; "
          f"times in ms (medians)\n")
    print("| call | C++ render | Python call | difference | ratio | paired difference | budget | within |")
    print("|---|---:|---:|---:|---:|---:|---:|---|")
    ok = True
    for label, scene, repeats in [
            (f"default scene 512x512, {default.mesh.triangle_count} triangles", default, args.repeats),
            (f"default scene 1x1, {default.mesh.triangle_count} triangles", one_pixel, args.repeats),
            (f"torus 512x512, {big.mesh.triangle_count} triangles", big, args.big_repeats)]:
        arguments = seed_arguments(scene)
        exact = phongrast.render_object(*arguments, mode="exact", **options)
        assert np.array_equal(exact, phongrast.render(scene, **options)[0]), "render_object and render differ"
        cpp_render = lambda: phongrast._cpp_render_seconds(scene, 1, **options)
        ok &= report(f"render(scene), {label}",
                     *measure(lambda: phongrast.render(scene, **options), cpp_render, repeats))
        ok &= report(f"render_object(3 x Nv arrays, mode=\"exact\"), {label}",
                     *measure(lambda: phongrast.render_object(*arguments, mode="exact", **options), cpp_render,
                              repeats))
        # Against a C++ Renderer's frames: the Python call adds the copy of the image it returns.
        python_renderer, cpp_renderer = phongrast.Renderer(**options), phongrast.Renderer(**options)
        # The seed's one-off call against what `phongrast render --repeat` times (a warm Renderer's frame).
        ok &= report(f"render_object(3 x Nv arrays, mode=\"exact\") vs a C++ Renderer frame, {label}",
                     *measure(lambda: phongrast.render_object(*arguments, mode="exact", **options),
                              lambda: cpp_renderer._cpp_render_seconds(scene, 1), repeats))
        # The same from fresh memory, as every call was before render() kept its thread's memory
        # (the release is timed with the call: a fresh call freed its memory before returning).
        # Informative: not counted against the budget.
        report(f"(fresh memory) release_render_memory() + render_object vs a C++ Renderer frame, {label}",
               *measure(lambda: (phongrast.release_render_memory(),
                                 phongrast.render_object(*arguments, mode="exact", **options)),
                        lambda: cpp_renderer._cpp_render_seconds(scene, 1), repeats))
        ok &= report(f"Renderer.render(scene), {label}",
                     *measure(lambda: python_renderer.render(scene), lambda: cpp_renderer._cpp_render_seconds(scene, 1),
                              repeats))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
