#!/usr/bin/env bash
# The default pipeline, and each effort level, against meshoptimizer's (builder, cone and apex test
# at cone weight 1) on every mesh of CGAL's demo data that reads (and assimp's multi-part Wuson),
# through `conescope-cli compare`: the same mesh, the same 64 orbit views at distance 3, limits
# 64/124. The default budget is meshoptimizer's own count, so the partitions have equal counts (the
# compare warns otherwise). meshoptimizer's partition at cone weight 0.25 is measured too, for its
# bounding spheres. Writes bench/results/all-meshes.csv (one row per mesh) and all-meshes.md (the
# table, geometric means, the meshes where we lose, sphere radii).
#
#   scripts/bench-all-meshes.sh                 # fetches the meshes (datasets/cgal-all), builds, runs
#   CONESCOPE_BENCH_BUILD_DIR=... CONESCOPE_BENCH_OUTPUT=... scripts/bench-all-meshes.sh
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/bench-setup.sh" conescope-cli
cli="$build/src/cli/conescope-cli"

rows="$output/all-meshes.json.tmp"
: > "$rows"
start=$(date +%s)
common=(--views 64 --distance 3 --no-per-view --no-per-cluster --format json -q)
# Plus assimp's Wuson, a game asset of 54 separate pieces (assimp-testmodels, installed with the
# other dependencies), where it is installed.
for mesh in "$root"/datasets/cgal-all/*.off "$root"/datasets/cgal-all/*.ply "$root"/datasets/cgal-all/*.stl \
            /usr/share/assimp/models/OFF/Wuson.off; do
  [[ -f "$mesh" ]] || continue
  # One JSON line per mesh: the comparison at each effort level (the default is balanced) and
  # meshoptimizer's cone weight 0.25 partition; a mesh that does not read is listed with its error.
  line="{\"mesh\": \"$(basename "$mesh")\""
  failed=""
  for effort in fast balanced best; do
    if json=$("$cli" compare "$mesh" --a builder=meshopt,cone=meshopt,test=apex --b "effort=$effort" "${common[@]}" 2>"$rows.err"); then
      line+=", \"$effort\": $json"
    else
      failed=$(tail -1 "$rows.err")
      break
    fi
  done
  if [[ -z "$failed" ]] && json=$("$cli" stats "$mesh" --builder meshopt --cone meshopt --cone-weight 0.25 --test apex "${common[@]}" 2>"$rows.err"); then
    line+=", \"meshopt_cw025\": $json}"
    python3 -c 'import json,sys; print(json.dumps(json.loads(sys.stdin.read())))' <<< "$line" >> "$rows"
  else
    [[ -n "$failed" ]] || failed=$(tail -1 "$rows.err")
    python3 -c 'import json,sys; print(json.dumps({"mesh": sys.argv[1], "error": sys.argv[2]}))' "$(basename "$mesh")" "$failed" >> "$rows"
  fi
done
rm -f "$rows.err"
python3 "$root/bench/all_meshes_table.py" "$rows" "$output/all-meshes.csv" "$output/all-meshes.md" "$(( $(date +%s) - start ))"
rm -f "$rows"
echo "bench-all-meshes: wrote $output/all-meshes.{csv,md}" >&2
