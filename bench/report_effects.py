"""bench_effects' JSON output as the Markdown tables of docs/performance.md
(`bench/report.py effects`), and the least-squares and unit helpers the other
tables of bench/report.py share.

Reads the median (and cv) aggregates of a run made with
--benchmark_repetitions=N --benchmark_report_aggregates_only=true, and prints:
  * each effect set's median time, specialised kernel against the general one
    (RenderOptions::specialize_effects = false, the baseline in the same run);
  * ambient-only Phong against ambient-only Gouraud, a least-squares line
    through time against lights, the culling speedup.
With --clock=cpu: 1-thread runs only, by the CPU time of the rendering thread
(robust when other processes compete for the cores); default: wall-clock.
Python 3 standard library only.
"""
import json
import statistics
import sys

EFFECTS = ["ambient", "diffuse", "specular", "full", "full-kd0", "full-ks0"]
SHADERS = ["flat", "gouraud", "phong"]
LIGHTS = [0, 1, 2, 4, 8]
FIT_LIGHTS = [1, 2, 4, 8]  # 0 lights is a different effect set (ambient only), kept out of the fit
AMBIENT_TARGET = 1.10


def parse_name(run_name):
    """'effects/mesh=x/shader=phong/.../threads=1/real_time' -> dict of the key=value parts."""
    fields = {}
    for part in run_name.split("/")[1:]:
        if "=" in part:
            key, value = part.split("=", 1)
            fields[key] = value
    return fields


def load(path):
    with open(path, encoding="utf-8") as f:
        data = json.load(f)
    runs = {}
    for b in data["benchmarks"]:
        if b.get("run_type") != "aggregate":
            continue
        fields = parse_name(b["run_name"])
        key = tuple(sorted(fields.items()))
        entry = runs.setdefault(key, {"fields": fields})
        if b["aggregate_name"] == "median":
            entry["ms"] = to_ms(b["real_time"], b["time_unit"])
            entry["cpu_ms"] = to_ms(b["cpu_time"], b["time_unit"])
            entry["label"] = b.get("label", "")
            for counter in ("samples", "drawn", "culled", "diffuse_evals", "specular_evals", "normal_interps"):
                if counter in b:
                    entry[counter] = b[counter]
            entry["repetitions"] = b.get("repetitions")
        elif b["aggregate_name"] == "cv":
            entry["cv"] = b["real_time"]  # a fraction
    return data.get("context", {}), runs


def to_ms(value, unit):
    return value * {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}[unit]


class Runs:
    def __init__(self, runs):
        self.runs = runs

    def get(self, **fields):
        defaults = {"dark": "0", "kernel": "special", "cull": "off", "effect": "full"}
        wanted = dict(defaults)
        wanted.update({k: str(v) for k, v in fields.items()})
        if "lights" in wanted:
            return self.runs.get(tuple(sorted(wanted.items())))
        # The effect and culling tables: a scene file's own lights when the mesh
        # has them (its lights=2 runs belong to the light sweep), else two generated ones.
        for lights in ("scene", "2"):
            wanted["lights"] = lights
            run = self.runs.get(tuple(sorted(wanted.items())))
            if run:
                return run
        return None

    def ms(self, **fields):
        run = self.get(**fields)
        return run["ms"] if run and "ms" in run else None

    def meshes(self):
        seen = []
        for entry in self.runs.values():
            mesh = entry["fields"].get("mesh")
            if mesh not in seen:
                seen.append(mesh)
        return seen

    def threads(self):
        return sorted({int(e["fields"]["threads"]) for e in self.runs.values()})


def fmt(ms):
    return "—" if ms is None else (f"{ms:.2f}" if ms < 100 else f"{ms:.0f}")


def ratio(a, b):
    return "—" if a is None or b is None or b == 0 else f"{a / b:.2f}"


def least_squares(xs, ys):
    """The line y = a + b x nearest the points; returns (a, b), b = nan for one distinct x."""
    n = len(xs)
    mx, my = sum(xs) / n, sum(ys) / n
    sxx = sum((x - mx) ** 2 for x in xs)
    sxy = sum((x - mx) * (y - my) for x, y in zip(xs, ys))
    b = sxy / sxx if sxx > 0 else float("nan")
    return my - b * mx, b


def fit_line(xs, ys):
    """Least squares y = a + b x; returns (a, b, r2, worst relative residual)."""
    a, b = least_squares(xs, ys)
    my = sum(ys) / len(ys)
    ss_tot = sum((y - my) ** 2 for y in ys)
    ss_res = sum((y - (a + b * x)) ** 2 for x, y in zip(xs, ys))
    r2 = 1.0 - ss_res / ss_tot if ss_tot > 0 else 1.0
    worst = max(abs(y - (a + b * x)) / (a + b * x) for x, y in zip(xs, ys))
    return a, b, r2, worst


