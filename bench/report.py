#!/usr/bin/env python3
"""The benchmarks' Markdown tables from their raw outputs: one script for all.

  bench/report.py effects [--clock=cpu] RESULTS.json [NOTE ...]
        bench_effects' JSON (Google Benchmark, with repetitions): each effect
        set's cost, specialised against general kernel, lights, culling
  bench/report.py callgrind PATH/TO/bench_effects_once
        runs valgrind --tool=callgrind on single renders: instruction counts do
        not depend on what else the machine is doing (needs valgrind)
  bench/report.py scaling RESULTS.json
        bench_scaling's JSON: log-log slopes of time against triangles and
        against shaded samples (a slope of 1 means time proportional to that
        quantity), the shader x lighting and shared-mesh cases, 2-thread speed-ups
  bench/report.py llvmpipe FILE...
        bench_llvmpipe's tables (one process per thread count) as one table
  bench/report.py summary LLVMPIPE_FILE... GOALS_FILE
        the speed goals per scene class: bench_llvmpipe's tables (one file
        per thread count) joined with bench_goals' rows, each goal met or not
  bench/report.py instructions PROGRAM [ARGUMENT...]
        the instructions one run of PROGRAM executes inside the render pipeline
        (valgrind --tool=callgrind), e.g. bench_speed_once --repeat 1 --warmup 0

bench/run.sh calls it. Python 3 standard library only: Debian's
/usr/bin/python3 runs it as it is.
"""
import fileinput
import json
import math
import os
import re
import subprocess
import sys
import tempfile
from collections import defaultdict

from report_effects import effects_command, least_squares, to_ms
from report_goals import summary_command


def fit_slope(xs, ys):
    """Least-squares slope of log(y) against log(x)."""
    return least_squares([math.log(x) for x in xs], [math.log(y) for y in ys])[1]


def run_ms(run):
    return to_ms(run["real_time"], run.get("time_unit", "ns"))


def scaling_command(args):
    """bench/report.py scaling RESULTS.json: the cost model of bench_scaling's JSON output."""
    if len(args) != 1:
        sys.stderr.write(scaling_command.__doc__ + "\n")
        return 2
    with open(args[0]) as f:
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
            cases.append((sweep, shader, what, threads, run["triangles"], run["samples"], rows, run_ms(run)))
            continue
        groups[(sweep, shader, threads)].append((run["triangles"], run["samples"], rows, run_ms(run)))

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
    return 0


def llvmpipe_command(args):
    """bench/report.py llvmpipe FILE...: merges bench_llvmpipe's per-thread-count tables, sorted by scene, shader, threads."""
    rows, scene_order, seen = [], [], set()
    for line in fileinput.input(args):
        if not line.startswith("| ") or line.startswith("| scene"):
            continue
        cells = [cell.strip() for cell in line.strip().strip("|").split("|")]
        if len(cells) != 11:
            continue
        cells[1] = cells[1].replace(",", "")
        key = (cells[0], cells[3], cells[4])
        if key in seen:  # a merged table printed earlier repeats rows
            continue
        seen.add(key)
        rows.append(cells)
        if cells[0] not in scene_order:
            scene_order.append(cells[0])
    rows.sort(key=lambda c: (scene_order.index(c[0]), c[3] != "gouraud", int(c[4])))
    print("| scene | triangles | image | shader | threads | phongrast exact ms | phongrast seed ms "
          "| llvmpipe ms (of which sort) | exact / llvmpipe | seed / llvmpipe | goal <= 0.25 |")
    print("|---|---:|---|---|---:|---:|---:|---:|---:|---:|---|")
    for c in rows:
        c[1] = f"{int(c[1]):,}"
        print("| " + " | ".join(c) + " |")
    return 0


# Counting starts and stops at the render pipeline's entry (float precision): no scene
# generation, no process start-up. The one place that names it.
TOGGLE = "*render_pass<float>*"


