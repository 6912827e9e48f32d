#!/bin/sh
# Issue 6 benchmark, start to finish: builds bench_effects (Release,
# -DPHONGRAST_BUILD_BENCH=ON, warnings as errors) in its own build folder,
# runs every case with repetitions, and writes the Markdown tables of
# docs/performance.md from the JSON.
#
#   bench/run_effects.sh [extra Google Benchmark flags, e.g. --benchmark_filter=mesh=spot/]
#
# Environment: BUILD_DIR (default build/bench), REPETITIONS (5), MIN_TIME
# (seconds per repetition, 0.1). Output: $BUILD_DIR/effects.json, effects.md
# (wall-clock), effects-cpu.md (1-thread runs by CPU time) and
# effects-callgrind.md (instruction counts; needs valgrind, CALLGRIND=0 skips).
set -eu
cd "$(dirname "$0")/.."
build=${BUILD_DIR:-build/bench}
repetitions=${REPETITIONS:-5}
min_time=${MIN_TIME:-0.1}

cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DPHONGRAST_WERROR=ON -DPHONGRAST_BUILD_BENCH=ON \
  -DPHONGRAST_BUILD_TESTS=OFF -DPHONGRAST_BUILD_APPS=OFF -DPHONGRAST_BUILD_IO=ON -DPHONGRAST_INSTALL=OFF >/dev/null
cmake --build "$build" -j2 --target bench_effects bench_effects_once

# What was measured: the commit, and whether the library sources differed from
# it (REVISION overrides, e.g. for a `git archive` export that has no .git).
if [ -n "${REVISION:-}" ]; then
  revision=$REVISION
else
  revision="commit $(git rev-parse --short HEAD 2>/dev/null || echo unknown)"
  if [ -n "$(git status --porcelain -- src include 2>/dev/null)" ]; then
    revision="$revision, plus uncommitted changes in src/ or include/ (shared working tree)"
  fi
fi
load_before=$(uptime)
start=$(date -u +%Y-%m-%dT%H:%M:%SZ)
"$build/bench/bench_effects" \
  --benchmark_repetitions="$repetitions" --benchmark_report_aggregates_only=true \
  --benchmark_min_time="$min_time" \
  --benchmark_out="$build/effects.json" --benchmark_out_format=json "$@" 2>"$build/effects.stderr"
load_after=$(uptime)

notes=$(sed -n 's/^bench_effects: //p' "$build/effects.stderr")
# One argument per note line.
old_ifs=$IFS
IFS='
'
# shellcheck disable=SC2086
python3 bench/effects_table.py "$build/effects.json" "started $start" "$revision" \
  "\`uptime\` before: \`$load_before\`" "\`uptime\` after: \`$load_after\`" $notes >"$build/effects.md"
# shellcheck disable=SC2086
python3 bench/effects_table.py --clock=cpu "$build/effects.json" "started $start" "$revision" \
  "\`uptime\` before: \`$load_before\`" "\`uptime\` after: \`$load_after\`" $notes >"$build/effects-cpu.md"
IFS=$old_ifs
echo "tables written to $build/effects.md (wall-clock) and $build/effects-cpu.md (1 thread, CPU time)"

# Instruction counts (callgrind) do not depend on the machine's load. CALLGRIND=0 skips them.
if [ "${CALLGRIND:-1}" != 0 ] && command -v valgrind >/dev/null 2>&1; then
  {
    python3 bench/callgrind_effects.py "$build/bench/bench_effects_once"
    echo "- $revision"
  } >"$build/effects-callgrind.md"
  echo "instruction counts written to $build/effects-callgrind.md"
fi
