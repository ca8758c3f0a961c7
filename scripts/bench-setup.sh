# Sourced by the benchmark scripts that run on every CGAL demo mesh (bench-all-meshes.sh,
# bench-small-meshes.sh, ...): sets root, build (CONESCOPE_BENCH_BUILD_DIR, default build-bench) and
# output (CONESCOPE_BENCH_OUTPUT, default bench/results), fetches every mesh, and builds the targets
# given as arguments. A new build directory is made in Release without the GUI; an existing one is
# used as it is. bench_record_table runs the record benches (granularity, cones-partition) on one
# mesh list, bench_mesh_list's.
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${CONESCOPE_BENCH_BUILD_DIR:-$root/build-bench}
output=${CONESCOPE_BENCH_OUTPUT:-$root/bench/results}
"$root/scripts/fetch-datasets.sh" --all
[[ -f "$build/CMakeCache.txt" ]] || cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DCONESCOPE_BUILD_GUI=OFF >/dev/null
cmake --build "$build" -j"$(nproc)" --target "$@" >/dev/null
mkdir -p "$output"

# Writes to FILE the meshes the record benches run on, a line "SET PATH" each: every CGAL demo mesh
# (.off, .ply), then every Sweet Home 3D furniture prop (fetched here), sorted.
bench_mesh_list() {
  local list=$1 mesh
  "$root/scripts/fetch-props.sh"
  : > "$list"
  for mesh in "$root"/datasets/cgal-all/*.off "$root"/datasets/cgal-all/*.ply; do [[ -f "$mesh" ]] && echo "cgal $mesh" >> "$list"; done
  find "$root/datasets/props-debian/sh3d" -name '*.obj' | sort | sed 's/^/props /' >> "$list"
}

# Runs bench/TABLE (a Python table script: conescope-cli, the mesh list, the output stem, the root) on
# bench_mesh_list's meshes, writing $output/NAME.{csv,md}, and says how long it took.
bench_record_table() {
  local name=$1 table=$2 list="$output/$1.list.tmp" start
  bench_mesh_list "$list"
  start=$(date +%s)
  python3 "$root/bench/$table" "$build/src/cli/conescope-cli" "$list" "$output/$name" "$root"
  rm -f "$list"
  echo "bench-$name: wrote $output/$name.{csv,md} in $(( $(date +%s) - start )) s" >&2
}
