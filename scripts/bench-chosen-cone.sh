#!/usr/bin/env bash
# The chosen cone (the default) against the minimal one on the same partitions, at 128 and 64
# views: every CGAL demo mesh that reads and the props of tests/data/props
# (bench/chosen_cone_table.py). Writes bench/results/chosen-cone.{csv,md}.
#
#   scripts/bench-chosen-cone.sh
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/bench-setup.sh" conescope-cli
list="$output/chosen-cone.list.tmp"
start=$(date +%s)
: > "$list"
for mesh in "$root"/datasets/cgal-all/*.off "$root"/datasets/cgal-all/*.ply; do [[ -f "$mesh" ]] && echo "cgal $mesh" >> "$list"; done
for mesh in "$root"/tests/data/props/*.obj; do echo "props $mesh" >> "$list"; done
python3 "$root/bench/chosen_cone_table.py" "$build/src/cli/conescope-cli" "$list" "$output/chosen-cone" "$root"
rm -f "$list"
echo "bench-chosen-cone: wrote $output/chosen-cone.{csv,md} in $(( $(date +%s) - start )) s" >&2
