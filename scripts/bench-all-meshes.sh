#!/usr/bin/env bash
# The default pipeline against meshoptimizer's (builder, cone and apex test at cone weight 1) on every
# mesh of CGAL's demo data that reads (and assimp's multi-part Wuson), through `conescope-cli compare`: the same mesh, the same 64
# orbit views at distance 3, limits 64/124. The default budget is meshoptimizer's own count, so the
# two partitions have equal counts (the compare warns otherwise). Writes bench/results/all-meshes.csv
# (one row per mesh) and all-meshes.md (the table, geometric means, the meshes where we lose).
#
#   scripts/bench-all-meshes.sh                 # fetches the meshes (datasets/cgal-all), builds, runs
#   CONESCOPE_BENCH_BUILD_DIR=... CONESCOPE_BENCH_OUTPUT=... scripts/bench-all-meshes.sh
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${CONESCOPE_BENCH_BUILD_DIR:-$root/build-bench}
output=${CONESCOPE_BENCH_OUTPUT:-$root/bench/results}

"$root/scripts/fetch-datasets.sh" --all
# A new build directory is made in Release without the GUI; an existing one is used as it is.
[[ -f "$build/CMakeCache.txt" ]] || cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DCONESCOPE_BUILD_GUI=OFF >/dev/null
cmake --build "$build" -j"$(nproc)" --target conescope-cli >/dev/null
cli="$build/src/cli/conescope-cli"
mkdir -p "$output"

rows="$output/all-meshes.json.tmp"
: > "$rows"
start=$(date +%s)
# Plus assimp's Wuson, a game asset of 54 separate pieces (assimp-testmodels, installed with the
# other dependencies), where it is installed.
for mesh in "$root"/datasets/cgal-all/*.off "$root"/datasets/cgal-all/*.ply "$root"/datasets/cgal-all/*.stl \
            /usr/share/assimp/models/OFF/Wuson.off; do
  [[ -f "$mesh" ]] || continue
  # One JSON line per mesh; a mesh that does not read (or has no back faces to cull) is listed with its error.
  if json=$("$cli" compare "$mesh" --a builder=meshopt,cone=meshopt --b "" --views 64 --distance 3 \
              --no-per-view --no-per-cluster --format json -q 2>"$rows.err"); then
    python3 -c 'import json,sys; d=json.load(sys.stdin); print(json.dumps({"mesh": sys.argv[1], "triangles": d["a"]["mesh"]["triangles"], "components": d["a"]["mesh"]["report"]["components"], "diff": {k: v for k, v in d["diff"].items() if k != "views"}, "radius_a": d["a"]["results"][0]["mean_sphere_radius"], "radius_b": d["b"]["results"][0]["mean_sphere_radius"], "oracle_b": d["b"]["results"][0]["oracle_fraction"], "cull_b": d["b"]["results"][0]["cull_fraction"]}))' "$(basename "$mesh")" <<< "$json" >> "$rows"
  else
    python3 -c 'import json,sys; print(json.dumps({"mesh": sys.argv[1], "error": sys.argv[2]}))' "$(basename "$mesh")" "$(tail -1 "$rows.err")" >> "$rows"
  fi
done
rm -f "$rows.err"
python3 "$root/bench/all_meshes_table.py" "$rows" "$output/all-meshes.csv" "$output/all-meshes.md" "$(( $(date +%s) - start ))"
rm -f "$rows"
echo "bench-all-meshes: wrote $output/all-meshes.{csv,md}" >&2
