#!/usr/bin/env bash
# Peak memory and time of the whole job on a 5,001,600-triangle mesh: read, cluster (default
# builder, cone and test), cull from orbit views and write the statistics, in one conescope-cli run.
# The mesh is a generated torus (1600 x 1563 quads, each split in two), written to the build folder.
#
#   scripts/memory-5m.sh              # default settings, 16 views
#   scripts/memory-5m.sh --builder meshlet --views 64
#
# Prints GNU time's report; "Maximum resident set size" is the peak memory.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${CONESCOPE_BENCH_BUILD_DIR:-$root/build-bench}
mesh=$build/torus-5m.off
"$root/scripts/install-dependencies.sh"  # GNU time and python3 among them
# Always brought up to date (a no-op when it is), so the figures are those of the current source.
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DCONESCOPE_BUILD_GUI=OFF >/dev/null
cmake --build "$build" -j"$(nproc)" --target conescope-cli >/dev/null
if [[ ! -s "$mesh" ]]; then
  echo "memory-5m: writing $mesh" >&2
  python3 - "$mesh" <<'EOF'
import math, sys
rings, tube = 1600, 1563  # 2 * rings * tube = 5,001,600 triangles
with open(sys.argv[1] + ".tmp", "w") as out:
    out.write("OFF\n%d %d 0\n" % (rings * tube, 2 * rings * tube))
    for i in range(rings):
        u = 2 * math.pi * i / rings
        out.write("".join("%.6f %.6f %.6f\n" % ((1 + 0.35 * math.cos(v)) * math.cos(u), (1 + 0.35 * math.cos(v)) * math.sin(u),
                                                  0.35 * math.sin(v))
                          for v in (2 * math.pi * j / tube for j in range(tube))))
    for i in range(rings):
        n = (i + 1) % rings
        out.write("".join("3 %d %d %d\n3 %d %d %d\n" % (i * tube + j, n * tube + j, n * tube + (j + 1) % tube,
                                                        i * tube + j, n * tube + (j + 1) % tube, i * tube + (j + 1) % tube)
                          for j in range(tube)))
import os
os.replace(sys.argv[1] + ".tmp", sys.argv[1])
EOF
fi
args=("$@")
[[ ${#args[@]} -gt 0 ]] || args=(--views 16)
/usr/bin/time -v "$build/src/cli/conescope-cli" stats "$mesh" "${args[@]}" --no-per-view --no-per-cluster -o "$build/torus-5m.json"
python3 -c "import json,sys; d=json.load(open(sys.argv[1])); print('clusters', d['clusters'], [(r['cone'], r['test'], round(r['efficiency'], 3), 'false_culls', r['false_culls']) for r in d['results']])" "$build/torus-5m.json"
