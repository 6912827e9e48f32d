#!/usr/bin/env bash
# Builds and runs phongrast's benchmarks, one subcommand per measurement; the
# tables are Markdown, made by bench/report.py, ready for docs/.
#
#   bench/run.sh effects [--quick] [--callgrind] [Google Benchmark flags]
#                                                             docs/performance.md: effect sets, lights, culling
#   bench/run.sh speed [--quick] [--steps] [--callgrind]      docs/performance.md: medians and peak memory per scene
#   bench/run.sh scaling [--quick | --full]                   docs/performance.md: time against triangles and pixels
#   bench/run.sh accuracy [--quick] [phongrast_accuracy flags] docs/accuracy.md (plots into docs/images/)
#   bench/run.sh llvmpipe [--quick] [bench_llvmpipe flags]    docs/llvmpipe.md: times and image agreement
#   bench/run.sh goals [--quick] [--no-huge]                  ambient-only / full lighting, peak memory per scene
#   bench/run.sh stages [--quick]                             where the time goes in the goals' usual misses
#   bench/run.sh all [--quick] [--no-huge]                    the goals per scene class (a summary table each),
#                                                             each mesh in every order of ORDERS, then llvmpipe,
#                                                             goals, speed --steps, scaling and where the time
#                                                             goes in the goals' usual misses (bench/run_all.sh)
#
# --quick runs a small subset of each, in seconds to a few minutes, to check
# that everything works; its numbers are not for the docs. Without it the
# 8M-triangle mesh at 2048x2048 is included (--no-huge leaves it out).
# Environment: BUILD_DIR (default build/bench-release), REPEAT (timed rounds, default 5),
# ORDERS (for all: the meshes' orders, default "generator spatial shuffled";
# bench/mesh_orders.hpp; llvmpipe and goals take --order ORDER themselves).
# Needs the packages of cmake/debian-packages.txt (Google Benchmark; OSMesa for
# llvmpipe) and Debian's /usr/bin/python3; --callgrind also needs valgrind
# (apt-get install valgrind: a measuring tool, not in the package list).
set -euo pipefail
cd "$(dirname "$0")/.."

build="${BUILD_DIR:-build/bench-release}"
repeat="${REPEAT:-5}"
python=/usr/bin/python3
[ -x "$python" ] || python=python3

usage() {
  sed -n '2,26p' "$0" | sed 's/^# \{0,1\}//' >&2
  exit 2
}

# need_valgrind: --callgrind without valgrind is an error, not an empty table.
need_valgrind() {
  command -v valgrind >/dev/null || { echo "run.sh: --callgrind needs valgrind (apt-get install valgrind)" >&2; exit 1; }
}

# build TARGET...: configures once (Release, benchmarks on, warnings as errors) and builds only these targets.
build() {
  if [ ! -f "$build/CMakeCache.txt" ]; then
    cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DPHONGRAST_WERROR=ON -DPHONGRAST_BUILD_BENCH=ON \
      -DPHONGRAST_BUILD_TESTS=OFF -DPHONGRAST_BUILD_APPS=OFF -DPHONGRAST_INSTALL=OFF >/dev/null
  fi
  if ! cmake --build "$build" -j2 --target "$@" >"$build/build.log" 2>&1; then
    tail -n 30 "$build/build.log" >&2
    echo "run.sh: building $* failed (Google Benchmark: libbenchmark-dev; OSMesa: libosmesa6-dev)" >&2
    exit 1
  fi
}

# What was measured, where and when.
header() {
  echo "- command: \`bench/run.sh $*\` (REPEAT=$repeat)"
  echo "- date: $(date -u '+%Y-%m-%d %H:%M UTC'); machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ *//')"
  echo "- commit: $(git rev-parse --short HEAD 2>/dev/null || echo unknown)$(git diff --quiet HEAD -- src include 2>/dev/null || echo ' (+ uncommitted changes in src/ or include/)')"
  echo "- load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
  echo
}

effects() {
  local given="$*" repetitions=5 min_time=0.1 callgrind=0 flags=()
  while [ $# -gt 0 ]; do
    case "$1" in
      --quick) repetitions=2 min_time=0.01 flags+=(--benchmark_filter='mesh=icosphere-1k/.*/threads=1') ;;
      --callgrind) need_valgrind; callgrind=1 ;;
      *) flags+=("$1") ;;
    esac
    shift
  done
  build bench_effects bench_effects_once
  header effects "$given"
  local json="$build/effects.json"
  "$build/bench/bench_effects" --benchmark_repetitions="$repetitions" --benchmark_report_aggregates_only=true \
    --benchmark_min_time="$min_time" --benchmark_out="$json" --benchmark_out_format=json "${flags[@]}" \
    2>"$build/effects.stderr" >/dev/null
  local notes=()
  mapfile -t notes < <(sed -n 's/^bench_effects: //p' "$build/effects.stderr")
  "$python" bench/report.py effects "$json" "${notes[@]}"
  echo
  echo "By CPU time of the rendering thread (1-thread runs):"
  echo
  "$python" bench/report.py effects --clock=cpu "$json" "${notes[@]}"
  if [ "$callgrind" = 1 ]; then
    echo
    "$python" bench/report.py callgrind "$build/bench/bench_effects_once"
  fi
}