def count(binary, args, function=None):
    """Instructions inside the render for one case; with `function`, also its inclusive share."""
    with tempfile.TemporaryDirectory() as folder:
        out = os.path.join(folder, "callgrind.out")
        subprocess.run(["valgrind", "--tool=callgrind", f"--callgrind-out-file={out}",
                        f"--toggle-collect={TOGGLE}", binary] + args,
                       check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        total = None
        with open(out, encoding="utf-8", errors="replace") as f:
            for line in f:
                if line.startswith(("summary:", "totals:")):
                    total = int(line.split()[1])
                    break
        inclusive = None
        if function:
            annotated = subprocess.run(["callgrind_annotate", "--inclusive=yes", out], check=True,
                                       capture_output=True, text=True).stdout
            for line in annotated.splitlines():
                if function in line:
                    inclusive = int(re.match(r"\s*([\d,]+)", line).group(1).replace(",", ""))
                    break
        return total, inclusive


def mi(n):
    return f"{n / 1e6:.2f}"


def callgrind_command(args):
    """bench/report.py callgrind PATH/TO/bench_effects_once: instruction counts of single renders."""
    if len(args) != 1:
        sys.stderr.write(callgrind_command.__doc__ + "\n")
        return 2
    binary = args[0]
    out = ["Millions of instructions (Mi) executed by one render, counted by callgrind "
           "(`bench/report.py callgrind`), 512 x 512, one thread, RenderOptions::exact().", ""]

    out += ["#### Ambient only", "",
            "| icosphere | flat Mi | Gouraud Mi | Phong Mi | Phong ÷ Gouraud | general-kernel Phong Mi | general ÷ specialised Phong |",
            "|---|---:|---:|---:|---:|---:|---:|"]
    for levels, name in ((3, "1,280 triangles"), (6, "81,920 triangles")):
        base = ["--levels", str(levels), "--lighting", "ambient"]
        flat, _ = count(binary, base + ["--shader", "flat"])
        gouraud, _ = count(binary, base + ["--shader", "gouraud"])
        phong, _ = count(binary, base + ["--shader", "phong"])
        general, _ = count(binary, base + ["--shader", "phong", "--general"])
        out.append(f"| {name} | {mi(flat)} | {mi(gouraud)} | {mi(phong)} | {phong / gouraud:.3f} "
                   f"| {mi(general)} | {general / phong:.2f} |")
    out.append("")

    out += ["#### Phong, full lighting, against the number of lights (icosphere, 1,280 triangles)", "",
            "| lights | specialised Mi | added per light | general Mi | added per light |",
            "|---|---:|---:|---:|---:|"]
    previous = {}
    for lights in (0, 1, 2, 4, 8):
        row = f"| {lights} |"
        for kernel in ("special", "general"):
            args = ["--levels", "3", "--shader", "phong", "--lights", str(lights)]
            if kernel == "general":
                args.append("--general")
            n, _ = count(binary, args)
            step = ""
            if kernel in previous and lights > 1:
                last_lights, last_n = previous[kernel]
                step = mi((n - last_n) / (lights - last_lights))
            previous[kernel] = (lights, n)
            row += f" {mi(n)} | {step} |"
        out.append(row)
    row = "| 2 + 6 of zero intensity |"
    for kernel in ("special", "general"):
        args = ["--levels", "3", "--shader", "phong", "--lights", "2", "--dark", "6"]
        if kernel == "general":
            args.append("--general")
        n, _ = count(binary, args)
        row += f" {mi(n)} | |"
    out += [row, ""]

    out += ["#### Back-face culling (full lighting, 2 lights, specialised kernel)", "",
            "| icosphere | shader | draw all Mi | cull Mi | cull ÷ draw all | of which closedness test Mi |",
            "|---|---|---:|---:|---:|---:|"]
    for levels, name in ((3, "1,280 triangles"), (6, "81,920 triangles")):
        for shader in ("gouraud", "phong"):
            args = ["--levels", str(levels), "--shader", shader]
            off, _ = count(binary, args)
            on, test = count(binary, args + ["--cull"], function="find_hidden_back_faces")
            out.append(f"| {name} | {shader} | {mi(off)} | {mi(on)} | {on / off:.2f} | "
                       f"{mi(test) if test else '—'} |")
    out.append("")
    print("\n".join(out))
    return 0


def instructions_command(args):
    """bench/report.py instructions PROGRAM [ARGUMENT...]: one run's instructions inside the render pipeline."""
    if not args:
        sys.stderr.write(instructions_command.__doc__ + "\n")
        return 2
    print(count(args[0], args[1:])[0])
    return 0


COMMANDS = {"effects": effects_command, "callgrind": callgrind_command, "scaling": scaling_command,
            "llvmpipe": llvmpipe_command, "summary": summary_command, "instructions": instructions_command}


def main(argv):
    if len(argv) < 2 or argv[1] not in COMMANDS:
        sys.stderr.write(__doc__)
        return 2
    return COMMANDS[argv[1]](argv[2:])


if __name__ == "__main__":
    sys.exit(main(sys.argv))
