#!/bin/sh
# Reproduces docs/accuracy.md: configures its own build folder with the
# benchmarks on, builds phongrast_accuracy, and runs it. The PNGs go straight
# to docs/images/; the CSVs and the Markdown tables to the build folder.
# Extra arguments go to the program (e.g. --scenes sphere,floor --runs 9).
set -eu
cd "$(dirname "$0")/../.."
build=${BUILD_DIR:-build/accuracy-bench}
report="$build/accuracy-report"

cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DPHONGRAST_BUILD_BENCH=ON \
  -DPHONGRAST_BUILD_TESTS=OFF -DPHONGRAST_BUILD_APPS=OFF -DPHONGRAST_BUILD_IO=ON -DPHONGRAST_INSTALL=OFF
cmake --build "$build" -j2 --target phongrast_accuracy

mkdir -p "$report" docs/images
{
  echo "date: $(date -u '+%Y-%m-%d %H:%M UTC')"
  echo "cpu: $(lscpu | sed -n 's/^Model name: *//p' | head -n 1), $(nproc) cores"
  echo "load before: $(uptime)"
} > "$report/machine.txt"
"$build/bench/accuracy/phongrast_accuracy" --out "$report" --images docs/images "$@"
echo "load after: $(uptime)" >> "$report/machine.txt"
cat "$report/machine.txt"
echo "tables: $report/accuracy_tables.md"
