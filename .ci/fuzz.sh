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
#   FUZZ_RUNS: inputs per reader target (default 200000); FUZZ_API_RUNS:
#   inputs for fuzz_api (default 40000: each input renders scenes, about 300
#   inputs/s on the CI machine's kind, so 200000 would run into the cap below
#   and make the run depend on the machine's speed); FUZZ_SEED (default 1);
#   FUZZ_SECONDS: a safety cap on the time per target (default 600).
set -euo pipefail
cd "$(dirname "$0")/.."

reader_runs="${FUZZ_RUNS:-200000}"
api_runs="${FUZZ_API_RUNS:-40000}"
seed="${FUZZ_SEED:-1}"
seconds="${FUZZ_SECONDS:-600}"
build=build/fuzz
sanitizers="-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer"
# Coverage instrumentation in the library too (not only in the targets), so
# libFuzzer sees which branches of the readers an input reaches.
coverage="-fsanitize=fuzzer-no-link"

# Line tables are all a sanitizer's report needs (file:line of each frame),
# and full debug information costs compile time: with GCC and the sanitizers,
# one fill-kernel file took 339 s at -g against 245 s at -g1 (not measured
# separately for clang; this whole build took 271-327 s).
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -gline-tables-only -DNDEBUG" \
  -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_CXX_FLAGS="$sanitizers $coverage" \
  -DPHONGRAST_BUILD_FUZZERS=ON -DPHONGRAST_BUILD_IO=ON -DPHONGRAST_BUILD_APPS=OFF \
  -DPHONGRAST_BUILD_TESTS=OFF -DPHONGRAST_INSTALL=OFF -DPHONGRAST_WERROR=ON
cmake --build "$build" -j2 --target fuzz_obj fuzz_ply fuzz_stl fuzz_gltf fuzz_scene fuzz_api

mkdir -p "$build/findings"
for target in fuzz_obj fuzz_ply fuzz_stl fuzz_gltf fuzz_scene fuzz_api; do
  name="${target#fuzz_}"
  runs="$reader_runs"
  [ "$target" = fuzz_api ] && runs="$api_runs"
  # New inputs go to a scratch corpus so the repository's seeds stay as they are.
  work="$build/corpus/$name"
  rm -rf "$work"
  mkdir -p "$work"
  echo "== $target: $runs inputs (seed $seed) from fuzz/corpus/$name (starts at ${SECONDS} s)"
  UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    "$build/fuzz/$target" -seed="$seed" -runs="$runs" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=4096 \
    -max_len=4096 -print_final_stats=1 -artifact_prefix="$build/findings/$name-" \
    "$work" "fuzz/corpus/$name"
done
echo "== fuzz: build and all targets took ${SECONDS} s"
