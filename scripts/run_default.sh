#!/usr/bin/env bash
# The main job in one command on a fresh Debian 12 machine: installs the dependencies,
# configures and builds the program `feature_segmentation`, runs it on the default model
# (fandisk) and says where the outputs are.
# Usage: scripts/run_default.sh [OUTPUT_DIR]   (default: ./output)
# Environment: FS_BUILD_DIR (default: <source>/build), FS_CMAKE_ARGS (extra cmake args).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
output="${1:-output}"
build="${FS_BUILD_DIR:-$here/build}"
jobs="$(nproc 2>/dev/null || echo 2)"

"$here/scripts/install_dependencies.sh"
# shellcheck disable=SC2086 # FS_CMAKE_ARGS is a list of arguments
cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=Release ${FS_CMAKE_ARGS:-}
cmake --build "$build" --target feature_segmentation -j "$jobs"

"$build/demo/Feature_segmentation/feature_segmentation" --output-dir "$output"

echo
echo "Outputs of the default run (fandisk) in $(cd "$output" && pwd):"
for f in feature_lines.polylines.txt feature_lines.obj segmentation.ply face_patches.txt vertex_patches.txt boundaries.polylines.txt segmentation_refined.ply summary.json; do
  echo "  $f"
done
