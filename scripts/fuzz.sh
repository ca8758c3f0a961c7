#!/usr/bin/env bash
# Builds the libFuzzer targets with clang (+ AddressSanitizer and UBSan) and runs each one for
# SECONDS (default 60) on a seed corpus made from datasets/ and tests/data/. Findings are written to
# fuzz-out/<target>/ and make the script fail.
#   scripts/fuzz.sh            # a minute per target
#   scripts/fuzz.sh 3600       # the long run
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
seconds=${1:-60}
# CONESCOPE_FUZZ_SEED fixes libFuzzer's random seed (the test command uses 1, so CI is repeatable);
# 0, the default, lets libFuzzer pick one.
seed=${CONESCOPE_FUZZ_SEED:-0}
build=${CONESCOPE_SANITIZE_BUILD_DIR:-$root/build-sanitize}
"$root/scripts/install-dependencies.sh"
CC=clang CXX=clang++ cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCONESCOPE_FUZZ=ON \
  -DCONESCOPE_BUILD_GUI=OFF -DCONESCOPE_BUILD_TESTS=ON -DCONESCOPE_BUILD_BENCH=OFF >/dev/null
targets=(fuzz_off_parser fuzz_mesh_readers fuzz_mesh_ingestion)
cmake --build "$build" -j"$(nproc)" --target "${targets[@]}"

# Leaks inside Debian's VTK are not ours to fix (see the file); every other leak still fails.
export LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$root/fuzz/lsan-suppressions.txt}
out=$root/fuzz-out
mkdir -p "$out"
status=0
for target in "${targets[@]}"; do
  corpus=$out/$target/corpus
  mkdir -p "$corpus"
  case $target in
    fuzz_off_parser) find "$root/datasets" "$root/tests/data" -name '*.off' -size -200k -exec cp {} "$corpus/" \; ;;
    fuzz_mesh_readers)
      # The first byte picks the reader: 0 off, 1 ply, 2 obj, 3 stl, 4 vtp, 5 vtk, 6 gltf, 7 glb,
      # 8 and 9 meshlet files (JSON, binary) on the target's own grid (tests/data/meshlets), 10 and
      # 11 hierarchy files (JSON, binary) of the same grid.
      # (A .gltf seed whose buffer is a file beside it has no such file in the fuzzer's folder; the
      # embedded ones and the .glb carry their data.)
      index=0
      for extension in off ply obj stl vtp vtk gltf glb json meshlets; do
        while IFS= read -r -d '' file; do
          { printf "\\x$(printf %02x $index)"; cat "$file"; } > "$corpus/$(basename "$file").seed"
        done < <(find "$root/datasets" "$root/tests/data" -name "*.$extension" -size -200k -print0)
        index=$((index + 1))
      done
      for seed in 10:grid-hierarchy.json 11:grid-hierarchy.lod; do
        { printf "\\x$(printf %02x "${seed%%:*}")"; cat "$root/tests/data/meshlets/${seed#*:}"; } > "$corpus/${seed#*:}.hierarchy.seed"
      done ;;
    fuzz_mesh_ingestion)
      # The target reads raw bytes as counts, floats and indices: the first 4 KB of each bundled
      # mesh make varied, reproducible seeds.
      for file in "$root"/datasets/*.off "$root"/datasets/*.vtp; do
        head -c 4096 "$file" > "$corpus/$(basename "$file").seed"
      done ;;
  esac
  # Inputs that once crashed a target stay in its corpus, so every run replays them first.
  find "$root/fuzz/regressions" -name "$target-*" -exec cp {} "$corpus/" \;
  echo "conescope: fuzzing $target for ${seconds}s"
  if ! (cd "$out/$target" && "$build/fuzz/$target" -max_total_time="$seconds" -rss_limit_mb=2048 -timeout=20 -seed="$seed" \
         -max_len=65536 -print_final_stats=1 "$corpus" 2>"$out/$target/log.txt"); then
    echo "conescope: $target found a problem; see $out/$target/log.txt and the crash-* files there" >&2
    tail -40 "$out/$target/log.txt" >&2
    status=1
  else
    grep -E "stat::number_of_executed_units|stat::peak_rss_mb" "$out/$target/log.txt" | sed "s/^/  /"
  fi
done
exit $status
