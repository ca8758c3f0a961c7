#!/usr/bin/env bash
# Whether a partition built for K cones per cluster (`--cones-per-cluster K`) beats the default partition split
# into K sub-groups afterwards, on every CGAL demo mesh that reads and every Sweet Home 3D furniture
# prop: bench/results/cones-partition.{csv,md}.
#
#   scripts/bench-cones-partition.sh
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/bench-setup.sh" conescope-cli
bench_record_table cones-partition cones_partition_table.py
