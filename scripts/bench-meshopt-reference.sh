#!/usr/bin/env bash
# The engine tests against meshoptimizer's own loop (tests/reference/meshopt_reference, which links
# only the library): for CGAL's elephant, bunny00, armadillo and the other meshes of datasets/cgal,
# meshoptimizer 0.18's meshlets at cone weight 1 (limits 64/124) written as a meshlet JSON with
# bounds and as an OBJ with an object per meshlet, read back by conescope-cli and scored with
# meshopt-apex-f32 and meshopt-sphere-s8 over 64 orbit views at distance 3. Writes
# bench/results/meshopt-reference.md (cluster counts, both efficiencies, the largest difference).
#
#   scripts/bench-meshopt-reference.sh        # fetches datasets/cgal, builds the two programs, runs (~20 s)
#   CONESCOPE_BENCH_BUILD_DIR=build scripts/bench-meshopt-reference.sh   # with an existing build
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${CONESCOPE_BENCH_BUILD_DIR:-$root/build-bench}
output=${CONESCOPE_BENCH_OUTPUT:-$root/bench/results}
"$root/scripts/fetch-datasets.sh"
[[ -f "$build/CMakeCache.txt" ]] || cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DCONESCOPE_BUILD_GUI=OFF >/dev/null
cmake --build "$build" -j"$(nproc)" --target conescope-cli meshopt_reference >/dev/null
mkdir -p "$output"
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

rows="$scratch/rows.json"
: > "$rows"
views=(--views 64 --distance 3)
for mesh in "$root/datasets/elephant.off" "$root"/datasets/cgal/*.off; do
  "$build/tests/reference/meshopt_reference" "$mesh" "${views[@]}" --json "$scratch/m.json" --obj "$scratch/m.obj" > "$scratch/reference.json"
  for input in json obj; do
    arguments=("$mesh" --cluster-file "$scratch/m.json")
    [[ $input == obj ]] && arguments=("$scratch/m.obj")
    "$build/src/cli/conescope-cli" stats "${arguments[@]}" --builder file --test meshopt-apex-f32,meshopt-sphere-s8 "${views[@]}" \
      --no-per-view --no-per-cluster --format json -q > "$scratch/$input.json"
  done
  /usr/bin/python3 -c 'import json, sys; print(json.dumps({"mesh": sys.argv[1], "reference": json.load(open(sys.argv[2])),
    "json": json.load(open(sys.argv[3])), "obj": json.load(open(sys.argv[4]))}))' \
    "$(basename "$mesh")" "$scratch/reference.json" "$scratch/json.json" "$scratch/obj.json" >> "$rows"
done
/usr/bin/python3 "$root/bench/meshopt_reference_table.py" "$rows" "$output/meshopt-reference.md"
echo "bench-meshopt-reference: wrote $output/meshopt-reference.md" >&2
