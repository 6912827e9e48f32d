#!/usr/bin/env bash
# Times two builds of bench_speed_once against each other on the same scenes,
# process after process in alternation (old, new, new, old, ...), so that a
# change in the machine's load hits both alike, and prints one Markdown row
# per case: each build's median over the rounds of its per-process medians,
# the ratio new / old, and whether the two images are identical (cmp of
# --dump); it exits 1 if any case's images differ. Used for the measured
# steps in docs/performance.md.
#
#   bench/compare_builds.sh OLD_BIN NEW_BIN [ROUNDS]
#
# OLD_BIN and NEW_BIN are bench_speed_once programs built from two commits
# (e.g. `git worktree add --detach ../old COMMIT`, then in it
# `cmake -S . -B build/bench -DCMAKE_BUILD_TYPE=Release -DPHONGRAST_BUILD_BENCH=ON
# -DPHONGRAST_BUILD_TESTS=OFF -DPHONGRAST_BUILD_APPS=OFF -DPHONGRAST_INSTALL=OFF`
# and `cmake --build build/bench --target bench_speed_once`). ROUNDS: default 5.
# CASES (environment) overrides the cases: lines of "scene shader mode threads
# [lighting]" (lighting as --lighting names it, e.g. ambient; default the scene's).
# CASES=all: every speed scene x flat, Gouraud, Phong x exact, seed x 1, 2
# threads (120 cases; with ROUNDS 1, a check that two commits draw the same
# pictures, e.g. before and after a speed issue, rather than a timing).
set -euo pipefail

[ $# -ge 2 ] || { sed -n '2,22p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 2; }
old_bin=$1
new_bin=$2
rounds=${3:-5}
for bin in "$old_bin" "$new_bin"; do
  [ -x "$bin" ] || { echo "compare_builds.sh: $bin is not an executable" >&2; exit 2; }
done
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

cases=${CASES:-"icosphere-9.7k gouraud exact 1
icosphere-9.7k phong exact 1
armadillo gouraud exact 1
armadillo phong exact 1
icosphere-1.3M gouraud exact 1
icosphere-1.3M gouraud seed 1
icosphere-1.3M phong exact 1
icosphere-1.3M gouraud exact 2
icosphere-1.3M phong exact 2"}

if [ "$cases" = all ]; then
  cases=$(for scene in icosphere-9.7k suzanne dolphins_colored spot teapot stanford-bunny armadillo icosphere-125k \
      icosphere-1.3M icosphere-8M; do
    for shader in flat gouraud phong; do
      for mode in exact seed; do
        for threads in 1 2; do echo "$scene $shader $mode $threads"; done
      done
    done
  done)
fi

# median of the numbers on standard input
median() { sort -g | awk '{ v[NR] = $1 } END { if (NR == 0) { print "nan"; exit } print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

compared=0 differing=0 skipped_cases=0
echo "| scene | shader | mode | threads | old ms | new ms | new / old | same image |"
echo "|---|---|---|---:|---:|---:|---:|---|"
while read -r scene shader mode threads lighting; do
  [ -n "$scene" ] || continue
  args=(--scene "$scene" --shader "$shader" --mode "$mode" --threads "$threads" --repeat 5 --warmup 1)
  if [ -n "$lighting" ]; then
    args+=(--lighting "$lighting")
    shader="$shader ($lighting)"
  fi
  : >"$scratch/old.txt"
  : >"$scratch/new.txt"
  skipped=0
  for ((round = 0; round < rounds; ++round)); do
    # Which goes first alternates too: on some VMs the second of two
    # back-to-back processes runs slower (a copy against itself: 1.03-1.10).
    sides="old new"
    ((round % 2)) && sides="new old"
    for side in $sides; do
      bin=$old_bin
      [ "$side" = new ] && bin=$new_bin
      if ! line=$("$bin" "${args[@]}" --dump "$scratch/$side.raw" 2>/dev/null); then
        skipped=1
        break 2
      fi
      echo "$line" | sed -n 's/.*median \([0-9.]*\) ms.*/\1/p' >>"$scratch/$side.txt"
    done
  done
  if [ "$skipped" = 1 ]; then
    echo "| $scene | $shader | $mode | $threads | (skipped: mesh not found or run failed) | | | |"
    skipped_cases=$((skipped_cases + 1))
    continue
  fi
  old_ms=$(median <"$scratch/old.txt")
  new_ms=$(median <"$scratch/new.txt")
  same=no
  cmp -s "$scratch/old.raw" "$scratch/new.raw" && same=yes
  compared=$((compared + 1))
  [ "$same" = yes ] || differing=$((differing + 1))
  awk -v s="$scene" -v sh="$shader" -v m="$mode" -v t="$threads" -v o="$old_ms" -v n="$new_ms" -v same="$same" \
    'BEGIN { printf "| %s | %s | %s | %s | %.2f | %.2f | %.3f | %s |\n", s, sh, m, t, o, n, n / o, same }'
done <<<"$cases"

echo
echo "same image in $((compared - differing)) of $compared cases compared ($skipped_cases skipped)"
# A picture that changed is a failure to look at, whatever the times say.
[ "$differing" = 0 ]
