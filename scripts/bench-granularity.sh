#!/usr/bin/env bash
# What each record granularity culls and costs (`conescope-cli granularity`: one cone per cluster
# with every test, 2, 4 and 8 cones per cluster as float and compact records, per-triangle culling)
# on every CGAL demo mesh that reads and every Sweet Home 3D furniture prop, 64 orbit views at
# distance 3, the default partition. Writes bench/results/granularity.csv (one row per mesh and
# record) and granularity.md (per set and record: culled share, ratio to the default record,
# bytes, tests per view, false culls).
#
#   scripts/bench-granularity.sh
#   CONESCOPE_PROPS_DEBS=/dir/with/debs CONESCOPE_BENCH_BUILD_DIR=... scripts/bench-granularity.sh
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/bench-setup.sh" conescope-cli
bench_record_table granularity granularity_table.py
