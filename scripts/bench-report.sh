#!/usr/bin/env bash
# One command for the benchmarks: fetches the CGAL meshes if missing, builds the benchmark programs
# in Release, and writes bench/results/:
#   report.csv      every (mesh, builder, budget, cone, test, distance) row, with meshoptimizer's own pipeline
#   report.md       the summary: per mesh against meshoptimizer's apex test, geometric means, targets
#   summary.csv     the per-mesh numbers behind the plot
#   efficiency.png  bar chart of efficiency per mesh (VTK charts under xvfb-run)
#   speed.txt       Google Benchmark: ns per cluster per test (scalar core, batched SIMD, meshoptimizer's
#                   loop) and preparation time for a >= 1M-triangle mesh
#   prepare.txt     preparation against meshoptimizer's at 2k to 3.3M triangles (median of 5 runs, each
#                   effort level, peak memory, expected cull rate) and the whole stats run at 5k, 52k and 1.2M
#   records.md      bytes per cluster and culling per byte of every test's record (and records.csv)
#   meshopt-reference.md  the engine tests against meshoptimizer's own loop on its meshlet files
#                   (scripts/bench-meshopt-reference.sh)
#   small-meshes.md the default's preparation and whole run against meshoptimizer's on 15 meshes of 2k
#                   to 20k triangles, three rounds (scripts/bench-small-meshes.sh; not in the quick run)
#   polygon-speed.txt  the whole stats run against meshoptimizer's on 8 polygon props of 50k to 200k
#                   triangles (scripts/bench-polygon-speed.sh; once scripts/bench-props.sh has fetched them;
#                   not in the quick run)
#
#   scripts/bench-report.sh            # full run (see docs/benchmarks.md for its duration)
#   scripts/bench-report.sh --quick    # one budget, one distance, cull timings on the real mesh only
#
# Environment: CONESCOPE_BENCH_BUILD_DIR (default build-bench), CONESCOPE_BENCH_OUTPUT (default bench/results).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${CONESCOPE_BENCH_BUILD_DIR:-$root/build-bench}
output=${CONESCOPE_BENCH_OUTPUT:-$root/bench/results}
quick=0
for argument in "$@"; do
  case "$argument" in
    --quick) quick=1 ;;
    *) echo "bench-report: unknown argument '$argument' (expected --quick)" >&2; exit 2 ;;
  esac
done

"$root/scripts/fetch-datasets.sh"

cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DCONESCOPE_BUILD_GUI=OFF >/dev/null
cmake --build "$build" -j"$(nproc)" --target conescope-bench-report conescope-bench-plot conescope-bench-speed conescope-bench-prepare \
  conescope-bench-records
bin="$build/bench"
mkdir -p "$output"

report_flags=()
speed_flags=()
if [[ $quick -eq 1 ]]; then
  report_flags+=(--quick)
  speed_flags+=(--benchmark_filter='^cull/.*/mesh$' --benchmark_min_time=0.05)
fi

start=$(date +%s)
# The timings of a few milliseconds first: this machine runs them a few percent slower right after
# minutes of full load on both cores (docs/benchmarks.md), which the report and the cull speed are.
# Preparation against meshoptimizer, median of 5 runs each (in rounds of every configuration), at about 2k, 5k and 13k triangles (the
# bundled torus, elephant and fandisk), 20k, 50k and 90k (CGAL's camel, armadillo, refined_elephant
# as they are), 1.2M (bunny00 subdivided twice) and 3.3M (armadillo three times); the whole stats
# run at 5k, 52k and 1.2M. The quick run takes one size.
{
  echo "# $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ //'), $(nproc) cores"
  if [[ $quick -eq 1 ]]; then
    "$bin/conescope-bench-prepare" --mesh "$root/datasets/cgal/camel.off" --repeat 3 --only optimized-fast \
      --only optimized-balanced --only meshoptimizer
  else
    for mesh in torus elephant fandisk; do
      whole=()
      [[ $mesh == elephant ]] && whole=(--whole-run)
      "$bin/conescope-bench-prepare" --mesh "$root/datasets/$mesh.off" --only optimized-fast --only optimized-balanced \
        --only optimized-best --only meshlet --only meshopt --only meshoptimizer "${whole[@]}"
      echo
    done
    for mesh in camel armadillo refined_elephant; do
      whole=()
      [[ $mesh == armadillo ]] && whole=(--whole-run)
      "$bin/conescope-bench-prepare" --mesh "$root/datasets/cgal/$mesh.off" "${whole[@]}"
      echo
    done
    "$bin/conescope-bench-prepare" --mesh "$root/datasets/cgal/bunny00.off" --min-triangles 1000000 --whole-run \
      --only optimized-fast --only optimized-balanced --only optimized-best --only meshlet --only meshoptimizer
    echo
    "$bin/conescope-bench-prepare" --mesh "$root/datasets/cgal/armadillo.off" --min-triangles 3000000 \
      --only optimized-fast --only optimized-balanced --only meshlet --only meshoptimizer
  fi
} > "$output/prepare.txt" 2>&1
if [[ $quick -eq 0 ]]; then
  CONESCOPE_BENCH_BUILD_DIR="$build" CONESCOPE_BENCH_OUTPUT="$output" "$root/scripts/bench-small-meshes.sh"
  if [[ -d "$root/datasets/props-debian/sh3d" ]]; then
    CONESCOPE_BENCH_BUILD_DIR="$build" CONESCOPE_BENCH_OUTPUT="$output" "$root/scripts/bench-polygon-speed.sh"
  else
    echo "bench-report: no polygon props yet (scripts/bench-props.sh fetches them): polygon-speed.txt not written" >&2
  fi
fi
echo "bench-report: preparation and small meshes took $(( $(date +%s) - start )) s" >&2

# From the source directory, so that the command the report records reads the same on every machine.
(cd "$root" && "$bin/conescope-bench-report" --meshes datasets/cgal --output "$(realpath --relative-to="$root" "$output")" \
  --jobs "$(nproc)" "${report_flags[@]}")
echo "bench-report: report took $(( $(date +%s) - start )) s" >&2

# Bytes per cluster and culling per byte of every test's record; the quick run on one mesh.
records_meshes=datasets/cgal
[[ $quick -eq 1 ]] && records_meshes=datasets/cgal/camel.off
(cd "$root" && "$bin/conescope-bench-records" --meshes "$records_meshes" --output "$(realpath --relative-to="$root" "$output")")
echo "bench-report: records took $(( $(date +%s) - start )) s" >&2
CONESCOPE_BENCH_BUILD_DIR="$build" CONESCOPE_BENCH_OUTPUT="$output" "$root/scripts/bench-meshopt-reference.sh" >/dev/null

xvfb-run -a -s "-screen 0 1600x1000x24" "$bin/conescope-bench-plot" "$output/summary.csv" "$output/efficiency.png"

{
  echo "# $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ //'), $(nproc) cores"
  "$bin/conescope-bench-speed" "${speed_flags[@]}"
} > "$output/speed.txt" 2>&1
echo "bench-report: cull speed took $(( $(date +%s) - start )) s" >&2

echo "bench-report: wrote $output/{report.csv,report.md,summary.csv,efficiency.png,speed.txt,prepare.txt,records.md,meshopt-reference.md} in $(( $(date +%s) - start )) s" >&2
