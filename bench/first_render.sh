#!/usr/bin/env bash
# The first frame of a process against its later ones (issue 26, point 4),
# with glibc's malloc as it comes and with its transparent huge pages
# (GLIBC_TUNABLES=glibc.malloc.hugetlb=1), each in RUNS fresh processes,
# alternating. The first frame's extra time is the kernel faulting in the
# frame's fresh buffers 4 KiB at a time.
# Usage: bench/first_render.sh [PYTHONPATH of the built module] [RUNS] [THREADS]
set -euo pipefail
cd "$(dirname "$0")/.."
module="${1:-build/release/python}"
runs="${2:-7}"
threads="${3:-1}"
out="$(mktemp)"
trap 'rm -f "$out"' EXIT
for run in $(seq "$runs"); do
  echo "default $(PYTHONPATH="$module" /usr/bin/python3 bench/first_render.py "$threads")" >> "$out"
  echo "huge-pages $(GLIBC_TUNABLES=glibc.malloc.hugetlb=1 PYTHONPATH="$module" /usr/bin/python3 bench/first_render.py "$threads")" >> "$out"
done
/usr/bin/python3 - "$out" "$threads" <<'PY'
import json, statistics, sys
rows = {}
for line in open(sys.argv[1]):
    setting, record = line.split(" ", 1)
    rows.setdefault(setting, []).append(json.loads(record))
print(f"threads {sys.argv[2]}, {len(rows['default'])} processes each; median ms of the library's render time")
print("| malloc | first frame | later frames | first / later |")
print("|---|---|---|---|")
for setting in ("default", "huge-pages"):
    first = statistics.median(r["first"] for r in rows[setting])
    later = statistics.median(r["later"] for r in rows[setting])
    print(f"| {setting} | {first:.1f} | {later:.1f} | {first / later:.2f} |")
PY
