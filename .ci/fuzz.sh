#!/usr/bin/env bash
# Builds the libFuzzer targets (fuzz/) with clang, AddressSanitizer and
# UndefinedBehaviorSanitizer in build/fuzz, and runs each for a bounded time
# from its seed corpus in fuzz/corpus/<target>/ (fuzz_api: the public C++
# API with scenes built in memory from the bytes, no file). A crash leaves its input in
# build/fuzz/findings/ and makes this script fail; turn it into a regression
# test (tests/test_fuzz_regressions.cpp, and the input into fuzz/corpus/).
# The runs are reproducible: a fixed seed, a fixed number of inputs and a
# scratch corpus emptied first, so the same commit fuzzes the same inputs in
# CI as on a developer's machine (a time limit would make CI pass or fail
# depending on the machine's speed).
#   FUZZ_RUNS: inputs per target (default 200000); FUZZ_SEED (default 1);
#   FUZZ_SECONDS: a safety cap on the time per target (default 600).
set -euo pipefail
cd "$(dirname "$0")/.."

runs="${FUZZ_RUNS:-200000}"
seed="${FUZZ_SEED:-1}"
seconds="${FUZZ_SECONDS:-600}"
build=build/fuzz
sanitizers="-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer"
# Coverage instrumentation in the library too (not only in the targets), so
# libFuzzer sees which branches of the readers an input reaches.
coverage="-fsanitize=fuzzer-no-link"

cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_CXX_FLAGS="$sanitizers $coverage" \
  -DPHONGRAST_BUILD_FUZZERS=ON -DPHONGRAST_BUILD_IO=ON -DPHONGRAST_BUILD_APPS=OFF \
  -DPHONGRAST_BUILD_TESTS=OFF -DPHONGRAST_INSTALL=OFF -DPHONGRAST_WERROR=ON
cmake --build "$build" -j2 --target fuzz_obj fuzz_ply fuzz_stl fuzz_gltf fuzz_scene fuzz_api

mkdir -p "$build/findings"
for target in fuzz_obj fuzz_ply fuzz_stl fuzz_gltf fuzz_scene fuzz_api; do
  name="${target#fuzz_}"
  # New inputs go to a scratch corpus so the repository's seeds stay as they are.
  work="$build/corpus/$name"
  rm -rf "$work"
  mkdir -p "$work"
  echo "== $target: $runs inputs (seed $seed) from fuzz/corpus/$name"
  UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    "$build/fuzz/$target" -seed="$seed" -runs="$runs" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=4096 \
    -max_len=4096 -print_final_stats=1 -artifact_prefix="$build/findings/$name-" \
    "$work" "fuzz/corpus/$name"
done
