#!/usr/bin/env bash
# Packaging test: a downstream CMake project gets CGAL::Feature_segmentation both with
# add_subdirectory and with find_package after `cmake --install`, builds and runs.
set -euo pipefail
: "${FS_SOURCE_DIR:?}" "${FS_BINARY_DIR:?}"
cmake_cmd="${CMAKE_COMMAND:-cmake}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
down="$FS_SOURCE_DIR/test/Feature_segmentation/downstream"
launcher=()
if command -v ccache >/dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
# Unoptimised and without debug information (-O0): the test is about finding, compiling
# and linking the package, and -O0 compiles in about half the time of -O3.
build_type=(-DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG=-O0)

echo "== add_subdirectory"
"$cmake_cmd" -S "$down" -B "$work/sub" -DFS_MODE=subdirectory -DFS_SOURCE_DIR="$FS_SOURCE_DIR" \
  "${build_type[@]}" "${launcher[@]}" >/dev/null
"$cmake_cmd" --build "$work/sub" >/dev/null
"$work/sub/downstream"

echo "== cmake --install, then find_package"
"$cmake_cmd" --install "$FS_BINARY_DIR" --prefix "$work/prefix" >/dev/null
test -f "$work/prefix/include/CGAL/Feature_segmentation/principal_curvatures.h"
"$cmake_cmd" -S "$down" -B "$work/pkg" -DFS_MODE=package -DCMAKE_PREFIX_PATH="$work/prefix" \
  "${build_type[@]}" "${launcher[@]}" >/dev/null
"$cmake_cmd" --build "$work/pkg" >/dev/null
# the installed headers, not the source tree's, must have been used
grep -q "$work/prefix/include" "$work/pkg/CMakeFiles/downstream.dir/flags.make"
"$work/pkg/downstream"

# the installed program and Python module (when they were built)
passed=2
if [ -x "$FS_BINARY_DIR/demo/Feature_segmentation/feature_segmentation" ]; then
  "$work/prefix/bin/feature_segmentation" --help > "$work/help.txt" # (grep -q on a pipe: SIGPIPE)
  grep -q '^Usage: feature_segmentation' "$work/help.txt"
  test -f "$work/prefix/share/feature_segmentation/editor/index.html"
  passed=$((passed + 1))
fi
if [ -d "$FS_BINARY_DIR/python/feature_segmentation" ]; then
  echo "== import feature_segmentation from the install prefix"
  (cd "$work" && PYTHONPATH="$work/prefix/lib/python3/dist-packages" /usr/bin/python3 -c "
import feature_segmentation as fs, numpy as np
assert fs.__file__.startswith('$work/prefix/'), fs.__file__
v = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], dtype=float)
f = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])
faces, vertices, result = fs.segment(v, f)
assert faces.shape == (4,) and vertices.shape == (4,) and result.faces == 4, result
print('installed module:', fs.__file__, result)
")
  passed=$((passed + 1))
fi
echo "script_downstream: $passed passed, 0 failed"
