#!/usr/bin/env bash
# The default pipeline at budgets from 0.8x to 1.2x meshoptimizer's count (nine steps of 0.05) on
# every CGAL demo mesh, beside meshoptimizer's own curve: its pipeline (builder at cone weight 1, its
# cone, apex) with its count moved by its vertex limit (53 to 80; other limits, so a reference for
# the shape of the curve, not an equal-limits comparison). 64 orbit views at distance 3. Flags a
# made count above the asked one (said with a warning: the limits allow no fewer) and a cliff: less
# culled at a larger made count than at the step before. Writes bench/results/budget-sweep.{csv,md}.
#
#   scripts/bench-budget-sweep.sh                 # every mesh of datasets/cgal-all
#   scripts/bench-budget-sweep.sh MESH...         # these meshes
#   CONESCOPE_BENCH_BUILD_DIR=... CONESCOPE_BENCH_OUTPUT=... scripts/bench-budget-sweep.sh
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/bench-setup.sh" conescope-cli
meshes=("$@")
if [[ ${#meshes[@]} -eq 0 ]]; then
  meshes=("$root"/datasets/cgal-all/*.off "$root"/datasets/cgal-all/*.ply "$root"/datasets/cgal-all/*.stl)
fi
start=$(date +%s)
/usr/bin/python3 "$root/bench/budget_sweep.py" "$build/src/cli/conescope-cli" "$output/budget-sweep" "${meshes[@]}"
echo "bench-budget-sweep: wrote $output/budget-sweep.{csv,md} in $(( $(date +%s) - start )) s" >&2