# One bench_speed_once line -> "median | RSS".
speed_fields() { sed -n 's/.*median \([0-9.]*\) ms.*peak RSS \([0-9.]*\) MiB.*/\1 | \2/p'; }

speed() {
  local scenes="icosphere-9.7k suzanne spot armadillo icosphere-125k icosphere-1.3M" steps=0 callgrind=0
  while [ $# -gt 0 ]; do
    case "$1" in
      --quick) scenes="icosphere-9.7k spot"; repeat=3 ;;
      --steps) steps=1 ;;
      --callgrind) need_valgrind; callgrind=1 ;;
      *) echo "run.sh speed: unknown argument $1" >&2; exit 2 ;;
    esac
    shift
  done
  build bench_speed_once
  local bin="$build/bench/bench_speed_once"
  if [ "$steps" = 1 ]; then
    echo "Medians in ms of $repeat interleaved rounds after one warm-up. A: every layer shaded, baseline (SSE2)"
    echo "kernels; B: Overdraw::automatic, baseline kernels; C: automatic, AVX2 kernels (when the CPU has AVX2)."
    echo
    echo "| scene | shader | mode | threads | A ms | B ms | C ms | B / A | C / A | samples shaded A / C |"
    echo "|---|---|---|---:|---:|---:|---:|---:|---:|---|"
  else
    echo "| scene | shader | mode | threads | ms (median of $repeat) | peak RSS MiB |"
    echo "|---|---|---|---:|---:|---:|"
  fi
  for scene in $scenes; do
    local k=$repeat
    [ "$scene" = icosphere-1.3M ] && [ "$steps" = 0 ] && k=3
    for shader in gouraud phong; do
      for mode in exact seed; do
        for threads in 1 2; do
          local args=(--scene "$scene" --shader "$shader" --mode "$mode" --threads "$threads" --repeat "$k")
          if [ "$steps" = 1 ]; then
            "$bin" "${args[@]}" --steps 2>/dev/null || echo "| $scene | $shader | $mode | $threads | (skipped: mesh not found) |"
          elif line=$("$bin" "${args[@]}" 2>/dev/null); then
            echo "| $scene | $shader | $mode | $threads | $(echo "$line" | speed_fields) |"
          else
            echo "| $scene | $shader | $mode | $threads | (skipped: mesh not found) | |"
          fi
        done
      done
    done
  done
  if [ "$callgrind" = 1 ]; then
    echo
    echo "Millions of instructions inside the render pipeline, one 1-thread render (valgrind --tool=callgrind):"
    echo
    echo "| scene | shader | Mi |"
    echo "|---|---|---:|"
    for scene in icosphere-9.7k suzanne; do
      for shader in gouraud phong; do
        local n
        n=$("$python" bench/report.py instructions "$bin" --scene "$scene" --shader "$shader" --repeat 1 --warmup 0)
        echo "| $scene | $shader | $(awk -v n="$n" 'BEGIN { printf "%.2f", n / 1e6 }') |"
      done
    done
  fi
}

scaling() {
  local grid=--quick
  case "${1:-}" in
    --full) grid="" ;;
    --quick | "") ;;
    *) echo "run.sh scaling: unknown argument $1 (expected --quick or --full)" >&2; exit 2 ;;
  esac
  build bench_scaling
  "$build/bench/bench_scaling" $grid --benchmark_out="$build/scaling.json" --benchmark_out_format=json >/dev/null
  "$python" bench/report.py scaling "$build/scaling.json"
}

accuracy() {
  local given="$*" args=(--images docs/images)
  if [ "${1:-}" = --quick ]; then
    shift
    args=(--images "$build/accuracy-report" --scenes sphere,overlap --runs 1)
  fi
  build phongrast_accuracy
  header accuracy "$given"
  "$build/bench/accuracy/phongrast_accuracy" --out "$build/accuracy-report" "${args[@]}" "$@"
  echo "- load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
  echo "- tables: $build/accuracy-report/accuracy_tables.md; plots and heat maps: ${args[1]}"
}

