"""The speed goals per scene class (`bench/report.py summary`): bench_llvmpipe's
tables (one file per thread count) joined with bench_goals' rows, one Markdown
table per scene class, then each goal met or not with its worst case.

The goals, and the rows each is judged on:
  * phongrast at most 0.25x of llvmpipe's frame plus sort, Gouraud and Phong,
    exact and seed, at 1 and at 2 threads: every row;
  * at most 60 ns per triangle per thread for the whole render (Gouraud,
    exact): scenes of about one-pixel triangles (no more pixels than triangles);
  * Phong ambient-only at most 0.5x of Phong full lighting, and flat and
    Gouraud ambient-only no slower than Phong ambient-only (within NOISE):
    meshes of 100,000 triangles or more;
  * peak memory, mesh included, at most 200 B x triangles + 32 B x pixels:
    meshes of 1,000,000 triangles or more (the goal names the 8M mesh; on
    small meshes the program's own resident pages, some megabytes, outweigh
    any per-triangle figure, so those rows are shown but not judged).
Python 3 standard library only.
"""
import fileinput

LLVMPIPE_GOAL = 0.25
NS_PER_TRIANGLE_GOAL = 60.0
AMBIENT_GOAL = 0.5
NOISE = 1.05  # "no slower": at most 5% slower, the spread of interleaved medians on a shared machine
LARGE_MESH = 100_000
MEMORY_MESH = 1_000_000


def markdown_rows(paths, first_column):
    """Every row of the Markdown tables in `paths` whose header starts with `first_column`, as dicts."""
    header, rows = None, []
    for line in fileinput.input(paths):
        if not line.startswith("|"):
            header = None
            continue
        cells = [cell.strip() for cell in line.strip().strip("|").split("|")]
        if cells[0] == first_column:
            header = cells
        elif header and not set(cells[0]) <= set("-:") and len(cells) == len(header):
            rows.append(dict(zip(header, cells)))
    return rows


def number(text):
    return float(text.replace(",", "").split()[0])


def verdict(ok):
    return "met" if ok else "**not met**"


def judge(scene, llvmpipe, goals):
    """One summary row (scene, threads): the cells and each goal's (applies, met, worst value)."""
    triangles, threads = number(goals["triangles"]), int(goals["threads"])
    columns, rows = (int(n) for n in goals["image"].split("x"))
    ratios = {}
    for shader in ("gouraud", "phong"):
        row = llvmpipe.get((scene, shader, str(threads)), {})
        for mode in ("exact", "seed"):
            key = f"{mode} / llvmpipe"
            ratios[(shader, mode)] = number(row[key]) if key in row else None
    measured = [r for r in ratios.values() if r is not None]
    gouraud = llvmpipe.get((scene, "gouraud", str(threads)))
    ns = number(gouraud["phongrast exact ms"]) * 1e6 / triangles if gouraud else None
    one_pixel = columns * rows <= triangles
    ambient = number(goals["Phong ambient / full"])
    others = max(number(goals["Gouraud ambient / Phong ambient"]), number(goals["flat ambient / Phong ambient"]))
    large = triangles >= LARGE_MESH
    peak, budget = number(goals["peak B / triangle"]), number(goals["budget B / triangle"])
    checks = {
        "llvmpipe": (bool(measured), bool(measured) and max(measured) <= LLVMPIPE_GOAL, max(measured, default=None)),
        "ns": (one_pixel and ns is not None, ns is not None and ns * threads <= NS_PER_TRIANGLE_GOAL,
               None if ns is None else ns * threads),
        "ambient": (large, ambient <= AMBIENT_GOAL and others <= NOISE, ambient),
        "memory": (triangles >= MEMORY_MESH, peak <= budget, peak),
    }
    fmt = lambda r: "—" if r is None else f"{r:.3f}"
    applies = lambda goal: verdict(checks[goal][1]) if checks[goal][0] else "n/a"
    cells = [scene, f"{int(triangles):,}", goals["image"], str(threads)]
    cells += [fmt(ratios[(s, m)]) for s in ("gouraud", "phong") for m in ("exact", "seed")]
    cells += [applies("llvmpipe"), "—" if ns is None else f"{ns:.0f}", "—" if ns is None else f"{ns * threads:.0f}",
              applies("ns"), f"{ambient:.3f}", goals["Gouraud ambient / Phong ambient"],
              goals["flat ambient / Phong ambient"], applies("ambient"), f"{peak:.0f} / {budget:.0f}",
              goals["peak MiB"], applies("memory")]
    return cells, checks


