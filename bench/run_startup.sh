#!/bin/bash
# Start-up, PNG encoding and batch throughput against the previous binary
# (issue 26; docs/startup.md quotes the output).
#
#   bench/run_startup.sh BASELINE_PHONGRAST [BASELINE_PYTHON_DIR]
#
# BASELINE_PHONGRAST: the `phongrast` built from the commit before this change
# (for instance `git worktree add /tmp/base <commit>` and build its
# phongrast_cli target with the release preset); BASELINE_PYTHON_DIR: the
# folder holding that build's phongrast*.so Python module (optional).
# This build: build/release (phongrast_cli, phongrast_python, and
# bench_png_encode with -DPHONGRAST_BUILD_BENCH=ON). Needs hyperfine.
#
# 1. Whole processes (hyperfine, medians): `phongrast --version`, a 256x256
#    render of a 10k-triangle mesh to PNG, `phongrast thumbnail` at 256, and
#    `python3 -c "import numpy, phongrast"` minus `import numpy`.
# 2. PNG encoding: bench_png_encode (interleaved medians, OpenImageIO's
#    writer as the baseline) on a 512x512 and a 1024x768 render.
# 3. `batch`: a 1,000-job manifest of 256x256 thumbnails (100 knots of about
#    10k triangles, each named 10 times, no two neighbours alike), images per
#    second, this binary and the baseline alternately (REPEATS, default 3);
#    and the time per image outside the render at 512x512 on a 100k-triangle
#    mesh (40 turntable views: (wall of 40 - wall of 1) / 39 - the log's
#    render time per image).
# Output: Markdown tables on stdout. WORK: scratch folder (default a temporary one).
# SECTIONS: which of "startup png batch" to run (default all three), e.g.
# SECTIONS=batch for the batch part alone (it then also reports CPU time).
set -eu
cd "$(dirname "$0")/.."
baseline=$(realpath "$1")
baseline_python=${2:+$(realpath "$2")}
phongrast=$(realpath build/release/apps/phongrast)
python_dir=$(realpath build/release/python)
bench_png=build/release/bench/bench_png_encode
# The interpreter the module was built for (src/python/CMakeLists.txt chose it).
python=$(sed -n 's/^Python3_EXECUTABLE:FILEPATH=//p' build/release/CMakeCache.txt)
python=${python:-/usr/bin/python3}
repeats=${REPEATS:-3}
work=${WORK:-$(mktemp -d /tmp/phongrast-bench-startup-XXXXXX)}
mkdir -p "$work"
median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
now() { date +%s.%N; }

echo "meshes ..." >&2
"$phongrast" generate -q -o "$work/knot10k.obj" --segments 250 --sides 20
"$phongrast" generate -q -o "$work/knot100k.obj" --segments 2500 --sides 20
for i in $(seq 0 99); do
  [ -e "$work/knot$i.obj" ] || "$phongrast" generate -q -o "$work/knot$i.obj" --segments $((200 + 2 * i)) --sides 20
done

# hyperfine median wall time in ms of each command, one per line; cpu_ms: the
# mean CPU time (user + system) of each, less disturbed by a busy machine.
hyper() {
  hyperfine -N --warmup 3 --runs "${RUNS:-40}" --export-json "$work/h.json" "$@" > /dev/null 2>&1
  python3 -c "import json; [print('%.2f' % (1e3 * r['median'])) for r in json.load(open('$work/h.json'))['results']]"
  python3 -c "import json; print(' '.join('%.2f' % (1e3 * (r['user'] + r['system'])) for r in json.load(open('$work/h.json'))['results']))" > "$work/cpu.txt"
  python3 -c "import json; print(' '.join('%.2f' % (1e3 * r['min']) for r in json.load(open('$work/h.json'))['results']))" > "$work/min.txt"
}

sections=" ${SECTIONS:-startup png batch} "
if [[ $sections == *" startup "* ]]; then
echo "start-up ..." >&2
cd "$work"
hyper "$baseline --version" "$phongrast --version" \
  "$baseline render knot10k.obj --size 256x256 -q -o base.png" "$phongrast render knot10k.obj --size 256x256 -q -o new.png" \
  "$phongrast thumbnail knot10k.obj thumb.png --size 256" > "$work/wall.txt"
