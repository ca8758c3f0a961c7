#!/usr/bin/env bash
# The AddressSanitizer + UndefinedBehaviorSanitizer build (clang): builds the core, readers, CLI and
# their tests with the sanitizers, runs those tests, then gives each libFuzzer target a short run.
#   scripts/sanitize.sh          # 20 s per fuzz target
#   scripts/sanitize.sh 300      # longer fuzzing
# The rendering and GUI layers are left out: Debian's VTK and Qt are not built with the sanitizers
# and their own start-up reports would drown ours.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
seconds=${1:-20}
build=${CONESCOPE_SANITIZE_BUILD_DIR:-$root/build-sanitize}
"$root/scripts/install-dependencies.sh"
CC=clang CXX=clang++ cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCONESCOPE_FUZZ=ON \
  -DCONESCOPE_BUILD_GUI=OFF -DCONESCOPE_BUILD_TESTS=ON -DCONESCOPE_BUILD_BENCH=OFF >/dev/null
cmake --build "$build" -j"$(nproc)"
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1}
# use_tls=0: the leak checker's thread that walks the threads' dynamic TLS crashes ("Tracer caught
# signal 11") once a VTK format module has been opened; without TLS as roots it can only report more.
export LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$root/fuzz/lsan-suppressions.txt:use_tls=0:print_suppressions=0}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
(cd "$build" && ctest --output-on-failure -j2 -L 'core|io|cli')
CONESCOPE_SANITIZE_BUILD_DIR=$build "$root/scripts/fuzz.sh" "$seconds"
