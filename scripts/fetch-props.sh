#!/usr/bin/env bash
# Real props from Debian packages, unpacked once into datasets/props-debian: Sweet Home 3D's
# furniture OBJ files (sweethome3d-furniture) and Trigger Rally's cars and wheels
# (trigger-rally-data). Used by bench-props.sh and by bench-setup.sh's bench_mesh_list (the
# granularity and cones-partition benches).
#
#   scripts/fetch-props.sh                                 # apt-get download, once
#   CONESCOPE_PROPS_DEBS=/dir/with/debs scripts/fetch-props.sh   # offline, from .deb files there
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
props="$root/datasets/props-debian"
if [[ ! -f "$props/.complete" ]]; then
  debs=${CONESCOPE_PROPS_DEBS:-$props/debs}
  mkdir -p "$debs" "$props"
  for package in sweethome3d-furniture trigger-rally-data; do
    ls "$debs"/${package}_*.deb >/dev/null 2>&1 || (cd "$debs" && apt-get download "$package")
    dpkg-deb -x "$(ls "$debs"/${package}_*.deb | head -1)" "$props/unpacked"
  done
  for sh3f in "$props"/unpacked/usr/share/sweethome3d/furniture/*.sh3f; do
    mkdir -p "$props/sh3d/$(basename "$sh3f" .sh3f)"
    unzip -o -q "$sh3f" '*.obj' -d "$props/sh3d/$(basename "$sh3f" .sh3f)"
  done
  mkdir -p "$props/trigger"
  unzip -o -q "$props/unpacked/usr/share/games/trigger-rally/data.zip" 'vehicles/*.obj' -d "$props/trigger" || true
  rm -rf "$props/unpacked"
  touch "$props/.complete"
fi