mapfile -t t < "$work/wall.txt"
read -r -a tc < "$work/cpu.txt"
read -r -a tm < "$work/min.txt"
PYTHONPATH=$python_dir hyper "$python -c 'import numpy'" "$python -c 'import numpy, phongrast'" > "$work/wall.txt"
mapfile -t p < "$work/wall.txt"
read -r -a pc < "$work/cpu.txt"
read -r -a pm < "$work/min.txt"
if [ -n "$baseline_python" ]; then
  PYTHONPATH=$baseline_python hyper "$python -c 'import numpy'" "$python -c 'import numpy, phongrast'" > "$work/wall.txt"
  mapfile -t q < "$work/wall.txt"
  read -r -a qc < "$work/cpu.txt"
  read -r -a qm < "$work/min.txt"
else
  q=(0 0); qc=(0 0); qm=(0 0)
fi
cd - > /dev/null
echo "| process (wall median / wall min / CPU user+sys mean, ${RUNS:-40} runs; $(nproc) cores, load $(cut -d' ' -f1 /proc/loadavg)) | before | after | goal (wall) |"
echo "|---|---|---|---|"
echo "| \`phongrast --version\` | ${t[0]} / ${tm[0]} / ${tc[0]} ms | ${t[1]} / ${tm[1]} / ${tc[1]} ms | <= 15 ms |"
echo "| \`phongrast render knot10k.obj --size 256x256 -o t.png\` (10k triangles) | ${t[2]} / ${tm[2]} / ${tc[2]} ms | ${t[3]} / ${tm[3]} / ${tc[3]} ms | <= 30 ms |"
echo "| \`phongrast thumbnail knot10k.obj t.png --size 256\` | (no such command) | ${t[4]} / ${tm[4]} / ${tc[4]} ms | |"
awk -v a="${q[0]}" -v b="${q[1]}" -v c="${p[0]}" -v d="${p[1]}" -v ac="${qc[0]}" -v bc="${qc[1]}" -v cc="${pc[0]}" -v dc="${pc[1]}" \
    -v am="${qm[0]}" -v bm="${qm[1]}" -v cm="${pm[0]}" -v dm="${pm[1]}" 'BEGIN {
  printf "| `import phongrast` on top of `import numpy` (difference of the two) | %s | %.2f / %.2f / %.2f ms | <= 20 ms |\n",
         (b > 0 ? sprintf("%.2f / %.2f / %.2f ms", b - a, bm - am, bc - ac) : "not measured"), d - c, dm - cm, dc - cc }'
echo
fi

if [[ $sections == *" png "* ]]; then
echo "PNG encoding ..." >&2
"$phongrast" render assets/default.json --size 512x512 -q -o "$work/default512.png"
"$phongrast" render "$work/knot10k.obj" --size 1024x768 -q -o "$work/knot1024x768.png" \
  --aov-files depth16,id --depth-scale 0.0004
"$phongrast" render assets/default.json --size 1024x768 -q -o "$work/default1024x768.png" \
  --aov-files depth16,id --depth-scale 0.0004
# The 16-bit images a dataset writes (docs/datasets.md): depth in steps of 0.4 mm, triangle ids.
"$bench_png" --rounds "${PNG_ROUNDS:-15}" "$work/default512.png" "$work/knot1024x768.png" \
  "$work/knot1024x768.depth.png" "$work/knot1024x768.id.png" "$work/default1024x768.depth.png" "$work/default1024x768.id.png"
echo
fi

[[ $sections == *" batch "* ]] || { [ -n "${WORK:-}" ] || rm -rf "$work"; exit 0; }
echo "batch ..." >&2
: > "$work/thumbs.jsonl"
for j in $(seq 0 999); do
  echo "{\"mesh\": \"knot$((j % 100)).obj\", \"size\": \"256x256\", \"output\": \"$j.png\"}" >> "$work/thumbs.jsonl"
