#!/usr/bin/env bash
# One command for the whole test suite on a fresh Debian 12 machine:
# installs the dependencies, configures, builds and runs ctest.
# Usage: scripts/run_tests.sh [BUILD_DIR]   (default: build)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${1:-$here/build}"
"$here/scripts/install_dependencies.sh"
jobs="$(nproc 2>/dev/null || echo 2)"
cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=Release -DFEATURE_SEGMENTATION_BUILD_TESTS=ON
cmake --build "$build" -j "$jobs"
cd "$build"
ctest --output-on-failure -j "$jobs"
