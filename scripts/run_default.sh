#!/usr/bin/env bash
# The main job in one command on a fresh Debian 12 machine: installs the dependencies,
# configures and builds the program `feature_segmentation` and the Python module, runs
# the program on the default model (fandisk) and says where the program, the module and
# the outputs are.
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
targets=(feature_segmentation)
# the Python module's target exists when pybind11 and Python were found
if cmake --build "$build" --target help 2>/dev/null | grep -c feature_segmentation_python >/dev/null; then
  targets+=(feature_segmentation_python)
fi
cmake --build "$build" --target "${targets[@]}" -j "$jobs"

program="$build/demo/Feature_segmentation/feature_segmentation"
"$program" --output-dir "$output"

echo
echo "Outputs of the default run (fandisk) in $(cd "$output" && pwd):"
for f in segmentation.ply face_patches.txt vertex_patches.txt feature_lines.obj feature_lines.polylines.txt \
         feature_lines.types.txt boundaries.polylines.txt boundaries.types.txt segmentation_refined.ply summary.json; do
  echo "  $f"
done
echo
echo "The program: $program  (--help for its options; run it on your own mesh: $program MESH --output-dir DIR)"
if [ -d "$build/python/feature_segmentation" ]; then
  echo "The Python module: PYTHONPATH=$build/python python3 -c 'import feature_segmentation'"
fi
