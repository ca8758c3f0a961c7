#!/usr/bin/env bash
# One command for the test suite: installs what is missing, builds, runs every test with ctest,
# then builds the core, readers and CLI again with AddressSanitizer + UBSan (clang), runs their
# tests under the sanitizers and gives each libFuzzer target a short run (scripts/sanitize.sh).
# Rendering and GUI tests start their own Xvfb through xvfb-run.
#   scripts/test.sh              # everything (what CI runs)
#   scripts/test.sh -L core      # ctest arguments select tests; the sanitizer stage is then left out
# CONESCOPE_FUZZ_SECONDS (default 15) sets the fuzzing time per target.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$root/scripts/install-dependencies.sh"
"$root/scripts/build.sh"
build=${CONESCOPE_BUILD_DIR:-$root/build}
(cd "$build" && ctest --output-on-failure -j2 "$@")
if [[ $# -eq 0 ]]; then
  CONESCOPE_FUZZ_SEED=${CONESCOPE_FUZZ_SEED:-1} "$root/scripts/sanitize.sh" "${CONESCOPE_FUZZ_SECONDS:-15}"
fi