def mesh_summary(runs, mesh):
    run = runs.get(mesh=mesh, shader="phong", threads=1)
    if not run:  # any run of the mesh without culling
        run = next((e for e in runs.runs.values()
                    if e["fields"].get("mesh") == mesh and e["fields"].get("cull") == "off" and "ms" in e), None)
    if not run:
        return "no runs"
    return f"{int(run.get('drawn', 0)):,} triangles drawn, {int(run.get('samples', 0)):,} pixels shaded"


def effect_table(runs, mesh, out):
    threads = runs.threads()
    if runs.ms(mesh=mesh, shader="phong", effect="ambient", threads=1) is None:
        return
    run = runs.get(mesh=mesh, shader="phong", threads=1)
    lights = "the scene's own lights" if run and run["fields"]["lights"] == "scene" else "2 lights"
    out.append(f"#### {mesh} ({mesh_summary(runs, mesh)}), {lights}\n")
    header = "| effect set | shader |"
    rule = "|---|---|"
    for t in threads:
        header += f" {t} thr: specialised ms | general ms | general ÷ specialised |"
        rule += "---:|---:|---:|"
    out += [header, rule]
    for effect in EFFECTS:
        for shader in SHADERS:
            row = f"| {effect} | {shader} |"
            for t in threads:
                s = runs.ms(mesh=mesh, shader=shader, effect=effect, threads=t)
                g = runs.ms(mesh=mesh, shader=shader, effect=effect, threads=t, kernel="general")
                row += f" {fmt(s)} | {fmt(g)} | {ratio(g, s)} |"
            out.append(row)
    out.append("")


def ambient_target_table(runs, out):
    out.append("| mesh | threads | ambient Phong ms | ambient Gouraud ms | Phong ÷ Gouraud | target ≤ 1.10 "
               "| general-kernel ambient Phong ÷ Gouraud |")
    out.append("|---|---:|---:|---:|---:|---|---:|")
    for mesh in runs.meshes():
        for t in runs.threads():
            p = runs.ms(mesh=mesh, shader="phong", effect="ambient", threads=t)
            g = runs.ms(mesh=mesh, shader="gouraud", effect="ambient", threads=t)
            if p is None or g is None:
                continue
            pg = runs.ms(mesh=mesh, shader="phong", effect="ambient", threads=t, kernel="general")
            gg = runs.ms(mesh=mesh, shader="gouraud", effect="ambient", threads=t, kernel="general")
            verdict = "met" if p / g <= AMBIENT_TARGET else f"missed by {100 * (p / g - AMBIENT_TARGET):.0f} points"
            out.append(f"| {mesh} | {t} | {fmt(p)} | {fmt(g)} | {p / g:.2f} | {verdict} | {ratio(pg, gg)} |")
    out.append("")


def lights_table(runs, mesh, out):
    columns = []
    for t in runs.threads():
        for shader in ("gouraud", "phong"):
            for kernel in ("special", "general"):
                if runs.ms(mesh=mesh, shader=shader, lights=1, kernel=kernel, threads=t) is not None:
                    columns.append((shader, kernel, t))
    if not columns:
        return
    out.append(f"#### {mesh}: full lighting, median ms against the number of lights\n")
    names = {"special": "spec.", "general": "gen."}
    out.append("| lights | " + " | ".join(f"{s} {names[k]} {t} thr" for s, k, t in columns) + " |")
    out.append("|---|" + "---:|" * len(columns))
    for n in LIGHTS:
        cells = [fmt(runs.ms(mesh=mesh, shader=s, lights=n, kernel=k, threads=t)) for s, k, t in columns]
        out.append(f"| {n} | " + " | ".join(cells) + " |")
    cells = [fmt(runs.ms(mesh=mesh, shader=s, lights=2, dark=6, kernel=k, threads=t)) for s, k, t in columns]
    out.append("| 2 + 6 of zero intensity | " + " | ".join(cells) + " |")
    cells = []
    for s, k, t in columns:
        two = runs.ms(mesh=mesh, shader=s, lights=2, kernel=k, threads=t)
        dark = runs.ms(mesh=mesh, shader=s, lights=2, dark=6, kernel=k, threads=t)
        cells.append(ratio(dark, two))
    out.append("| (2 + 6 dark) ÷ 2 | " + " | ".join(cells) + " |")
    fits = {"ms per light (slope)": [], "intercept ms": [], "R²": [], "worst residual": []}
    for s, k, t in columns:
        ys = [runs.ms(mesh=mesh, shader=s, lights=n, kernel=k, threads=t) for n in FIT_LIGHTS]
        if any(y is None for y in ys):
            for v in fits.values():
                v.append("—")
            continue
        a, b, r2, worst = fit_line(FIT_LIGHTS, ys)
        fits["ms per light (slope)"].append(f"{b:.3f}")
        fits["intercept ms"].append(f"{a:.2f}")
        fits["R²"].append(f"{r2:.4f}")
        fits["worst residual"].append(f"{100 * worst:.1f}%")
    for name, cells in fits.items():
        out.append(f"| fit 1–8: {name} | " + " | ".join(cells) + " |")
    out.append("")


