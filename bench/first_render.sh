#!/usr/bin/env bash
# The first frame of a process against its later ones (issue 26, point 4),
# with glibc's malloc as it comes and with its transparent huge pages
# (GLIBC_TUNABLES=glibc.malloc.hugetlb=1), each in RUNS fresh processes,
# alternating; with a BASELINE module folder, that build's processes too,
# alternating with this one's (only ratios taken in one run mean anything on
# a shared machine).
# Usage: bench/first_render.sh [PYTHONPATH of the built module] [RUNS] [THREADS] [BASELINE PYTHONPATH]
set -euo pipefail
cd "$(dirname "$0")/.."
module="${1:-build/release/python}"
runs="${2:-7}"
threads="${3:-1}"
baseline="${4:-}"
out="$(mktemp)"
trap 'rm -f "$out"' EXIT
for run in $(seq "$runs"); do
  if [ -n "$baseline" ]; then
    echo "before-default $(PYTHONPATH="$baseline" /usr/bin/python3 bench/first_render.py "$threads")" >> "$out"
  fi
  echo "default $(PYTHONPATH="$module" /usr/bin/python3 bench/first_render.py "$threads")" >> "$out"
  if [ -n "$baseline" ]; then
    echo "before-huge-pages $(GLIBC_TUNABLES=glibc.malloc.hugetlb=1 PYTHONPATH="$baseline" /usr/bin/python3 bench/first_render.py "$threads")" >> "$out"
  fi
  echo "huge-pages $(GLIBC_TUNABLES=glibc.malloc.hugetlb=1 PYTHONPATH="$module" /usr/bin/python3 bench/first_render.py "$threads")" >> "$out"
done
/usr/bin/python3 - "$out" "$threads" <<'PY'
import json, statistics, sys
rows = {}
for line in open(sys.argv[1]):
    setting, record = line.split(" ", 1)
    rows.setdefault(setting, []).append(json.loads(record))
load = open("/proc/loadavg").read().split()[:3]
print(f"threads {sys.argv[2]}, {len(rows['default'])} processes each; median ms of the library's render time; "
      f"load average {' '.join(load)} at the end")
print("| build | malloc | first frame | later frames | first / later | peak RSS MiB |")
print("|---|---|---|---|---|---|")
for setting in ("before-default", "default", "before-huge-pages", "huge-pages"):
    if setting not in rows:
        continue
    build = "before" if setting.startswith("before") else "this"
    malloc = setting.replace("before-", "")
    first = statistics.median(r["first"] for r in rows[setting])
    later = statistics.median(r["later"] for r in rows[setting])
    ratio = statistics.median(r["first"] / r["later"] for r in rows[setting])
    peak = statistics.median(r.get("peak_mib", 0.0) for r in rows[setting])
    print(f"| {build} | {malloc} | {first:.1f} | {later:.1f} | {first / later:.2f} (per process {ratio:.2f}) | {peak:.1f} |")
PY
