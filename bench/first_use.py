"""First-use costs of two builds of `phongrast`, measured alternately
(issue 26, points 1 and 4; docs/startup.md quotes the output).

    python3 bench/first_use.py BASELINE_PHONGRAST NEW_PHONGRAST [--rounds N] [--work DIR]

Each round runs every case once with the baseline and once with the new
binary, in that order, so both see the same machine; medians over the
rounds, and the median of the per-round ratios new / baseline. On a shared
machine only those ratios mean much: the load average is printed with them.

Cases (the meshes are generated into --work by NEW_PHONGRAST):
  version    `phongrast --version`, wall time of the process
  render     `phongrast render knot10k.obj --size 256x256 -o t.png`: wall
             time of the process (goal: at most 30 ms)
  thumbnail  `phongrast thumbnail knot10k.obj t.png --size 256`
  first      a 100k-triangle knot at 512x512 on 1 thread: the first frame of a
             process (the render time in --stats-json of a run without --repeat)
  later      the same: the median of 5 frames after a warm-up (--repeat 5)
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time


def wall_ms(command, cwd):
    start = time.perf_counter()
    subprocess.run(command, cwd=cwd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return 1e3 * (time.perf_counter() - start)


def render_ms(binary, cwd, repeat):
    stats = os.path.join(cwd, "stats.json")
    command = [binary, "render", "knot100k.obj", "--size", "512x512", "--threads", "1", "-q", "-o", "k.png",
               "--stats-json", stats]
    if repeat:
        command += ["--repeat", "5"]
    subprocess.run(command, cwd=cwd, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    seconds = json.load(open(stats))["render_seconds"]
    return 1e3 * (seconds["median"] if repeat else seconds["runs"][0])


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("baseline")
    parser.add_argument("new")
    parser.add_argument("--rounds", type=int, default=30)
    parser.add_argument("--work", default=None)
    parser.add_argument("--cases", default="version,render,thumbnail,first,later")
    args = parser.parse_args()
    binaries = {"before": os.path.realpath(args.baseline), "after": os.path.realpath(args.new)}
    work = args.work or tempfile.mkdtemp(prefix="phongrast-first-use-")
    os.makedirs(work, exist_ok=True)
    new = binaries["after"]
    subprocess.run([new, "generate", "-q", "-o", os.path.join(work, "knot10k.obj"), "--segments", "250",
                    "--sides", "20"], check=True)
    subprocess.run([new, "generate", "-q", "-o", os.path.join(work, "knot100k.obj"), "--segments", "2500",
                    "--sides", "20"], check=True)
    cases = {
        "version": lambda b: wall_ms([b, "--version"], work),
        "render": lambda b: wall_ms([b, "render", "knot10k.obj", "--size", "256x256", "-q", "-o", "t.png"], work),
        "thumbnail": lambda b: wall_ms([b, "thumbnail", "knot10k.obj", "thumb.png", "--size", "256"], work),
        "first": lambda b: render_ms(b, work, repeat=False),
        "later": lambda b: render_ms(b, work, repeat=True),
    }
    chosen = args.cases.split(",")
    times = {(case, build): [] for case in chosen for build in binaries}
    for case in chosen:  # warm the page cache and the binaries
        for binary in binaries.values():
            cases[case](binary)
    for _ in range(args.rounds):
        for case in chosen:
            for build, binary in binaries.items():
                times[(case, build)].append(cases[case](binary))
    load = " ".join(open("/proc/loadavg").read().split()[:3])
    print(f"{args.rounds} rounds, alternating; {os.cpu_count()} cores; load average {load} at the end")
    print("| case | before (median ms) | after (median ms) | after / before (median of rounds) |")
    print("|---|---|---|---|")
    for case in chosen:
        before, after = times[(case, "before")], times[(case, "after")]
        ratio = statistics.median(a / b for a, b in zip(after, before))
        print(f"| {case} | {statistics.median(before):.2f} | {statistics.median(after):.2f} | {ratio:.3f} |")
    if "first" in chosen and "later" in chosen:
        for build in binaries:
            first = statistics.median(times[("first", build)])
            later = statistics.median(times[("later", build)])
            print(f"{build}: first frame / later frames (C++ command, 1 thread) = {first / later:.2f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
