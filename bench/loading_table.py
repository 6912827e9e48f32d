#!/usr/bin/env python3
"""Markdown table of bench_loading's medians (its --benchmark_out JSON).

Usage: loading_table.py results.json
One row per format and size: phongrast's median time, MB/s and triangles/s,
then each other reader's median time and how many times slower it is
(its time / phongrast's time, measured in the same run; above 1 is slower).
"""
import json
import sys


def main(path):
    with open(path) as f:
        runs = json.load(f)["benchmarks"]
    medians = {}
    sizes = {}
    for run in runs:
        if run.get("aggregate_name") != "median":
            continue
        _, fmt, triangles, reader = run["run_name"].split("/")[:4]
        key = (fmt, int(triangles))
        medians.setdefault(key, {})[reader] = run
        sizes[key] = run["file_MB"]
    others = ["previous", "assimp", "tinygltf"]
    print("| format | triangles | file MB | phongrast ms | MB/s | M triangles/s | "
          + " | ".join(f"{o} ms (x phongrast)" for o in others) + " |")
    print("|---|---:|---:|---:|---:|---:|" + "---:|" * len(others))
    order = ["obj", "ply-ascii", "ply-binary", "stl-binary", "glb"]
    for key in sorted(medians, key=lambda k: (order.index(k[0]) if k[0] in order else 99, k[1])):
        row = medians[key]
        ours = row.get("phongrast")
        if ours is None:
            continue
        ms = ours["real_time"]
        cells = [key[0], f"{key[1]:,}", f"{sizes[key]:.1f}", f"{ms:.2f}",
                 f"{ours['bytes_per_second'] / 1e6:.0f}", f"{ours['triangles_per_second'] / 1e6:.2f}"]
        for other in others:
            if other in row:
                t = row[other]["real_time"]
                cells.append(f"{t:.2f} ({t / ms:.1f}x)")
            else:
                cells.append("—")
        print("| " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main(sys.argv[1])
