#!/bin/bash
# Throughput of `phongrast batch` against one `phongrast render` process per
# image, and the time per image beyond the render itself.
#
#   bench/run_batch.sh [PHONGRAST]      (default build/release/apps/phongrast)
#
# 1. 1,000 images: 100 generated torus knots (8,000-12,000 triangles each) x 10
#    turntable views at 256x256, one `batch` process; images per second and
#    (wall time - summed render time) / images, from the shard log.
# 2. The same knots, one `phongrast render KNOT.obj --size 256x256` process per
#    image: measured on the first LOOP_IMAGES (default 60) images, extrapolated
#    to 1,000 (each process does the same kind of work, so its time is linear).
# 3. The default scene at 512x512: the marginal cost of one more image in a
#    batch ((batch of DEFAULT_JOBS, default 60, minus batch of 1) / (DEFAULT_JOBS
#    - 1), so the one-time start is left out), in wall time and in CPU time
#    (user + sys, every thread), against one render of the same scene
#    (`render --repeat`: median wall time; CPU of --repeat DEFAULT_JOBS+1
#    minus --repeat 1, per render).
# Each measurement is repeated REPEATS (default 3) times; medians are reported.
# Output: a Markdown table on stdout. Environment: WORK (a scratch folder,
# default a temporary one), REPEATS, LOOP_IMAGES, DEFAULT_JOBS.
set -eu
cd "$(dirname "$0")/.."
phongrast=$(realpath "${1:-build/release/apps/phongrast}")
repeats=${REPEATS:-3}
loop_images=${LOOP_IMAGES:-60}
default_jobs=${DEFAULT_JOBS:-60}
work=${WORK:-$(mktemp -d /tmp/phongrast-bench-batch-XXXXXX)}
mkdir -p "$work"

