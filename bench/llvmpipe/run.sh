#!/usr/bin/env bash
# The llvmpipe comparison of issue 8, from scratch: configures its own build
# folder with the benchmarks on, builds bench_llvmpipe, and runs it once per
# thread count (llvmpipe reads LP_NUM_THREADS only when its first context is
# created, so each thread count needs its own process). The 2-thread run also
# writes each scene's two renders and a difference heat map.
#
#   bench/llvmpipe/run.sh                 # everything, median of 5 runs
#   bench/llvmpipe/run.sh --repeat 9      # extra arguments go to bench_llvmpipe
#   BUILD_DIR=/tmp/b bench/llvmpipe/run.sh
#
# Needs the Debian packages of cmake/debian-packages.txt (libosmesa6-dev among them).
set -euo pipefail
cd "$(dirname "$0")/../.."

build="${BUILD_DIR:-build/llvmpipe}"
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DPHONGRAST_BUILD_BENCH=ON -DPHONGRAST_WERROR=ON >/dev/null
if ! cmake --build "$build" -j2 --target bench_llvmpipe >/dev/null; then
  echo "run.sh: bench_llvmpipe did not build (is OSMesa installed? Debian: libosmesa6-dev)" >&2
  exit 1
fi
bench="$build/bench/llvmpipe/bench_llvmpipe"

echo "date: $(date -u '+%Y-%m-%d %H:%M UTC')"
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ *//')"
echo "commit: $(git rev-parse --short HEAD 2>/dev/null || echo unknown)$(git diff --quiet HEAD -- src include 2>/dev/null || echo ' (+ uncommitted changes in src/ or include/)')"
echo "load before: $(cut -d' ' -f1-3 /proc/loadavg)"
echo
output="$build/llvmpipe-output.txt"
{
  "$bench" --threads 1 "$@"
  echo
  "$bench" --threads 2 --images "$build/llvmpipe-images" "$@"
} | tee "$output"
echo
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "images: $build/llvmpipe-images"
if command -v python3 >/dev/null; then
  echo
  echo "Both thread counts in one table:"
  python3 bench/llvmpipe/merge_tables.py "$output"
fi
