#!/usr/bin/env bash
# The full speed report: every scene class of the speed goals (the 512x512
# scenes, 100k+ triangles, the 1.3M sphere, the 8M mesh at 2048x2048) against
# llvmpipe at 1 and 2 threads, ns per triangle, ambient-only against full
# lighting and peak memory, each goal met or not, then the detailed tables.
# The same as `bench/run.sh all` (its flags: --quick, --no-huge); about
# 20 minutes on 2 cores; the report is also written to build/bench-release/report.md.
exec "$(dirname "$0")/run.sh" all "$@"
