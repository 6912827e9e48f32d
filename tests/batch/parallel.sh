#!/bin/bash
# GNU parallel runs 4 shards of a 40-job manifest into one folder; the images
# must equal a single process's byte for byte. Usage: parallel.sh PHONGRAST
set -u
PHONGRAST=$1
. "$(dirname "$0")/scheduler_common.sh"
command -v parallel > /dev/null || skip "GNU parallel is not installed (apt-get install parallel)"
make_work_folder
trap 'rm -rf "$work"' EXIT
write_manifest || exit 1
parallel --will-cite -j 4 "$PHONGRAST" batch "$work/jobs.jsonl" -o "$work/out" --quiet --shard {}/4 ::: 0 1 2 3 \
  || { echo "FAILED: a shard exited with an error"; exit 1; }
check_sharded_run "$work/out" 4 && echo "ok: 4 shards under GNU parallel = one process"
