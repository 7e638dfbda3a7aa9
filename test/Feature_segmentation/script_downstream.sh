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

echo "== add_subdirectory"
"$cmake_cmd" -S "$down" -B "$work/sub" -DFS_MODE=subdirectory -DFS_SOURCE_DIR="$FS_SOURCE_DIR" \
  -DCMAKE_BUILD_TYPE=Release "${launcher[@]}" >/dev/null
"$cmake_cmd" --build "$work/sub" >/dev/null
"$work/sub/downstream"

echo "== cmake --install, then find_package"
"$cmake_cmd" --install "$FS_BINARY_DIR" --prefix "$work/prefix" >/dev/null
test -f "$work/prefix/include/CGAL/Feature_segmentation/principal_curvatures.h"
"$cmake_cmd" -S "$down" -B "$work/pkg" -DFS_MODE=package -DCMAKE_PREFIX_PATH="$work/prefix" \
  -DCMAKE_BUILD_TYPE=Release "${launcher[@]}" >/dev/null
"$cmake_cmd" --build "$work/pkg" >/dev/null
# the installed headers, not the source tree's, must have been used
grep -q "$work/prefix/include" "$work/pkg/CMakeFiles/downstream.dir/flags.make"
"$work/pkg/downstream"
echo "script_downstream: 2 passed, 0 failed"
