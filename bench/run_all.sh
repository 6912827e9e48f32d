#!/usr/bin/env bash
# The full speed report: every scene class of the speed goals (the 512x512
# scenes, 100k+ triangles, the 1.3M sphere, the 8M mesh at 2048x2048) against
# llvmpipe at 1 and 2 threads, ns per triangle, ambient-only against full
# lighting and peak memory, each goal met or not, then the detailed tables.
# The same as `bench/run.sh all` (its flags: --quick, --no-huge); about
# 20 minutes on 2 cores; the report is also written to build/bench-release/report.md.
#
# With PHONGRAST_BASELINE set to a previous build's `phongrast` (and optionally
# PHONGRAST_BASELINE_PYTHON to the folder of its Python module), it then runs
# bench/run_startup.sh against it: process start-up and `import phongrast`,
# PNG encoding against OpenImageIO's, and `batch` images per second
# (docs/startup.md; needs build/release with PHONGRAST_BUILD_BENCH=ON).
set -e
"$(dirname "$0")/run.sh" all "$@"
if [ -n "${PHONGRAST_BASELINE:-}" ]; then
  "$(dirname "$0")/run_startup.sh" "$PHONGRAST_BASELINE" ${PHONGRAST_BASELINE_PYTHON:+"$PHONGRAST_BASELINE_PYTHON"}
fi