# llvmpipe reads LP_NUM_THREADS only when its first context is created, so each thread count is its own process.
llvmpipe() {
  local args=(--repeat "$repeat") order=generator
  if [ "${1:-}" = --quick ]; then
    shift
    args=(--repeat 1 --seconds 0 --no-large --no-assets --no-huge)
  fi
  # --order ORDER (bench/mesh_orders.hpp): each order's measurements in files of their own.
  local rest=()
  while [ $# -gt 0 ]; do
    case "$1" in
      --order) order="$2"; shift ;;
      *) rest+=("$1") ;;
    esac
    shift
  done
  build bench_llvmpipe
  local bin="$build/bench/llvmpipe/bench_llvmpipe" suffix=""
  [ "$order" = generator ] || suffix="-$order"
  local one="$build/llvmpipe-1-thread$suffix.txt" two="$build/llvmpipe-2-threads$suffix.txt"
  "$bin" --threads 1 --order "$order" "${args[@]}" "${rest[@]}" >"$one"
  "$bin" --threads 2 --order "$order" --images "$build/llvmpipe-images$suffix" "${args[@]}" "${rest[@]}" >"$two"
  head -n 1 "$one"
  head -n 1 "$two"
  echo
  "$python" bench/report.py llvmpipe "$one" "$two"
  echo
  sed -n '/Image agreement/,$p' "$two"
  echo
  echo "Renders and difference heat maps: $build/llvmpipe-images$suffix"
}

# bench_goals, one process per scene (phongrast alone: llvmpipe's memory must not count);
# at least REPEAT rounds, more for small scenes (to fill 2 s), at most 3 for the
# 8M-triangle mesh, whose frames take seconds.
goals() {
  local quick=0 list=() order=()
  while [ $# -gt 0 ]; do
    case "$1" in
      --quick) quick=1; list+=(--no-assets --no-large --no-huge) ;;
      --no-huge) list+=(--no-huge) ;;
      --order) order=(--order "$2"); shift ;;
      *) echo "run.sh goals: unknown argument $1 (expected --quick, --no-huge or --order ORDER)" >&2; exit 2 ;;
    esac
    shift
  done
  build bench_goals
  local bin="$build/bench/bench_goals" first=--header k seconds=2 scenes
  scenes=$("$bin" --list "${list[@]}")
  for scene in $scenes; do
    k=$repeat
    [ "$quick" = 1 ] && k=3 seconds=0
    [ "$scene" = icosphere-8M ] && [ "$k" -gt 3 ] && k=3
    "$bin" --scene "$scene" --repeat "$k" --seconds "$seconds" "${order[@]}" $first
    first=""
  done
}

# Where the time goes in the cases furthest from a goal (docs/performance.md,
# "What stands in the way"): each render stage's median (bench_speed_once
# --stages), one process per case, and the shuffled mesh's stages against the
# spatial one's (bench_mesh_order). The cases are the summary's usual misses,
# fixed so that runs compare: the 512² scenes' Gouraud (spot), the seed's
# Gouraud at 1 thread on 70k+ triangles (armadillo), ambient against full
# lighting on 125k, and the 1.3M sphere's ns per triangle (not with --quick).
where_time_goes() {
  local quick=$1 passes
  build bench_speed_once bench_mesh_order
  local bin="$build/bench/bench_speed_once"
  local cases="llvmpipe|spot|gouraud|exact|1|full|200
llvmpipe|spot|gouraud|exact|2|full|200
llvmpipe|armadillo|gouraud|seed|1|full|30
ambient|icosphere-125k|phong|exact|1|ambient|20
ambient|icosphere-125k|phong|exact|1|full|20
ns per triangle|icosphere-1.3M|gouraud|exact|1|full|9"
  echo "| goal | case | frame | stages: median ms per pass |"
  echo "|---|---|---|---|"
  while IFS='|' read -r goal scene shader mode threads lighting passes; do
    [ "$quick" = --quick ] && [ "$scene" = icosphere-1.3M ] && continue
    [ "$quick" = --quick ] && passes=5
    local out stages frame
    if ! out=$("$bin" --scene "$scene" --shader "$shader" --mode "$mode" --threads "$threads" --lighting "$lighting" \
        --repeat "$passes" --stages 2>/dev/null); then
      echo "| $goal | $scene $shader $mode $lighting, $threads thread(s) | (skipped: mesh not found or run failed) | |"
      continue
    fi
    stages=$(echo "$out" | sed -n 's/^stages, median ms per pass over [0-9]* passes: //p' | sed 's/ | /; /g')
    frame=$(echo "$out" | sed -n 's/.*: median \([0-9.]*\) ms.*/\1 ms/p')
    echo "| $goal | $scene $shader $mode $lighting, $threads thread(s) | $frame | $stages |"
  done <<<"$cases"
  echo
  if [ "$quick" != --quick ]; then
    echo "The shuffled mesh against the spatial one (goal: within 1.25x), orders interleaved in one process:"
    echo
    "$build/bench/bench_mesh_order" --scene icosphere-1.3M --threads 1 --renderer-only --repeat 9 --cpu-time --stages \
      --orders spatial shuffled
  fi
}

