#!/usr/bin/env bash
# Installs the Debian 12 packages the package, its tests, benchmarks and manual need
# (with --evaluation, also what the quality evaluation needs).
# A no-op when everything is present; nothing is fetched from outside Debian's archive.
set -euo pipefail

packages=(
  build-essential cmake
  libcgal-dev      # CGAL 5.5 (header-only)
  libcgal-demo     # /usr/share/doc/libcgal-dev/data.tar.gz: fandisk and the other CAD meshes
  libboost-graph-dev libboost-test-dev libboost-program-options-dev   # options of the program
  libyaml-cpp-dev  # the ABC ground truth (benchmark/Feature_segmentation/evaluation)
  zlib1g-dev       # the evaluation reads the gzipped ABC meshes of the data folder
  libeigen3-dev
  libtbb-dev       # threads (concurrency_tag, --threads)
  doxygen
  ccache
  clang libclang-rt-14-dev   # libFuzzer and the sanitizers (fuzz targets in the test command)
  nlohmann-json3-dev   # the editor's server (feature_segmentation edit, on Boost.Beast)
  nodejs           # npm ci puts three.js (the editor's page) and playwright-core into the build
  chromium         # the editor's browser test (headless)
  python3-dev pybind11-dev python3-numpy python3-pytest   # the Python module and its tests
  python3-distributed   # Dask: python3 -m feature_segmentation.batch
)
# --evaluation: also gmsh, which builds the evaluation's generated parts (large: the test
# command does without it)
if [ "${1:-}" = "--evaluation" ]; then packages+=(gmsh); fi
# npm: Debian's package, unless an npm comes with the installed Node.js (NodeSource's)
if ! command -v npm >/dev/null 2>&1; then packages+=(npm); fi

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install_dependencies: all Debian packages present"
  exit 0
fi

echo "install_dependencies: installing ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "install_dependencies: done"
