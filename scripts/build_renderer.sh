#!/usr/bin/env bash
# Installs the contact-sheet renderer's extras (Mesa's off-screen OpenGL, libpng,
# ImageMagick's montage, a font) when missing and builds the renderer
# (benchmark/Feature_segmentation/evaluation) in BUILD_DIR/evaluation-render.
# Used by run_evaluation.sh and render_contact_sheet.sh.
# Usage: scripts/build_renderer.sh BUILD_DIR
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${1:?usage: build_renderer.sh BUILD_DIR}"
jobs="$(nproc 2>/dev/null || echo 2)"
extras=(libosmesa6-dev libpng-dev pkg-config imagemagick fonts-dejavu-core)
missing=()
for p in "${extras[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "build_renderer: installing ${missing[*]}"
  SUDO=""; if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
cmake -S "$here/benchmark/Feature_segmentation/evaluation" -B "$build/evaluation-render" >/dev/null
cmake --build "$build/evaluation-render" -j "$jobs" >/dev/null
