#!/usr/bin/env bash
# Cone culling level by level of a cluster LOD hierarchy (`conescope-cli lod`, default builder, cone
# and test) on every mesh of CGAL's demo data that reads: per level its clusters, triangles, mean cone
# half-angle and efficiency over 64 orbit views at distance 3, with one cone per cluster and with four
# (`--cones 4`), and the cut at 1 pixel (1080 pixels high, 60 degrees). Writes
# bench/results/lod-levels.csv (one row per mesh and level, and the cut) and lod-levels.md (the
# table, how much of level 0's culling each level keeps with each record), and lod-grouping.md
# (the hierarchy's grouping against METIS's, bench/lod_grouping.cpp).
#
#   scripts/bench-lod.sh                        # fetches the meshes (datasets/cgal-all), builds, runs
#   CONESCOPE_BENCH_BUILD_DIR=... CONESCOPE_BENCH_OUTPUT=... scripts/bench-lod.sh
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/bench-setup.sh" conescope-cli conescope-bench-lod-grouping
cli="$build/src/cli/conescope-cli"

rows="$output/lod-levels.json.tmp"
: > "$rows"
start=$(date +%s)
for mesh in "$root"/datasets/cgal-all/*.off "$root"/datasets/cgal-all/*.ply "$root"/datasets/cgal-all/*.stl; do
  [[ -f "$mesh" ]] || continue
  # One JSON line per mesh; a mesh that does not read is listed with its error.
  if json=$("$cli" lod "$mesh" --views 64 --distance 3 --threshold 1 --cones 4 --no-per-view --format json -q 2>"$rows.err"); then
    python3 -c 'import json,sys; d=json.loads(sys.stdin.read()); d["mesh"]=sys.argv[1]; print(json.dumps(d))' "$(basename "$mesh")" <<< "$json" >> "$rows"
  else
    python3 -c 'import json,sys; print(json.dumps({"mesh": sys.argv[1], "error": sys.argv[2]}))' "$(basename "$mesh")" "$(tail -1 "$rows.err" | sed "s|$root/||g")" >> "$rows"
  fi
done
rm -f "$rows.err"
python3 "$root/bench/lod_table.py" "$rows" "$output/lod-levels.csv" "$output/lod-levels.md" "$(( $(date +%s) - start ))"
rm -f "$rows"
# The grouping against METIS's on the same meshes.
"$build/bench/conescope-bench-lod-grouping" --meshes "$root/datasets/cgal-all" --views 64 --output "$output/lod-grouping.md"
echo "bench-lod: wrote $output/lod-levels.{csv,md} and lod-grouping.md" >&2
