#!/usr/bin/env bash
# Checks bench/compare_builds.sh with stand-in bench_speed_once programs (no
# benchmark build needed): the same pictures pass, a picture that differs
# makes it exit 1 and say "no", a case whose run fails is skipped (not a
# failure), and CASES=all is the 120-case matrix.
# Usage: test_compare_builds.sh PATH/TO/bench/compare_builds.sh
set -uo pipefail
script=$1
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
failures=0
fail() { echo "FAILED: $*"; failures=$((failures + 1)); }

# fake NAME PICTURE: a bench_speed_once that writes PICTURE as its --dump and
# prints a median; it fails for the scene "missing", as for a mesh not found.
fake() {
  cat >"$scratch/$1" <<FAKE
#!/bin/sh
dump=""
scene=""
while [ \$# -gt 0 ]; do
  [ "\$1" = --dump ] && dump=\$2
  [ "\$1" = --scene ] && scene=\$2
  shift
done
[ "\$scene" = missing ] && exit 1
printf '%s' "$2" >"\$dump"
echo "\$scene 512x512: median 2.000 ms, min 1.900, max 2.100 (5 renders)"
FAKE
  chmod +x "$scratch/$1"
}
fake old "pixels A"
fake same "pixels A"
fake other "pixels B"

out=$(CASES="suzanne gouraud exact 1
missing gouraud exact 1" bash "$script" "$scratch/old" "$scratch/same" 1)
status=$?
[ "$status" = 0 ] || fail "the same pictures: exit $status, expected 0"
grep -q '| suzanne | gouraud | exact | 1 | 2.00 | 2.00 | 1.000 | yes |' <<<"$out" || fail "the same pictures: no 'yes' row"
grep -q '| missing | gouraud | exact | 1 | (skipped' <<<"$out" || fail "a failed run: no skipped row"
grep -q 'same image in 1 of 1 cases compared (1 skipped)' <<<"$out" || fail "the same pictures: no summary line"

out=$(CASES="suzanne gouraud exact 1" bash "$script" "$scratch/old" "$scratch/other" 1)
status=$?
[ "$status" = 1 ] || fail "a different picture: exit $status, expected 1"
grep -q '| suzanne | gouraud | exact | 1 | 2.00 | 2.00 | 1.000 | no |' <<<"$out" || fail "a different picture: no 'no' row"
grep -q 'same image in 0 of 1 cases compared (0 skipped)' <<<"$out" || fail "a different picture: no summary line"

out=$(CASES=all bash "$script" "$scratch/old" "$scratch/same" 1)
status=$?
[ "$status" = 0 ] || fail "CASES=all: exit $status, expected 0"
rows=$(grep -c '| yes |' <<<"$out")
[ "$rows" = 120 ] || fail "CASES=all: $rows rows, expected 120"
grep -q '| icosphere-8M | phong | seed | 2 |' <<<"$out" || fail "CASES=all: no 8M Phong seed row at 2 threads"

[ "$failures" = 0 ] && echo "compare_builds.sh: all checks passed"
[ "$failures" = 0 ]
