#!/usr/bin/env bash
# One command for the whole test suite on a fresh Debian 12 machine:
# installs the dependencies, configures, builds and runs ctest, meanwhile building the
# libFuzzer targets with Clang, AddressSanitizer and UndefinedBehaviorSanitizer in
# BUILD_DIR-fuzz; then runs them (every seed, then FUZZ_SECONDS of fuzzing per target,
# default 20).
# Usage: scripts/run_tests.sh [BUILD_DIR]   (default: build-tests; a build for the tests
# only, everything at -O1, so not the program's build folder)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$(realpath -m "${1:-$here/build-tests}")"
"$here/scripts/install_dependencies.sh"
jobs="$(nproc 2>/dev/null || echo 2)"
# One compile job more than cores: a core does not idle while the other links.
build_jobs=$((jobs + 1))
# The benchmarks are not built: no test runs them (their folder's quality tests are).
# Everything is compiled at -O1 (FAST_TEST_BUILD): two thirds of the compile time.
cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=Release -DFEATURE_SEGMENTATION_BUILD_TESTS=ON \
  -DFEATURE_SEGMENTATION_BUILD_BENCHMARKS=OFF -DFEATURE_SEGMENTATION_FAST_TEST_BUILD=ON
cmake --build "$build" -j "$build_jobs"

# Fuzzing under the sanitizers: the readers, the edit-script and feature-line parsers and
# the whole pipeline on small meshes (the sanitizer subset of the suite; the whole suite
# builds with -DFEATURE_SEGMENTATION_SANITIZE=ON, see the README). The fuzzers are built
# while the suite runs, which leaves a core mostly idle (its longest tests wait for a
# compiler, a browser or a server); their log is printed if the build fails.
fuzz_build="${build%/}-fuzz"
fuzz_log="$build/fuzz_build.log"
(
  # -O1 -g1: what the sanitizers' reports need, at about half the compile time of -O2 -g
  CXX=clang++ cmake -S "$here" -B "$fuzz_build" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" \
    -DFEATURE_SEGMENTATION_BUILD_FUZZERS=ON -DFEATURE_SEGMENTATION_BUILD_TESTS=OFF \
    -DFEATURE_SEGMENTATION_BUILD_EXAMPLES=OFF -DFEATURE_SEGMENTATION_BUILD_DEMO=OFF \
    -DFEATURE_SEGMENTATION_BUILD_PYTHON=OFF \
    -DFEATURE_SEGMENTATION_BUILD_BENCHMARKS=OFF -DFEATURE_SEGMENTATION_BUILD_DOC=OFF \
    -DFEATURE_SEGMENTATION_FUZZ_SECONDS="${FUZZ_SECONDS:-20}" &&
  cmake --build "$fuzz_build" -j "$jobs"
) > "$fuzz_log" 2>&1 &
fuzz_pid=$!

suite=0
(cd "$build" && ctest --output-on-failure -j "$jobs") || suite=$?
if ! wait "$fuzz_pid"; then
  cat "$fuzz_log"
  echo "run_tests: the fuzzers did not build (log above: $fuzz_log)" >&2
  exit 1
fi
echo "run_tests: the fuzzers are built ($fuzz_log)"
[ "$suite" -eq 0 ] || exit "$suite"
cd "$fuzz_build"
ctest --output-on-failure -j "$jobs"
