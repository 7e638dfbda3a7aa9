#!/usr/bin/env bash
# A contact sheet of the program's segmentations: runs feature_segmentation on every
# MESH (with the options in FS_OPTIONS, default none: the package's defaults), renders
# each segmentation.ply from two sides with the evaluation's renderer (Mesa's
# off-screen OpenGL) and lays the pictures out in one PNG, each labelled with the
# mesh's name and its patch count.
# Usage: scripts/render_contact_sheet.sh OUT.png MESH...
# Environment: FS_BUILD_DIR (default: <source>/build), FS_OPTIONS (program options),
# FS_TILE_SIZE (pixels per view, default 220), FS_COLUMNS (default 4).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
if [ $# -lt 2 ]; then
  echo "usage: $0 OUT.png MESH..." >&2
  exit 2
fi
out="$1"; shift
build="${FS_BUILD_DIR:-$here/build}"
jobs="$(nproc 2>/dev/null || echo 2)"
tile="${FS_TILE_SIZE:-220}"

"$here/scripts/install_dependencies.sh"
cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" --target feature_segmentation -j "$jobs" >/dev/null
"$here/scripts/build_renderer.sh" "$build"

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
args=()
i=0
for mesh in "$@"; do
  i=$((i + 1))
  name="$(basename "$mesh")"; name="${name%.*}"
  dir="$work/$i"  # numbered: two meshes of the same name do not collide
  # shellcheck disable=SC2086 # FS_OPTIONS is a list of options
  if ! "$build/demo/Feature_segmentation/feature_segmentation" "$mesh" --output-dir "$dir" --quiet ${FS_OPTIONS:-} 2> "$dir.err"; then
    echo "render_contact_sheet: $mesh: $(tail -n 1 "$dir.err")" >&2
    exit 1
  fi
  patches="$(sed -n 's/^    "patches": \([0-9]*\),\{0,1\}$/\1/p' "$dir/summary.json" | head -n 1)"
  if [ -z "$patches" ]; then
    echo "render_contact_sheet: $mesh: no patch count in $dir/summary.json" >&2
    exit 1
  fi
  python3 "$here/benchmark/Feature_segmentation/evaluation/ply_to_scene.py" \
    "$dir/segmentation.ply" "$dir.scene" "$name ($patches patches)"
  if ! "$build/evaluation-render/render_scenes" "$dir.scene" "$dir" "$tile" > "$dir.tiles"; then
    echo "render_contact_sheet: $mesh: the renderer failed" >&2
    exit 1
  fi
  while IFS=$'\t' read -r png label; do
    args+=(-label "$label" "$png")
  done < "$dir.tiles"
done
montage -font /usr/share/fonts/truetype/dejavu/DejaVuSans.ttf -pointsize 13 "${args[@]}" \
        -tile "${FS_COLUMNS:-4}x" -geometry +4+4 "$out"
echo "render_contact_sheet: $out"
