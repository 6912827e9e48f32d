#!/usr/bin/env bash
# Issue 8 in one command: the llvmpipe comparison, the speed steps and the
# scaling benchmark, built from this working tree and run one after another,
# with every table written to one Markdown report.
#
#   bench/run_all.sh             # about 15 minutes on 2 cores
#   bench/run_all.sh --full      # the scaling benchmark's full grid (up to 4M triangles, 4096^2): about 45 minutes
#   bench/run_all.sh --quick     # no 1.3M-triangle scene, quick scaling grid: about 6 minutes
#   BUILD_DIR=/tmp/b REPEAT=9 bench/run_all.sh
#
# 1. llvmpipe against phongrast (bench_llvmpipe, docs/llvmpipe.md): every scene,
#    1 and 2 threads (one process each: llvmpipe reads LP_NUM_THREADS once),
#    both renderers interleaved, medians of REPEAT rounds, ratios, and the
#    image agreement; images and heat maps in $BUILD_DIR/llvmpipe-images.
# 2. The speed steps (bench_speed_once --steps, docs/performance.md): every
#    layer shaded with the baseline kernels, automatic overdraw, AVX2 kernels,
#    round-robin in one process per row; medians and ratios to the first.
# 3. bench_scaling (Google Benchmark): time against triangles and pixels with
#    the log-log slopes, shader x lighting, and the meshes of ../shared/assets
#    (bench/scaling_slopes.py makes the tables).
#
# Needs the packages of cmake/debian-packages.txt (OSMesa for step 1, Google
# Benchmark for step 3) and python3 for merging tables and fitting slopes
# (without it the raw outputs are kept and the script says so).
set -euo pipefail
cd "$(dirname "$0")/.."

scaling=--quick
large=""
while [ $# -gt 0 ]; do
  case "$1" in
    --full) scaling=""; shift ;;
    --quick) large=--no-large; shift ;;
    *) echo "run_all.sh: unknown argument $1 (expected --full or --quick)" >&2; exit 2 ;;
  esac
done
build="${BUILD_DIR:-build/bench-all}"
repeat="${REPEAT:-5}"
report="$build/report.md"

cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DPHONGRAST_WERROR=ON -DPHONGRAST_BUILD_BENCH=ON \
  -DPHONGRAST_BUILD_TESTS=OFF >/dev/null
if ! cmake --build "$build" -j2 --target bench_llvmpipe bench_speed_once bench_scaling >/dev/null; then
  echo "run_all.sh: the benchmarks did not build (OSMesa: libosmesa6-dev; Google Benchmark: libbenchmark-dev)" >&2
  exit 1
fi
have_python=1
command -v python3 >/dev/null || have_python=0

mkdir -p "$build"
exec > >(tee "$report")
echo "# phongrast speed report"
echo
echo "- command: \`bench/run_all.sh $*\` (REPEAT=$repeat)"
echo "- date: $(date -u '+%Y-%m-%d %H:%M UTC')"
echo "- machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ *//')"
echo "- commit: $(git rev-parse --short HEAD 2>/dev/null || echo unknown)$(git diff --quiet HEAD -- src include 2>/dev/null || echo ' (+ uncommitted changes in src/ or include/)')"
echo "- load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
echo

echo "## 1. phongrast against llvmpipe"
echo
one="$build/llvmpipe-1-thread.txt" two="$build/llvmpipe-2-threads.txt"
"$build/bench/llvmpipe/bench_llvmpipe" --threads 1 --repeat "$repeat" $large >"$one"
"$build/bench/llvmpipe/bench_llvmpipe" --threads 2 --repeat "$repeat" $large --images "$build/llvmpipe-images" >"$two"
head -n 1 "$one"
head -n 1 "$two"
echo
if [ "$have_python" = 1 ]; then
  python3 bench/llvmpipe/merge_tables.py "$one" "$two"
else
  echo "(python3 missing: the two tables unmerged)"
  grep '^|' "$one"
  echo
  grep '^|' "$two"
fi
echo
sed -n '/Image agreement/,$p' "$two"
echo

echo "## 2. The speed steps, one process per row"
echo
echo "Medians in ms of $repeat round-robin rounds after one warm-up. A: every layer shaded,"
echo "baseline (SSE2) kernels; B: Overdraw::automatic, baseline kernels; C: automatic, AVX2 kernels"
echo "(when the CPU has AVX2). Samples shaded: A / C."
echo
echo "| scene | shader | mode | threads | A ms | B ms | C ms | B / A | C / A | samples shaded |"
echo "|---|---|---|---:|---:|---:|---:|---:|---:|---|"
scenes="icosphere-9.7k suzanne dolphins_colored spot teapot stanford-bunny armadillo"
[ -z "$large" ] && scenes="$scenes icosphere-1.3M"
for scene in $scenes; do
  for shader in gouraud phong; do
    for mode in exact seed; do
      for threads in 1 2; do
        "$build/bench/bench_speed_once" --scene "$scene" --shader "$shader" --mode "$mode" --threads "$threads" \
          --repeat "$repeat" --steps 2>/dev/null || echo "| $scene | $shader | $mode | $threads | (skipped: mesh not found) |"
      done
    done
  done
done
echo

echo "## 3. Scaling (bench_scaling ${scaling:-full grid})"
echo
"$build/bench/bench_scaling" $scaling --benchmark_out="$build/scaling.json" --benchmark_out_format=json >/dev/null
if [ "$have_python" = 1 ]; then
  python3 bench/scaling_slopes.py "$build/scaling.json"
else
  echo "(python3 missing: the raw results are in $build/scaling.json)"
fi
echo
echo "- load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "- report: $report"
