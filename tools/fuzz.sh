#!/usr/bin/env bash
# tools/fuzz.sh TARGET SECONDS — builds the libFuzzer targets (clang++-14, PYRO_FUZZ=ON: coverage,
# ASan, UBSan) into build-fuzz/ and runs TARGET (scene, vdb, png, particles or cli) for SECONDS under
# `nice -n 19`, starting from the committed seeds in tests/fuzz/corpus/TARGET. New inputs go to
# build-fuzz/corpus/TARGET (not committed); a crashing input is written to
# build-fuzz/artifacts/TARGET/ — commit it under tests/fuzz/regressions/TARGET/ with the fix
# (the normal suite feeds every file there to the target: tests/fuzz/fuzz_inputs_test.cpp).
# Environment: JOBS (build jobs, default 2), CXX (default clang++-14), FUZZ_ARGS (extra
# libFuzzer flags).
set -euo pipefail
if [[ $# -ne 2 ]]; then
  echo "usage: tools/fuzz.sh TARGET SECONDS   (TARGET: scene, vdb, png, particles, cli)" >&2
  exit 2
fi
target=$1
seconds=$2
case "$target" in scene | vdb | png | particles | cli) ;; *)
  echo "tools/fuzz.sh: unknown target \"$target\" (expected scene, vdb, png, particles or cli)" >&2
  exit 2 ;;
esac
if ! [[ "$seconds" =~ ^[1-9][0-9]*$ ]]; then
  echo "tools/fuzz.sh: SECONDS must be a positive whole number, found \"$seconds\"" >&2
  exit 2
fi
root=$(cd "$(dirname "$0")/.." && pwd)
build=$root/build-fuzz
cxx=${CXX:-clang++-14}

if [[ ! -f $build/CMakeCache.txt ]]; then
  nice -n 19 cmake -S "$root" -B "$build" -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g" -DPYRO_FUZZ=ON -DPYRO_BUILD_TESTS=OFF >/dev/null
fi
nice -n 19 cmake --build "$build" -j "${JOBS:-2}" --target "fuzz_$target"

mkdir -p "$build/corpus/$target" "$build/artifacts/$target"
# allocator_may_return_null: malloc of an absurd size read from a damaged file returns null as in
# a release build; -malloc_limit_mb lets such a request reach the allocator rather than
# libFuzzer's own limit. (operator new of such a size still stops the run under ASan, where a
# release build throws std::bad_alloc: see tests/fuzz/fuzz_inputs_test.cpp on *.no_asan.* inputs.)
# FUZZ_ARGS="-fork=1 -ignore_ooms=1 -ignore_crashes=1" keeps going past findings.
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:allocator_may_return_null=1}
export LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$root/tests/sanitizers/lsan_suppressions.txt}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
cd "$build"
# shellcheck disable=SC2086
exec nice -n 19 "$build/fuzz_$target" -max_total_time="$seconds" -timeout=30 -rss_limit_mb=4096 -malloc_limit_mb=1048576 \
  -print_final_stats=1 -artifact_prefix="$build/artifacts/$target/" ${FUZZ_ARGS:-} \
  "$build/corpus/$target" "$root/tests/fuzz/corpus/$target"
