#!/usr/bin/env bash
# The quality evaluation in one command (issues 6 and 13): installs what it needs, builds the
# evaluation program and the contact-sheet renderer, evaluates fandisk, the paper's
# models, the ground-truth models (ABC format) and the CAD parts (with their B-rep faces),
# and writes
#   OUT/table.md, OUT/table.csv, OUT/robustness.csv   the tables
#   OUT/cad_parts.md, OUT/cad_parts.csv               the CAD parts at 0, 0.1% and 0.3% noise
#   OUT/resolution.md, OUT/resolution.csv             fandisk at 13k to 828k faces
#   OUT/contact_sheets/MODEL.png                       feature lines and every method's patches (a row
#                                                      per CC variant: default, smoothed, best, smoothed)
#   OUT/contact_sheets/cad_worst_five.png              the five CAD parts with the lowest F at the
#                                                      defaults: ground truth and three methods
#   OUT/tiles/                                         the pictures' parts (OUT/scenes/, the renderer's
#                                                      input, is kept with FS_KEEP_SCENES=1)
# Usage: scripts/run_evaluation.sh [OUT]   (default: out/evaluation)
# Environment: FEATURE_SEGMENTATION_DATA (default: ../shared/data beside the clone, if
# present; without it only fandisk is evaluated, and its resolution series),
# FS_BUILD_DIR (default: <source>/build),
# FS_TILE_SIZE (default 300 pixels per view).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
out="${1:-out/evaluation}"
build="${FS_BUILD_DIR:-$here/build}"
jobs="$(nproc 2>/dev/null || echo 2)"
tile="${FS_TILE_SIZE:-300}"

"$here/scripts/install_dependencies.sh" --evaluation

cmake -S "$here" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" --target evaluate_quality -j "$jobs"
"$here/scripts/build_renderer.sh" "$build"

data="${FEATURE_SEGMENTATION_DATA:-}"
if [ -z "$data" ] && [ -d "$here/../shared/data" ]; then data="$(cd "$here/../shared/data" && pwd)"; fi
mkdir -p "$out"
out="$(cd "$out" && pwd)"
if [ -n "$data" ]; then
  "$build/benchmark/Feature_segmentation/evaluate_quality" --data "$data" --out "$out"
else
  echo "run_evaluation: no data folder (FEATURE_SEGMENTATION_DATA unset, no ../shared/data): fandisk only"
  "$build/benchmark/Feature_segmentation/evaluate_quality" --out "$out"
fi

font=/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf
rm -rf "$out/tiles" "$out/contact_sheets"
mkdir -p "$out/tiles" "$out/contact_sheets"
for scene in "$out"/scenes/*.scene; do
  model="$(basename "$scene" .scene)"
  args=()
  while IFS=$'\t' read -r png label; do
    args+=(-label "$label" "$png")
  done < <("$build/evaluation-render/render_scenes" "$scene" "$out/tiles/$model" "$tile")
  montage -font "$font" -pointsize 13 "${args[@]}" -tile 4x -geometry +6+6 \
          -title "$model" "$out/contact_sheets/$model.png"
  echo "run_evaluation: $out/contact_sheets/$model.png"
done

# The five CAD parts this package does worst on (evaluate_quality's worst_K_NAME scenes),
# one row each: ground truth, this package, sharp edges 20, Efficient RANSAC.
worst=("$out"/contact_sheets/worst_*.png)
if [ -e "${worst[0]}" ]; then
  convert "${worst[@]}" -append "$out/contact_sheets/cad_worst_five.png"
  echo "run_evaluation: $out/contact_sheets/cad_worst_five.png"
fi

# The scenes (about 4 MB per model) only feed the renderer.
if [ "${FS_KEEP_SCENES:-0}" != 1 ]; then rm -rf "$out/scenes"; fi

echo
echo "Tables: $out/table.md, $out/table.csv, $out/robustness.csv, $out/cad_parts.md, $out/cad_parts.csv,"
echo "        $out/resolution.md, $out/resolution.csv"
echo "Contact sheets: $out/contact_sheets/"
