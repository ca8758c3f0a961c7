#!/usr/bin/env bash
# This build's default and best effort against an earlier build's default, at equal counts, and both
# against meshoptimizer's pipeline (bench/earlier_table.py): 64 orbit views, distance 3, limits 64/124.
# EARLIER is the earlier build's conescope-cli (build one with `git worktree add`), or a CSV this
# script wrote before (its earlier columns are reused). LIST: mesh paths, one a line (for instance
# the props of scripts/bench-props.sh, or datasets/cgal-all/*.off). Writes bench/results/NAME.{csv,md}.
#
#   scripts/bench-earlier.sh ../earlier/build/src/cli/conescope-cli props.list earlier-props "Props"
set -euo pipefail
[[ $# -eq 4 ]] || { echo "usage: $0 EARLIER LIST NAME TITLE" >&2; exit 2; }
source "$(dirname "${BASH_SOURCE[0]}")/bench-setup.sh" conescope-cli
start=$(date +%s)
/usr/bin/python3 "$root/bench/earlier_table.py" "$build/src/cli/conescope-cli" "$1" "$2" "$output/$3" "$4"
echo "bench-earlier: wrote $output/$3.{csv,md} in $(( $(date +%s) - start )) s" >&2