HEADER = ("| scene | triangles | image | threads | Gouraud exact / llvmpipe | Gouraud seed / llvmpipe "
          "| Phong exact / llvmpipe | Phong seed / llvmpipe | all <= 0.25 | ns / triangle (Gouraud exact) "
          "| x threads | <= 60 | Phong ambient / full | Gouraud ambient / Phong ambient | flat ambient / Phong ambient "
          "| ambient goal | peak B / triangle / budget | peak MiB | memory goal |")


def goal_lines(judged):
    """Each goal over the rows it applies to: met everywhere or not, and its worst row (for memory: the largest mesh)."""
    names = {"llvmpipe": f"at most {LLVMPIPE_GOAL}x of llvmpipe's frame plus sort (largest of the four ratios)",
             "ns": f"at most {NS_PER_TRIANGLE_GOAL:.0f} ns per one-pixel triangle per thread (Gouraud exact, ns x threads)",
             "ambient": f"Phong ambient-only at most {AMBIENT_GOAL}x of full, flat and Gouraud ambient no slower "
                        f"(within {NOISE:.2f}x) on meshes of {LARGE_MESH:,}+ triangles (Phong ambient / full)",
             "memory": f"peak memory, mesh included, at most 200 B/triangle + 32 B/pixel on meshes of "
                       f"{MEMORY_MESH:,}+ triangles (peak B per triangle)"}
    lines = []
    for goal, name in names.items():
        rows = [(scene, triangles, threads, checks[goal]) for scene, triangles, threads, checks in judged
                if checks[goal][0]]
        if not rows:
            lines.append(f"- {name}: no row to judge")
            continue
        failed = sum(1 for row in rows if not row[3][1])
        if goal == "memory":
            scene, _, threads, (_, met, value) = max(rows, key=lambda row: (row[1], row[3][2]))
            where = f"on the largest mesh, {scene} at {threads} thread(s): {value:.0f} B/triangle, {verdict(met)}"
        else:
            scene, _, threads, (_, _, value) = max(rows, key=lambda row: row[3][2])
            where = f"worst: {scene} at {threads} thread(s), {value:.3g}"
        lines.append(f"- {name}: {verdict(not failed)} (met on {len(rows) - failed} of {len(rows)} rows); {where}")
    return lines


def summary_command(args):
    """bench/report.py summary LLVMPIPE_FILE... GOALS_FILE: the goals per scene class."""
    if len(args) < 2:
        print(summary_command.__doc__)
        return 2
    llvmpipe = {(r["scene"], r["shader"], r["threads"]): r for r in markdown_rows(args[:-1], "scene")}
    goals = markdown_rows(args[-1:], "scene")
    classes = []
    for row in goals:
        if row["class"] not in classes:
            classes.append(row["class"])
    judged = []
    for scene_class in classes:
        print(f"### {scene_class}")
        print()
        print(HEADER)
        print("|---|---:|---|---:|" + "---:|" * 4 + "---|---:|---:|---|---:|---:|---:|---|---:|---:|---|")
        for row in (r for r in goals if r["class"] == scene_class):
            cells, checks = judge(row["scene"], llvmpipe, row)
            judged.append((row["scene"], number(row["triangles"]), int(row["threads"]), checks))
            print("| " + " | ".join(cells) + " |")
        print()
    print("Goals (n/a: the goal is not judged on that row):")
    print()
    print("\n".join(goal_lines(judged)))
    return 0
