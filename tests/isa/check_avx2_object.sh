#!/bin/sh
# Checks the object files of src/fill_kernels_avx2_*.cpp,
# src/lighting_avx2.cpp and src/coverage_screen_avx2.cpp: their kernels,
# lighting lanes and screen (namespace
# phongrast::detail::avx2) use 256-bit AVX registers, and no other
# function in them (the inline functions and templates of the headers they
# include, which the linker may pick over other objects' copies) uses a
# VEX-encoded (AVX) instruction, so code that runs on any x86-64 never lands
# in AVX2 code.
#   check_avx2_object.sh optimised|unoptimised OBJECT_FILE...
# With "optimised" (a Release build: -O3 vectorises the kernels; -O0 does
# not, nor GCC 12's -O2 with its very cheap cost model) the kernels of each
# object must also use ymm registers: proof that the target pragma applied.
set -eu
expect_wide=0
[ "$1" = optimised ] && expect_wide=1
shift
[ $# -gt 0 ] || { echo "check_avx2_object.sh: no object file given" >&2; exit 2; }
for object in "$@"; do
  echo "$object:"
  [ -s "$object" ] || { echo "no such object file: '$object'" >&2; exit 1; }
  objdump -d -C --no-show-raw-insn "$object" | awk -v expect_wide="$expect_wide" '
    /^[0-9a-f]+ <.*>:$/ { name = $0; kernel = index(name, "::avx2::") > 0; if (kernel) kernels++; else others++; next }
    name != "" && /\t/ {
      n = split($0, field, "\t"); instruction = field[n]
      if (kernel) { if (instruction ~ /ymm/) wide[name] = 1 }
      else if (instruction ~ /^v[a-z0-9]+[ \t]/ || instruction ~ /^v[a-z0-9]+$/) { bad[name] = instruction }
    }
    END {
      for (f in wide) wide_count++
      printf "%d AVX2 kernel functions, %d of them with ymm registers; %d other functions\n", kernels, wide_count, others
      failed = 0
      for (f in bad) { print "AVX instruction outside the AVX2 kernels: " f " (" bad[f] ")"; failed = 1 }
      if (expect_wide && wide_count == 0) { print "no AVX2 kernel uses ymm registers: the target pragma did not apply"; failed = 1 }
      exit failed
    }'
done
