#!/usr/bin/env bash
# Preparation and the whole `stats --views 1` run on small and ordinary meshes (15 CGAL demo meshes
# of 2k to 20k triangles and the bundled torus), where runs take a few milliseconds and one run of
# the benchmark moves by a third on a shared machine: conescope-bench-prepare (the default effort
# against meshoptimizer's builder + bounds at cone weight 1, and the whole run against reading the
# same file and running meshoptimizer's builder, bounds and one view), 5 fresh processes each, in
# three rounds over all meshes; a mesh's ratio is the median of its rounds. Writes
# bench/results/small-meshes.md (per mesh, and geometric means).
#
#   scripts/bench-small-meshes.sh
#   CONESCOPE_BENCH_BUILD_DIR=... CONESCOPE_BENCH_OUTPUT=... scripts/bench-small-meshes.sh
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/bench-setup.sh" conescope-bench-prepare

meshes=("$root/datasets/torus.off")
for name in hand head elk knot bones mushroom elephant cow femur homer bull fandisk lion-head camel; do
  meshes+=("$root/datasets/cgal-all/$name.off")
done
runs="$output/small-meshes.runs.tmp"
: > "$runs"
start=$(date +%s)
for round in 1 2 3; do
  for mesh in "${meshes[@]}"; do
    echo "round $round" >> "$runs"
    "$build/bench/conescope-bench-prepare" --mesh "$mesh" --repeat 5 --only optimized-balanced --only meshoptimizer --whole-run >> "$runs"
  done
done
python3 "$root/bench/small_meshes_table.py" "$runs" "$output/small-meshes.md" "$(( $(date +%s) - start ))"
rm -f "$runs"
echo "bench-small-meshes: wrote $output/small-meshes.md" >&2
