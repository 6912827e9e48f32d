#!/usr/bin/env bash
# What the extra outputs (RenderOptions::aovs) and the progress machinery cost,
# in instructions counted by callgrind (repeatable whatever the machine's load):
#   - a render that asks for nothing, built from this tree, against the same
#     render built from an earlier revision (BASELINE, a bench_effects_once
#     binary built from that revision, e.g. in its own worktree);
#   - the same render asking for each plane, and for all of them.
# Usage: bench/extra_outputs_cost.sh BASELINE_BENCH_EFFECTS_ONCE [NEW_BENCH_EFFECTS_ONCE]
# NEW defaults to build/bench-release/bench/bench_effects_once (bench/run.sh builds it).
# Needs valgrind (apt-get install valgrind). Prints a Markdown table for docs/performance.md.
set -euo pipefail
cd "$(dirname "$0")/.."
baseline="${1:?usage: bench/extra_outputs_cost.sh BASELINE_BENCH_EFFECTS_ONCE [NEW_BENCH_EFFECTS_ONCE]}"
new="${2:-build/bench-release/bench/bench_effects_once}"
command -v valgrind >/dev/null || { echo "extra_outputs_cost.sh: needs valgrind (apt-get install valgrind)" >&2; exit 1; }

# instructions BINARY ARGS...: instructions executed inside the render (pipeline passes and resolve).
instructions() {
  local out
  out="$(mktemp)"
  valgrind --tool=callgrind --callgrind-out-file="$out" --toggle-collect='*render_and_resolve*' "$@" 2>&1 |
    awk '/Collected/ {print $NF}'
  rm -f "$out"
}

echo "| scene (81,920 triangles, 512², 1 thread) | baseline | this tree | ratio | + depth | + normal | + id | + alpha | + all |"
echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|"
for case in "phong full" "gouraud full" "flat full" "phong ambient" "gouraud ambient"; do
  read -r shader lighting <<<"$case"
  args=(--levels 6 --shader "$shader" --lighting "$lighting")
  old=$(instructions "$baseline" "${args[@]}")
  now=$(instructions "$new" "${args[@]}")
  row="| $shader, $lighting | $old | $now | $(awk -v a="$now" -v b="$old" 'BEGIN {printf "%.4f", a / b}')"
  for planes in depth normal id alpha all; do
    with=$(instructions "$new" "${args[@]}" --aovs "$planes")
    row="$row | $(awk -v a="$with" -v b="$now" 'BEGIN {printf "%.3fx", a / b}')"
  done
  echo "$row |"
done
