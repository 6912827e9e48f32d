# Shared by the scheduler tests (slurm.sh, parallel.sh): a temporary folder, a
# manifest of 40 small PNG jobs over meshes the project generates, the
# single-process reference run, and the comparison of a sharded run with it.
# Sourced with PHONGRAST set to the program.

skip() {  # ctest reports exit status 77 as "skipped" (SKIP_RETURN_CODE)
  echo "SKIPPED: $*"
  exit 77
}

make_work_folder() {
  work=$(mktemp -d /tmp/phongrast-scheduler-XXXXXX)
}

# 40 jobs: turntables of 1-3 views and scene files, three meshes of different sizes.
write_manifest() {
  "$PHONGRAST" generate -q -o "$work/knot-small.obj" --segments 30 --sides 6
  "$PHONGRAST" generate -q -o "$work/knot.obj" --segments 120 --sides 10
  "$PHONGRAST" generate -q -o "$work/knot-big.obj" --segments 480 --sides 16
  cat > "$work/scene.json" <<'JSON'
{"mesh": "knot.obj", "camera": {"eye": [2, 3, 12], "lookat": [0, 0, 0], "focal": 4, "sensor": [8, 8]},
 "image": {"height": 48, "width": 64}, "lights": [{"position": [5, 5, 10], "intensity": [1, 1, 1]}]}
JSON
  local manifest="$work/jobs.jsonl" i
  : > "$manifest"
  for i in $(seq 1 40); do
    case $((i % 4)) in
      0) echo "{\"mesh\": \"knot-small.obj\", \"views\": $((1 + i % 3)), \"size\": \"32x32\", \"output\": \"small/$i-{view}.png\"}" ;;
      1) echo "{\"mesh\": \"knot-big.obj\", \"elevation\": 25, \"size\": \"64x48\", \"output\": \"big-$i.png\"}" ;;
      2) echo "{\"scene\": \"scene.json\", \"shader\": \"gouraud\", \"samples\": 2, \"output\": \"scene-$i.png\"}" ;;
      3) echo "{\"mesh\": \"knot.obj\", \"views\": 3, \"elevation\": -10, \"size\": \"40x40\", \"mode\": \"seed\", \"output\": \"t$i/{view}.png\"}" ;;
    esac >> "$manifest"
  done
  "$PHONGRAST" batch "$manifest" -o "$work/reference" --quiet
}

# Every image of the sharded run in $1 equals the reference byte for byte, each
# job was rendered by exactly one of the $2 shards, and --status says all done.
check_sharded_run() {
  local out=$1 shards=$2 problems=0
  if ! diff -r -x .phongrast-batch "$work/reference" "$out"; then
    echo "FAILED: the sharded images differ from the single-process run"
    problems=1
  fi
  local logs
  logs=$(ls "$out/.phongrast-batch")
  if [ "$(echo "$logs" | wc -l)" != "$shards" ]; then
    echo "FAILED: expected $shards shard logs, found: $logs"
    problems=1
  fi
  local done_jobs
  done_jobs=$(cat "$out"/.phongrast-batch/*.jsonl | grep '"status":"done"' | grep -o '"job":[0-9]*' | sort)
  if [ "$(echo "$done_jobs" | wc -l)" != 40 ] || [ -n "$(echo "$done_jobs" | uniq -d)" ]; then
    echo "FAILED: expected each of the 40 jobs done exactly once; got:"
    echo "$done_jobs" | uniq -c
    problems=1
  fi
  if ! "$PHONGRAST" batch --status "$work/jobs.jsonl" -o "$out"; then
    echo "FAILED: --status does not report every job done"
    problems=1
  fi
  return $problems
}
