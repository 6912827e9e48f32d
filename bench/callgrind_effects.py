#!/usr/bin/env python3
"""Instruction counts of single renders (callgrind), as Markdown tables.

Usage: callgrind_effects.py PATH/TO/bench_effects_once [> callgrind.md]

Wall-clock times on a machine shared with compilers are noisy; the number of
instructions a render executes is not. Each case of bench_effects_once is run
once under `valgrind --tool=callgrind`, counting only inside the render
pipeline (Pipeline<float>::run: no scene generation, no process start-up), and
the tables give the ambient-only Phong/Gouraud ratio, the instructions added
per light, and what culling saves. Python 3 standard library only.
"""
import os
import re
import subprocess
import sys
import tempfile

TOGGLE = "*Pipeline<float>::run*"


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


def main(argv):
    if len(argv) != 2:
        sys.stderr.write(__doc__)
        return 2
    binary = argv[1]
    out = ["Millions of instructions (Mi) executed by one render, counted by callgrind "
           "(`bench/callgrind_effects.py`), 512 x 512, one thread, RenderOptions::exact().", ""]

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


if __name__ == "__main__":
    sys.exit(main(sys.argv))
