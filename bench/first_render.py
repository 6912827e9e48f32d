"""One process's first render against its later ones (issue 26, point 4).

Prints, as JSON, the render times in ms (the library's own RenderStats
seconds, so Python's conversions are left out) of a Renderer's first frame
and of 5 more, on a 100k-triangle sphere at 512x512, at the thread count
given, and the process's peak resident memory in MiB. bench/first_render.sh
runs it in fresh processes, with glibc's malloc as it comes and with
transparent huge pages (GLIBC_TUNABLES=glibc.malloc.hugetlb=1), and reports
medians.
"""
import json
import resource
import sys

import numpy as np
import phongrast

n = 224  # n x n grid, 2 (n - 1)^2 = 99,458 triangles
u, v = np.meshgrid(np.linspace(0, np.pi, n), np.linspace(0, 2 * np.pi, n), indexing="ij")
positions = np.stack([np.sin(u) * np.cos(v), np.sin(u) * np.sin(v), np.cos(u)], -1).reshape(-1, 3)
index = np.arange(n * n).reshape(n, n)
a, b, c, d = index[:-1, :-1].ravel(), index[1:, :-1].ravel(), index[1:, 1:].ravel(), index[:-1, 1:].ravel()
faces = np.concatenate([np.stack([a, b, c], 1), np.stack([a, c, d], 1)]).astype(np.uint32)
scene = phongrast.Scene.from_mesh(phongrast.Mesh(positions, faces), 512, 512)
renderer = phongrast.Renderer(threads=int(sys.argv[1]) if len(sys.argv) > 1 else 0)
times = [renderer.render(scene)[1]["seconds"] * 1000 for _ in range(6)]
peak_mib = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
print(json.dumps({"first": times[0], "later": sorted(times[1:])[2], "peak_mib": peak_mib}))