# Every measurement into its own file first, then the report: the summary
# per scene class (bench/report.py summary), then the detailed tables.
all() {
  local quick="" huge=""
  while [ $# -gt 0 ]; do
    case "$1" in
      --quick) quick=--quick ;;
      --no-huge) huge=--no-huge ;;
      *) echo "run.sh all: unknown argument $1 (expected --quick or --no-huge)" >&2; exit 2 ;;
    esac
    shift
  done
  [ -n "$quick" ] && huge=""  # --quick leaves the 8M mesh out anyway
  mkdir -p "$build"
  local part="$build/report-part" loads=()
  header all $quick $huge >"$part-header.md"
  # The load average as each part starts: on a shared machine other work shifts
  # times, and not all cases alike (Phong full slows more than ambient-only).
  loads+=("$(cut -d' ' -f1-3 /proc/loadavg)")
  local orders=(${ORDERS:-generator spatial shuffled}) order llvmpipe_files=()
  : >"$part-llvmpipe.md"
  : >"$part-goals.md"
  for order in "${orders[@]}"; do
    echo "run.sh all: 1/5 phongrast against llvmpipe, meshes in the $order order" >&2
    { echo "### Meshes in the $order order"; echo; llvmpipe $quick $huge --order "$order"; echo; } >>"$part-llvmpipe.md"
    local suffix=""
    [ "$order" = generator ] || suffix="-$order"
    llvmpipe_files+=("$build/llvmpipe-1-thread$suffix.txt" "$build/llvmpipe-2-threads$suffix.txt")
  done
  loads+=("$(cut -d' ' -f1-3 /proc/loadavg)")
  for order in "${orders[@]}"; do
    echo "run.sh all: 2/5 ambient-only against full lighting, peak memory, meshes in the $order order" >&2
    goals $quick $huge --order "$order" >>"$part-goals.md"
    echo >>"$part-goals.md"
  done
  loads+=("$(cut -d' ' -f1-3 /proc/loadavg)")
  echo "run.sh all: 3/5 speed steps" >&2
  speed --steps $quick >"$part-steps.md"
  loads+=("$(cut -d' ' -f1-3 /proc/loadavg)")
  echo "run.sh all: 4/5 scaling" >&2
  scaling --quick >"$part-scaling.md"
  loads+=("$(cut -d' ' -f1-3 /proc/loadavg)")
  echo "run.sh all: 5/5 where the time goes" >&2
  where_time_goes "$quick" >"$part-stages.md"
  {
    echo "# phongrast speed report"
    echo
    cat "$part-header.md"
    echo "## Summary: the goals per scene class"
    echo
    echo "Ratios: phongrast's whole render over llvmpipe's frame plus its sort (section 1); ns per triangle:"
    echo "phongrast Gouraud exact (section 1) over the mesh's triangles, and times the threads; ambient and"
    echo "memory: bench_goals, phongrast alone (section 2); where the time goes in the usual misses: section 5."
    echo "Load average as sections 1-5 started: ${loads[0]}; ${loads[1]}; ${loads[2]}; ${loads[3]}; ${loads[4]}."
    echo
    echo "Every scene in each mesh order of ORDERS (${orders[*]}; bench/mesh_orders.hpp): rows named \"(spatial)\""
    echo "or \"(shuffled)\" are the same mesh and picture, its vertices and faces in that order."
    echo
    "$python" bench/report.py summary "${llvmpipe_files[@]}" "$part-goals.md"
    echo
    echo "## 1. phongrast against llvmpipe"
    echo
    cat "$part-llvmpipe.md"
    echo
    echo "## 2. Ambient-only against full lighting, and peak memory (phongrast alone)"
    echo
    cat "$part-goals.md"
    echo
    echo "## 3. The speed steps, one process per row"
    echo
    cat "$part-steps.md"
    echo
    echo "## 4. Scaling"
    echo
    cat "$part-scaling.md"
    echo
    echo "## 5. Where the time goes (the goals' usual misses)"
    echo
    cat "$part-stages.md"
    echo
    echo "- load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
  } | tee "$build/report.md"
  echo "report: $build/report.md" >&2
}

[ $# -ge 1 ] || usage
command=$1
shift
case "$command" in
  effects | speed | scaling | accuracy | llvmpipe | goals | all) "$command" "$@" ;;
  stages)
    if [ $# -gt 1 ] || { [ $# -eq 1 ] && [ "$1" != --quick ]; }; then
      echo "run.sh stages: expected --quick or nothing" >&2
      exit 2
    fi
    where_time_goes "${1:-}" ;;
  *) usage ;;
esac
