#!/usr/bin/env python3
"""Cost model from bench_scaling's JSON output: log-log slopes of render time
against triangles (the "triangles" sweep, image fixed) and against shaded
samples (the "pixels" sweep, mesh fixed), per shader and thread count; the
time and cost per sample of every case of the "lighting" (shader x lighting)
and "meshes" (../shared/assets) sweeps; and the 2-thread speed-up of every
case.

A slope of 1 means time proportional to that quantity; below 1, a fixed cost
(or the other quantity) still matters over that range.

Usage:
  build/<dir>/bench/bench_scaling [--quick] --benchmark_out=scaling.json --benchmark_out_format=json
  bench/scaling_slopes.py scaling.json
"""
import json
import math
import sys
from collections import defaultdict


def fit_slope(xs, ys):
    """Least-squares slope of log(y) against log(x)."""
    lx = [math.log(x) for x in xs]
    ly = [math.log(y) for y in ys]
    mx, my = sum(lx) / len(lx), sum(ly) / len(ly)
    sxx = sum((a - mx) ** 2 for a in lx)
    sxy = sum((a - mx) * (b - my) for a, b in zip(lx, ly))
    return sxy / sxx if sxx > 0 else float("nan")


def to_ms(run):
    scale = {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}[run.get("time_unit", "ns")]
    return run["real_time"] * scale


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    with open(sys.argv[1]) as f:
        data = json.load(f)
    groups = defaultdict(list)  # (sweep, shader, threads) -> [(triangles, samples, rows, ms)]
    cases = []  # lighting and meshes sweeps: (sweep, shader, what, threads, triangles, samples, rows, ms)
    for run in data["benchmarks"]:
        if run.get("run_type", "iteration") != "iteration":
            continue
        parts = run["name"].split("/")
        sweep, shader, threads = parts[0], parts[1], int(parts[2].split(":")[1])
        rows = int(next(p for p in parts if p.startswith("rows:")).split(":")[1])
        if sweep in ("lighting", "meshes"):
            what = parts[3].split(":", 1)[1]
            cases.append((sweep, shader, what, threads, run["triangles"], run["samples"], rows, to_ms(run)))
            continue
        groups[(sweep, shader, threads)].append((run["triangles"], run["samples"], rows, to_ms(run)))

    context = data.get("context", {})
    print(f"host {context.get('host_name', '?')}, {context.get('num_cpus', '?')} CPUs, "
          f"load average {context.get('load_avg', '?')}, date {context.get('date', '?')}")
    print()
    print("| sweep | shader | threads | range | slope vs triangles | slope vs samples | ms per 1M triangles (largest) | ns per sample (largest) |")
    print("|---|---|---:|---|---:|---:|---:|---:|")
    for (sweep, shader, threads), runs in sorted(groups.items()):
        runs.sort()
        if len(runs) < 2:
            continue
        tris = [r[0] for r in runs]
        samples = [r[1] for r in runs]
        ms = [r[3] for r in runs]
        if sweep == "triangles":
            rng = f"{int(min(tris)):,}..{int(max(tris)):,} triangles at {runs[0][2]}^2"
            s_tri, s_samp = f"{fit_slope(tris, ms):.2f}", "-"
        else:
            runs.sort(key=lambda r: r[2])
            samples = [r[1] for r in runs]
            ms = [r[3] for r in runs]
            rng = f"{runs[0][2]}^2..{runs[-1][2]}^2 with {int(tris[0]):,} triangles"
            s_tri, s_samp = "-", f"{fit_slope(samples, ms):.2f}"
        last = max(runs, key=lambda r: r[0] if sweep == "triangles" else r[2])
        print(f"| {sweep} | {shader} | {threads} | {rng} | {s_tri} | {s_samp} | "
              f"{last[3] / last[0] * 1e6:.0f} | {last[3] * 1e6 / max(last[1], 1):.1f} |")

    if cases:
        print()
        print("| sweep | shader | lighting or mesh | threads | triangles | image | samples shaded | ms | ns per sample |")
        print("|---|---|---|---:|---:|---|---:|---:|---:|")
        for sweep, shader, what, threads, tri, samples, rows, ms in cases:
            print(f"| {sweep} | {shader} | {what} | {threads} | {int(tri):,} | {rows}^2 | {int(samples):,} | "
                  f"{ms:.2f} | {ms * 1e6 / max(samples, 1):.1f} |")

    print()
    print("| case | 1 thread ms | 2 threads ms | speed-up |")
    print("|---|---:|---:|---:|")
    one = {}
    two = {}
    for (sweep, shader, threads), runs in groups.items():
        for tri, _, rows, ms in runs:
            key = f"{sweep} {shader} {int(tri):,} triangles {rows}^2"
            (one if threads == 1 else two)[key] = ms
    for key in sorted(one):
        if key in two:
            print(f"| {key} | {one[key]:.2f} | {two[key]:.2f} | {one[key] / two[key]:.2f} |")


if __name__ == "__main__":
    main()
