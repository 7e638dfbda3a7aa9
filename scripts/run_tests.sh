#!/usr/bin/env bash
# One command for the whole test suite on a fresh Debian 12 machine:
# installs the dependencies, configures, builds and runs ctest; then builds the libFuzzer
# targets with Clang, AddressSanitizer and UndefinedBehaviorSanitizer in BUILD_DIR-fuzz
# and runs them (every seed, then FUZZ_SECONDS of fuzzing per target, default 20).
# Usage: scripts/run_tests.sh [BUILD_DIR]   (default: build)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$(realpath -m "${1:-$here/build}")"
"$here/scripts/install_dependencies.sh"
jobs="$(nproc 2>/dev/null || echo 2)"
# One compile job more than cores: a core does not idle while the other links.
build_jobs=$((jobs + 1))
# The benchmarks are not built: no test runs them (their folder's quality tests are).
# The test programs and the examples are compiled with -O1 (FAST_TEST_BUILD), the
# program, the editor and the Python module as users get them.
cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=Release -DFEATURE_SEGMENTATION_BUILD_TESTS=ON \
  -DFEATURE_SEGMENTATION_BUILD_BENCHMARKS=OFF -DFEATURE_SEGMENTATION_FAST_TEST_BUILD=ON
cmake --build "$build" -j "$build_jobs"
cd "$build"
ctest --output-on-failure -j "$jobs"

# Fuzzing under the sanitizers: the readers, the edit-script and feature-line parsers and
# the whole pipeline on small meshes (the sanitizer subset of the suite; the whole suite
# builds with -DFEATURE_SEGMENTATION_SANITIZE=ON, see the README).
fuzz_build="${build%/}-fuzz"
# -O1 -g1: what the sanitizers' reports need, at about half the compile time of -O2 -g
CXX=clang++ cmake -S "$here" -B "$fuzz_build" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" \
  -DFEATURE_SEGMENTATION_BUILD_FUZZERS=ON -DFEATURE_SEGMENTATION_BUILD_TESTS=OFF \
  -DFEATURE_SEGMENTATION_BUILD_EXAMPLES=OFF -DFEATURE_SEGMENTATION_BUILD_DEMO=OFF \
  -DFEATURE_SEGMENTATION_BUILD_PYTHON=OFF \
  -DFEATURE_SEGMENTATION_BUILD_BENCHMARKS=OFF -DFEATURE_SEGMENTATION_BUILD_DOC=OFF \
  -DFEATURE_SEGMENTATION_FUZZ_SECONDS="${FUZZ_SECONDS:-20}"
cmake --build "$fuzz_build" -j "$build_jobs"
cd "$fuzz_build"
ctest --output-on-failure -j "$jobs"
