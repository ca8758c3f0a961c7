#!/usr/bin/env bash
# Whether a partition built for K cones per cluster (`--cones-per-cluster K`) beats the default partition split
# into K sub-groups afterwards, on every CGAL demo mesh that reads and every Sweet Home 3D furniture
# prop: bench/results/cones-partition.{csv,md}.
#
#   scripts/bench-cones-partition.sh
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/bench-setup.sh" conescope-cli
cli="$build/src/cli/conescope-cli"
list="$output/cones-partition.list.tmp"
bench_mesh_list "$list"
start=$(date +%s)
python3 "$root/bench/cones_partition_table.py" "$cli" "$list" "$output/cones-partition" "$root"
rm -f "$list"
echo "bench-cones-partition: wrote $output/cones-partition.{csv,md} in $(( $(date +%s) - start )) s" >&2
