#!/usr/bin/env python3
"""Merges the per-thread-count tables that bench_llvmpipe prints (one process
per thread count) into one Markdown table sorted by scene, shader, threads.
Reads run.sh's output on stdin or from the files named as arguments."""
import fileinput

rows, scene_order, seen = [], [], set()
for line in fileinput.input():
    if not line.startswith("| ") or line.startswith("| scene"):
        continue
    cells = [cell.strip() for cell in line.strip().strip("|").split("|")]
    if len(cells) != 11:
        continue
    cells[1] = cells[1].replace(",", "")
    key = (cells[0], cells[3], cells[4])
    if key in seen:  # a merged table printed earlier (run.sh's own output) repeats rows
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