def culling_table(runs, out):
    out.append("| mesh | shader | threads | draw all ms | cull ms | speedup | triangles culled | detected |")
    out.append("|---|---|---:|---:|---:|---:|---:|---|")
    for mesh in runs.meshes():
        for shader in ("gouraud", "phong"):
            for t in runs.threads():
                off = runs.ms(mesh=mesh, shader=shader, threads=t)
                on_run = runs.get(mesh=mesh, shader=shader, threads=t, cull="on")
                if off is None or not on_run or "ms" not in on_run:
                    continue
                on = on_run["ms"]
                detected = "yes" if "back faces culled" in on_run.get("label", "") else "no (not closed)"
                out.append(f"| {mesh} | {shader} | {t} | {fmt(off)} | {fmt(on)} | {off / on:.2f} "
                           f"| {int(on_run.get('culled', 0)):,} | {detected} |")
    out.append("")


def context_lines(context, runs):
    cvs = sorted(e["cv"] for e in runs.runs.values() if "cv" in e)
    reps = {e.get("repetitions") for e in runs.runs.values() if e.get("repetitions")}
    lines = [
        f"- run: {context.get('date', '?')} on `{context.get('host_name', '?')}`, "
        f"{context.get('num_cpus', '?')} CPUs at {context.get('mhz_per_cpu', '?')} MHz; "
        f"load average at start {', '.join(f'{x:.2f}' for x in context.get('load_avg', []))}",
        f"- medians of {', '.join(str(r) for r in sorted(reps)) or '?'} repetitions each; "
        f"wall-clock time per render, 512 x 512 pixels (the default scene: its own size), RenderOptions::exact()",
    ]
    # With one render thread all the work runs on the timed thread, so wall
    # time well above its CPU time means the process waited for a core: the
    # machine was busy with something else.
    waits = sorted(e["ms"] / e["cpu_ms"] for e in runs.runs.values()
                   if e["fields"].get("threads") == "1" and e.get("cpu_ms"))
    if waits:
        lines.append(f"- load check: 1-thread runs took {statistics.median(waits):.2f}x their CPU time in wall time "
                     f"(median; worst {waits[-1]:.2f}x); 1.00 means the machine was otherwise idle")
    if cvs:
        lines.append(f"- spread between repetitions (coefficient of variation): median {100 * statistics.median(cvs):.1f}%, "
                     f"worst {100 * cvs[-1]:.1f}%")
    return lines


def use_cpu_clock(raw):
    """1-thread runs only, timed by the CPU time of the thread that rendered."""
    kept = {}
    for key, entry in raw.items():
        if entry["fields"].get("threads") == "1" and "cpu_ms" in entry:
            entry = dict(entry, ms=entry["cpu_ms"])
            kept[key] = entry
    return kept


def effects_command(args):
    """bench/report.py effects [--clock=cpu] RESULTS.json [NOTE ...]: each NOTE becomes a line of the run's description."""
    cpu_clock = "--clock=cpu" in args
    args = [a for a in args if a != "--clock=cpu"]
    if not args:
        sys.stderr.write(effects_command.__doc__ + "\n")
        return 2
    context, raw = load(args[0])
    out = context_lines(context, Runs(raw)) + [f"- {note}" for note in args[1:]]
    if cpu_clock:
        raw = use_cpu_clock(raw)
        out.append("- **times below are CPU time of the rendering thread, 1-thread runs only** (medians): "
                   "unlike wall-clock time they do not count the time the process waited for a core")
    runs = Runs(raw)
    out.append("")
    out.append("### Each effect set, specialised against general kernel\n")
    for mesh in runs.meshes():
        effect_table(runs, mesh, out)
    out.append("### Target: ambient-only Phong within 10% of ambient-only Gouraud (specialised kernels)\n")
    ambient_target_table(runs, out)
    out.append("### Target: cost linear in the number of lights\n")
    for mesh in runs.meshes():
        lights_table(runs, mesh, out)
    out.append("### Back-face culling (full lighting, 2 lights or the scene's own, specialised kernel)\n")
    culling_table(runs, out)
    print("\n".join(out))
    return 0