now() { date +%s.%N; }
median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
# Sum of "render_seconds" over the records of the logs in folder $1.
render_seconds() { cat "$1"/.phongrast-batch/*.jsonl | grep -o '"render_seconds":[0-9.e+-]*' | cut -d: -f2 |
                   awk '{ s += $1 } END { printf "%.6f", s }'; }

echo "generating 100 meshes in $work ..." >&2
: > "$work/knots.jsonl"
for i in $(seq 0 99); do
  [ -e "$work/knot$i.obj" ] || "$phongrast" generate -q -o "$work/knot$i.obj" --segments $((200 + 2 * i)) --sides 20
  echo "{\"mesh\": \"knot$i.obj\", \"views\": 10, \"size\": \"256x256\"}" >> "$work/knots.jsonl"
done
cp assets/default.json assets/default.obj "$work/"
: > "$work/default.jsonl"
for i in $(seq 1 "$default_jobs"); do
  echo "{\"scene\": \"default.json\", \"output\": \"default-$i.png\"}" >> "$work/default.jsonl"
done
head -n 1 "$work/default.jsonl" > "$work/default-1.jsonl"

# "wall cpu" seconds of a command (cpu: user + sys of the process and its children).
measure() {
  local TIMEFORMAT='%R %U %S'
  { time "$@" > /dev/null 2> /dev/null; } 2>&1 | awk '{ printf "%.6f %.6f\n", $1, $2 + $3 }'
}

# One batch run of manifest $1 into a fresh folder $2: prints "wall render".
batch_run() {
  rm -rf "$2"
  local start end
  start=$(now)
  "$phongrast" batch "$1" -o "$2" --quiet
  end=$(now)
  echo "$(awk -v a="$start" -v b="$end" 'BEGIN { printf "%.6f", b - a }') $(render_seconds "$2")"
}

batch_walls=(); batch_renders=(); loop_walls=(); default_walls=(); default_cpus=(); render_walls=(); render_cpus=()
for run in $(seq "$repeats"); do
  echo "run $run of $repeats: batch of 1,000 ..." >&2
  read -r wall render < <(batch_run "$work/knots.jsonl" "$work/out-batch")
  batch_walls+=("$wall"); batch_renders+=("$render")
  echo "run $run of $repeats: $loop_images render processes ..." >&2
  mkdir -p "$work/out-loop"
  start=$(now)
  for i in $(seq 0 $((loop_images - 1))); do
    "$phongrast" render "$work/knot$((i % 100)).obj" --size 256x256 -q -o "$work/out-loop/$i.png"
  done
  end=$(now)
  loop_walls+=("$(awk -v a="$start" -v b="$end" 'BEGIN { printf "%.6f", b - a }')")
  echo "run $run of $repeats: default scene ..." >&2
  rm -rf "$work/out-d1" "$work/out-dn"
  read -r wall_1 cpu_1 < <(measure "$phongrast" batch "$work/default-1.jsonl" -o "$work/out-d1" --quiet)
  read -r wall_n cpu_n < <(measure "$phongrast" batch "$work/default.jsonl" -o "$work/out-dn" --quiet)
  default_walls+=("$(awk -v a="$wall_1" -v b="$wall_n" -v n="$default_jobs" 'BEGIN { print (b - a) / (n - 1) }')")
  default_cpus+=("$(awk -v a="$cpu_1" -v b="$cpu_n" -v n="$default_jobs" 'BEGIN { print (b - a) / (n - 1) }')")
  read -r _ render_cpu_1 < <(measure "$phongrast" render "$work/default.json" -o "$work/r.png" --repeat 1)
  read -r _ render_cpu_n < <(measure "$phongrast" render "$work/default.json" -o "$work/r.png" --repeat "$default_jobs")
  render_cpus+=("$(awk -v a="$render_cpu_1" -v b="$render_cpu_n" -v n="$default_jobs" 'BEGIN { print (b - a) / (n - 1) }')")
  render_walls+=("$("$phongrast" render "$work/default.json" -o "$work/r.png" --repeat "$default_jobs" |
                   sed -n 's/.*median \([0-9.]*\) ms.*/\1/p' | awk '{ print $1 / 1000 }')")
done

batch_wall=$(printf '%s\n' "${batch_walls[@]}" | median)
batch_render=$(printf '%s\n' "${batch_renders[@]}" | median)
loop_wall=$(printf '%s\n' "${loop_walls[@]}" | median)
default_wall=$(printf '%s\n' "${default_walls[@]}" | median)
default_cpu=$(printf '%s\n' "${default_cpus[@]}" | median)
render_wall=$(printf '%s\n' "${render_walls[@]}" | median)
render_cpu=$(printf '%s\n' "${render_cpus[@]}" | median)

awk -v bw="$batch_wall" -v br="$batch_render" -v lw="$loop_wall" -v li="$loop_images" \
    -v dw="$default_wall" -v dc="$default_cpu" -v rw="$render_wall" -v rc="$render_cpu" \
    -v cores="$(nproc)" -v r="$repeats" 'BEGIN {
  batch_rate = 1000 / bw; loop_rate = li / lw
  printf "| measurement (medians of %d runs, %d cores) | value |\n|---|---|\n", r, cores
  printf "| `batch`, 1,000 images (100 knots x 10 views, 256x256): wall time | %.2f s |\n", bw
  printf "| `batch`: images per second | %.1f |\n", batch_rate
  printf "| `batch`: render time per image (summed in the log) | %.2f ms |\n", 1000 * br / 1000
  printf "| `batch`: time per image beyond the render | %.2f ms |\n", 1000 * (bw - br) / 1000
  printf "| one `render` process per image: %d images, wall time | %.2f s |\n", li, lw
  printf "| one `render` process per image: images per second | %.2f |\n", loop_rate
  printf "| one `render` process per image: 1,000 images, extrapolated | %.0f s |\n", 1000 / loop_rate
  printf "| **throughput, `batch` / one process per image** | **%.1fx** |\n", batch_rate / loop_rate
  printf "| default scene 512x512: one more image in a `batch`, wall time | %.2f ms |\n", 1000 * dw
  printf "| default scene: one render (`render --repeat`, median), wall time | %.2f ms |\n", 1000 * rw
  printf "| **default scene: wall time beyond the render, per image** | **%.2f ms = %.0f%% of the render** |\n", 1000 * (dw - rw), 100 * (dw - rw) / rw
  printf "| default scene: one more image in a `batch`, CPU time (all threads) | %.2f ms |\n", 1000 * dc
  printf "| default scene: one render, CPU time (all threads) | %.2f ms |\n", 1000 * rc
  printf "| **default scene: CPU time beyond the render, per image** | **%.2f ms = %.0f%% of the render** |\n", 1000 * (dc - rc), 100 * (dc - rc) / rc
}'
[ -n "${WORK:-}" ] || rm -rf "$work"
