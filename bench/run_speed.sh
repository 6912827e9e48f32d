#!/bin/sh
# Issue 8 speed measurements, before and after, in one run:
#   bench/run_speed.sh [--baseline COMMIT] [--repeat K] [--no-large] [--callgrind] [--scaling | --scaling-quick]
#
# Builds bench_speed_once from the working tree in build/speed-bench (or
# $BUILD_DIR; tests off there, so use a folder of its own). With
# --baseline, also builds the renderer of COMMIT (exported with `git archive`
# into build/speed-baseline, with today's bench_speed_once driver copied in)
# and times both binaries alternately on the same scenes, so that the machine's
# load affects both alike: each row is the median of K renders after one
# warm-up. --callgrind adds instruction counts of one 1-thread render inside
# Pipeline::run (independent of the load). --scaling runs bench_scaling and
# prints the log-log slopes (bench/scaling_slopes.py).
set -eu
cd "$(dirname "$0")/.."
ROOT=$(pwd)
BASELINE=""
REPEAT=7
LARGE=1
CALLGRIND=0
SCALING=""
while [ $# -gt 0 ]; do
  case "$1" in
    --baseline) BASELINE=$2; shift 2 ;;
    --repeat) REPEAT=$2; shift 2 ;;
    --no-large) LARGE=0; shift ;;
    --callgrind) CALLGRIND=1; shift ;;
    --scaling) SCALING=full; shift ;;
    --scaling-quick) SCALING=quick; shift ;;
    *) echo "run_speed.sh: unknown argument $1" >&2; exit 2 ;;
  esac
done

configure() {  # source dir, build dir
  cmake -S "$1" -B "$2" -DCMAKE_BUILD_TYPE=Release -DPHONGRAST_WERROR=ON -DPHONGRAST_BUILD_BENCH=ON \
    -DPHONGRAST_BUILD_TESTS=OFF >/dev/null
}
BUILD=${BUILD_DIR:-build/speed-bench}
configure "$ROOT" "$BUILD"
cmake --build "$BUILD" --target bench_speed_once bench_scaling -j2 >/dev/null
CURRENT=$BUILD/bench/bench_speed_once

BEFORE=""
if [ -n "$BASELINE" ]; then
  SRC=build/speed-baseline/src
  rm -rf "$SRC"
  mkdir -p "$SRC"
  git archive "$BASELINE" | tar -x -C "$SRC"
  # The meshes are found at <source>/../shared/assets.
  [ -e build/speed-baseline/shared ] || ln -s "$ROOT/../shared" build/speed-baseline/shared
  # Today's driver and its CMake registration on top of the old renderer.
  cp bench/speed_once.cpp bench/bench_scaling.cpp bench/CMakeLists.txt "$SRC/bench/"
  configure "$SRC" build/speed-baseline/build
  cmake --build build/speed-baseline/build --target bench_speed_once -j2 >/dev/null
  BEFORE=build/speed-baseline/build/bench/bench_speed_once
fi

echo "commit $(git rev-parse --short HEAD)$(git diff --quiet HEAD -- src include || echo ' (plus uncommitted changes in src/ or include/)')," \
     "baseline ${BASELINE:-none}; $(nproc) cores; $(date -u '+%Y-%m-%d %H:%M UTC'); load average $(cut -d' ' -f1-3 /proc/loadavg)"
echo
if [ -n "$BEFORE" ]; then
  echo "| scene | shader | mode | threads | before ms | after ms | after / before | peak RSS before / after MiB |"
  echo "|---|---|---|---:|---:|---:|---:|---|"
else
  echo "| scene | shader | mode | threads | ms (median) | peak RSS MiB |"
  echo "|---|---|---|---:|---:|---|"
fi
field() {  # output line, what -> number
  case "$2" in
    median) echo "$1" | sed -n 's/.*median \([0-9.]*\) ms.*/\1/p' ;;
    rss) echo "$1" | sed -n 's/.*peak RSS \([0-9.]*\) MiB.*/\1/p' ;;
  esac
}
SCENES="icosphere-9.7k suzanne spot armadillo"
[ "$LARGE" = 1 ] && SCENES="$SCENES icosphere-1.3M"
for scene in $SCENES; do
  repeat=$REPEAT
  [ "$scene" = icosphere-1.3M ] && repeat=3
  for shader in gouraud phong; do
    for mode in exact seed; do
      for threads in 1 2; do
        args="--scene $scene --shader $shader --mode $mode --threads $threads --repeat $repeat"
        after=$($CURRENT $args)
        if [ -n "$BEFORE" ]; then
          before=$($BEFORE $args)
          b=$(field "$before" median); a=$(field "$after" median)
          echo "| $scene | $shader | $mode | $threads | $b | $a | $(echo "$a $b" | awk '{printf "%.2f", $1 / $2}') | $(field "$before" rss) / $(field "$after" rss) |"
        else
          echo "| $scene | $shader | $mode | $threads | $(field "$after" median) | $(field "$after" rss) |"
        fi
      done
    done
  done
done

if [ "$CALLGRIND" = 1 ]; then
  echo
  echo "Instructions inside Pipeline<float>::run, one render, 1 thread (valgrind --tool=callgrind):"
  echo
  echo "| scene | shader | before | after | after / before |"
  echo "|---|---|---:|---:|---:|"
  count() {  # binary, args...
    bin=$1; shift
    valgrind --tool=callgrind --callgrind-out-file=/dev/null '--toggle-collect=*Pipeline<float>::run*' \
      "$bin" "$@" --repeat 1 --warmup 0 2>&1 | sed -n 's/.*Collected : \([0-9]*\).*/\1/p'
  }
  for scene in icosphere-9.7k suzanne; do
    for shader in gouraud phong; do
      a=$(count "$CURRENT" --scene "$scene" --shader "$shader")
      if [ -n "$BEFORE" ]; then
        b=$(count "$BEFORE" --scene "$scene" --shader "$shader")
        echo "| $scene | $shader | $b | $a | $(echo "$a $b" | awk '{printf "%.2f", $1 / $2}') |"
      else
        echo "| $scene | $shader | - | $a | - |"
      fi
    done
  done
fi

if [ -n "$SCALING" ]; then
  echo
  flag=""
  [ "$SCALING" = quick ] && flag=--quick
  "$BUILD/bench/bench_scaling" $flag --benchmark_out="$BUILD/scaling.json" --benchmark_out_format=json >/dev/null
  python3 bench/scaling_slopes.py "$BUILD/scaling.json"
fi
