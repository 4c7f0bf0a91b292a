#!/usr/bin/env bash
# Installs roofsweep's build and test dependencies from Debian's archive.
# Idempotent: packages already present are skipped, so a second run costs a
# dpkg query and nothing else. Must run as root (or with sudo available).
#
#   scripts/install-deps.sh          core build + tests
#   scripts/install-deps.sh --qgis   also QGIS for the Processing provider tests
set -euo pipefail

core=(
  build-essential cmake ninja-build pkg-config ccache
  libgdal-dev gdal-bin libproj-dev proj-bin libgeographiclib-dev libeigen3-dev
  libopencv-dev libcgal-dev libgtest-dev libbenchmark-dev libtbb-dev
  libboost-dev  # Boost.Geometry R-tree in algorithms/edges (also pulled in by libcgal-dev)
  libcli11-dev nlohmann-json3-dev libvalijson-dev libcitygml-dev
  # libcitygml's CMake target hard-codes libGL.so/libGLU.so but does not
  # depend on the packages that provide them.
  libgl-dev libglu1-mesa-dev
  libxml2-dev libxml2-utils
)
qgis=(qgis python3-qgis qgis-providers python3-pytest python3-gdal)

want=("${core[@]}")
for arg in "$@"; do
  case "$arg" in
    --qgis) want+=("${qgis[@]}") ;;
    *) echo "install-deps.sh: unknown option '$arg'" >&2; exit 2 ;;
  esac
done

missing=()
for p in "${want[@]}"; do
  st=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
  [[ "$st" == "install ok installed" ]] || missing+=("$p")
done

if ((${#missing[@]} == 0)); then
  echo "install-deps: all ${#want[@]} packages present."
  exit 0
fi

SUDO=""
if [[ $(id -u) -ne 0 ]]; then
  command -v sudo >/dev/null || { echo "install-deps: need root to install: ${missing[*]}" >&2; exit 1; }
  SUDO=sudo
fi
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "install-deps: done."
