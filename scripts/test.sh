#!/usr/bin/env bash
# One command for the test suite: installs what is missing, builds, and runs every test with ctest.
# Rendering and GUI tests start their own Xvfb through xvfb-run.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$root/scripts/install-dependencies.sh"
"$root/scripts/build.sh"
build=${CONESCOPE_BUILD_DIR:-$root/build}
cd "$build"
ctest --output-on-failure -j2 "$@"
