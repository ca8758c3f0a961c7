#!/usr/bin/env bash
# Installs the Debian 12 packages ConeScope needs, only those that are missing.
set -euo pipefail

packages=(
  cmake g++ make pkg-config
  libvtk9-dev libvtk9-qt-dev qtbase5-dev libglm-dev libmeshoptimizer-dev
  libgtest-dev libgmock-dev libbenchmark-dev libcli11-dev nlohmann-json3-dev libexpat1-dev
  # assimp decodes glTF for the reader (src/io) and counts triangles independently in the tests;
  # assimp-testmodels are files nobody here wrote (tests/io/AssimpModelsTests.cpp).
  libassimp-dev assimp-testmodels
  # METIS partitions graphs: the LOD bench groups clusters with it to measure ConeScope's grouping
  libmetis-dev
  # content hashes of meshes, so a batch run again skips what it has done (src/batch/BatchInputs.cpp)
  libxxhash-dev
  xvfb xauth clang libclang-rt-14-dev
  time python3
  # The Python module (python/): pybind11 builds it against Debian's Python; numpy and pandas are
  # its arrays and tables, dask and distributed run batches on many machines, pytest tests it;
  # venv, pip and setuptools install it as a package (pip install --no-build-isolation .).
  pybind11-dev python3-dev python3-numpy python3-pandas python3-dask python3-distributed python3-pytest
  python3-venv python3-pip python3-setuptools
  # The batch report's page test opens report.html in headless chromium.
  chromium
)

missing=()
for package in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$package")
  fi
done

if ((${#missing[@]} == 0)); then
  echo "conescope: all build dependencies are installed"
  exit 0
fi

run_as_root=()
if [[ $(id -u) -ne 0 ]]; then
  command -v sudo >/dev/null || { echo "conescope: need root or sudo to install: ${missing[*]}" >&2; exit 1; }
  run_as_root=(sudo)
fi
echo "conescope: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${run_as_root[@]}" apt-get update -qq
"${run_as_root[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
