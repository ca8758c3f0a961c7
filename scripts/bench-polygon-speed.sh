#!/usr/bin/env bash
# The whole `conescope-cli stats --views 1` run against reading the same file and running
# meshoptimizer's builder, bounds and one view (conescope-bench-prepare --whole-run, median of 5
# fresh processes in rounds) on polygon and many-part props of 50k to 200k triangles from Sweet
# Home 3D's furniture (scripts/bench-props.sh fetches them into datasets/props-debian). Writes
# bench/results/polygon-speed.txt.
#
#   scripts/bench-polygon-speed.sh
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/bench-setup.sh" conescope-bench-prepare
sh3d="$root/datasets/props-debian/sh3d"
[[ -d "$sh3d" ]] || { echo "bench-polygon-speed: run scripts/bench-props.sh first (it fetches $sh3d)" >&2; exit 1; }
# Triangles (fans of polygons), faces, polygons and components: from 50k to 200k triangles, most of them polygons.
meshes=(BlendSwap-CC-0/kitchenaid/kitchenaid BlendSwap-CC-0/L_shaped_sofa/L_shaped_sofa Scopia/acacia/acacia
        BlendSwap-CC-0/peterbilt/peterbilt BlendSwap-CC-BY/chessboard/chessboard BlendSwap-CC-BY/white_lily/white_lily
        Scopia/copperBeech/copperBeech Scopia/japaneseMaple/japaneseMaple)
for mesh in "${meshes[@]}"; do
  collection=${mesh%%/*}
  file="$sh3d/$collection/$(echo "$collection" | tr '[:upper:]' '[:lower:]')/${mesh#*/}.obj"
  "$build/bench/conescope-bench-prepare" --mesh "$file" --whole-run --only optimized-balanced --repeat 5
done > "$output/polygon-speed.txt" 2>&1
grep -E "^mesh:|^\| read \+ conescope" "$output/polygon-speed.txt" >&2
echo "bench-polygon-speed: wrote $output/polygon-speed.txt" >&2
