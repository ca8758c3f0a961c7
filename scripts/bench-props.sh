#!/usr/bin/env bash
# The defaults against meshoptimizer's pipeline (builder at cone weight 1, its cone, apex test) on
# real props from Debian packages and double-sided meshes made here, through `conescope-cli
# compare` at 64 orbit views, distance 3, limits 64/124: Sweet Home 3D's 820 furniture OBJ files
# (sweethome3d-furniture) and Trigger Rally's 18 cars and wheels (trigger-rally-data), and each
# bundled mesh with every triangle followed by its reverse. Each mesh falls in the sets it belongs
# to: polygon (faces of more than 3 corners), many-part (100 or more components), small prop (35
# clusters or fewer), double-sided (report.double_sided_faces > 0). Writes bench/results/props.csv
# (one row per mesh) and props.md (per set: meshes, wins, losses, ties, more clusters, culls none
# where meshoptimizer culls some, geometric mean of the ratio; then every loss).
#
#   scripts/bench-props.sh                          # downloads the two packages once (apt-get download)
#   CONESCOPE_PROPS_DEBS=/dir/with/debs scripts/bench-props.sh   # offline, from .deb files there
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/bench-setup.sh" conescope-cli
props="$root/datasets/props-debian"
"$root/scripts/fetch-props.sh"
# Double-sided copies of the bundled meshes: each triangle followed by its reverse.
doubled="$props/double-sided"
mkdir -p "$doubled"
for mesh in "$root"/datasets/*.off; do
  /usr/bin/python3 - "$mesh" "$doubled/$(basename "$mesh" .off)-double-sided.off" <<'PY'
import sys
words = [w for line in open(sys.argv[1]) for w in line.split('#')[0].split()]
vertices, faces = int(words[1]), int(words[2])
numbers, at = words[4:], 0
points = [numbers[3 * i:3 * i + 3] for i in range(vertices)]
at = 3 * vertices
polygons = []
for _ in range(faces):
    n = int(numbers[at]); polygons.append(numbers[at + 1:at + 1 + n]); at += 1 + n
with open(sys.argv[2], "w") as out:
    out.write(f"OFF\n{vertices} {2 * faces} 0\n")
    out.writelines(" ".join(p) + "\n" for p in points)
    for face in polygons:
        out.write(f"{len(face)} {' '.join(face)}\n{len(face)} {' '.join(reversed(face))}\n")
PY
done
start=$(date +%s)
find "$props/sh3d" "$props/trigger" "$doubled" \( -name '*.obj' -o -name '*.off' \) | sort > "$output/props.list.tmp"
/usr/bin/python3 "$root/bench/props_table.py" "$build/src/cli/conescope-cli" "$output/props.list.tmp" "$output/props"
rm -f "$output/props.list.tmp"
echo "bench-props: wrote $output/props.{csv,md} in $(( $(date +%s) - start )) s" >&2