done
echo "{\"mesh\": \"knot100k.obj\", \"size\": \"512x512\", \"views\": 40}" > "$work/big40.jsonl"
echo "{\"mesh\": \"knot100k.obj\", \"size\": \"512x512\"}" > "$work/big1.jsonl"
render_seconds() { cat "$1"/.phongrast-batch/*.jsonl | grep -o '"render_seconds":[0-9.e+-]*' | cut -d: -f2 |
                   awk '{ s += $1 } END { printf "%.6f", s }'; }
timed() { local s e; s=$(now); "$@" > /dev/null 2>&1 || true; e=$(now); awk -v a="$s" -v b="$e" 'BEGIN { printf "%.6f", b - a }'; }
# Wall seconds on stdout like timed; the CPU seconds (user + sys of the process
# and its workers, bash's `time`) appended to $work/cpu-seconds.
timed_cpu() {
  local TIMEFORMAT='%R %U %S' line
  line=$( { time "$@" > /dev/null 2>&1 || true; } 2>&1 )
  set -- $line
  awk -v u="$2" -v s="$3" 'BEGIN { printf "%.6f\n", u + s }' >> "$work/cpu-seconds"
  printf '%s' "$1"
}
# Every run writes into folders of its own, and they are deleted only after
# the last run. Deleting a run's 2,000 images just before the next run made
# each new file slower to create, for either binary: on a file system
# without a journal (this machine's /tmp is ext4 without one), ext4 skips
# the inodes deleted in the last minute when it picks one for a new file
# (fs/ext4/ialloc.c, recently_deleted), about 0.4 ms of system time per
# image here. (So a run started within a minute or so of deleting many files
# on the same file system still pays some of it.)
outputs="$work/batch-outputs"
rm -rf "$outputs"
mkdir -p "$outputs"
base_rates=(); new_rates=(); outside=(); renders=(); base_cpu=(); new_cpu=()
for run in $(seq "$repeats"); do
  echo "run $run of $repeats ..." >&2
  out="$outputs/run-$run"
  : > "$work/cpu-seconds"
  w=$(timed_cpu "$baseline" batch "$work/thumbs.jsonl" -o "$out-b" --quiet); base_rates+=("$(awk -v w="$w" 'BEGIN { print 1000 / w }')")
  w=$(timed_cpu "$phongrast" batch "$work/thumbs.jsonl" -o "$out-n" --quiet); new_rates+=("$(awk -v w="$w" 'BEGIN { print 1000 / w }')")
  mapfile -t c < "$work/cpu-seconds"
  base_cpu+=("${c[0]}"); new_cpu+=("${c[1]}")
  w1=$(timed "$phongrast" batch "$work/big1.jsonl" -o "$out-1" --quiet)
  w40=$(timed "$phongrast" batch "$work/big40.jsonl" -o "$out-40" --quiet)
  r=$(awk -v s="$(render_seconds "$out-40")" 'BEGIN { print s / 40 }')
  renders+=("$r")
  outside+=("$(awk -v a="$w1" -v b="$w40" -v r="$r" 'BEGIN { print (b - a) / 39 - r }')")
  # The same images: every thumbnail byte-identical in pixels is checked by the tests; here, the count.
  [ "$(ls "$out-n" | grep -c png)" = 1000 ] || { echo "batch wrote $(ls "$out-n" | grep -c png) images, expected 1000" >&2; exit 1; }
done
rm -rf "$outputs"
b=$(printf '%s\n' "${base_rates[@]}" | median); n=$(printf '%s\n' "${new_rates[@]}" | median)
o=$(printf '%s\n' "${outside[@]}" | median); r=$(printf '%s\n' "${renders[@]}" | median)
bc=$(printf '%s\n' "${base_cpu[@]}" | median); nc=$(printf '%s\n' "${new_cpu[@]}" | median)
awk -v b="$b" -v n="$n" -v o="$o" -v r="$r" -v k="$repeats" -v bc="$bc" -v nc="$nc" -v load="$(cut -d' ' -f1-3 /proc/loadavg)" 'BEGIN {
  printf "| `batch` (medians of %d runs, alternating; %d cores, load %s at the end) | before | after | goal |\n|---|---|---|---|\n", k, '"$(nproc)"', load
  printf "| 1,000 jobs of 256x256 thumbnails: images per second | %.1f | %.1f (%.2fx) | >= 3x |\n", b, n, n / b
  # (CPU seconds for 1,000 images = milliseconds per image)
  printf "| the same: CPU time (user + sys, all processes) per image | %.2f ms | %.2f ms (%.2fx less) | |\n", bc, nc, bc / nc
  printf "| 100k triangles at 512x512, 40 views: render per image (log) | | %.2f ms | |\n", 1000 * r
  printf "| the same: time per image outside the render | | %.2f ms = %.0f%% of the render | <= 10%% |\n", 1000 * o, 100 * o / r
}'
[ -n "${WORK:-}" ] || rm -rf "$work"
