#!/usr/bin/env bash
# One command for a first look: installs what is missing, builds, and opens the GUI on a bundled
# mesh. Without a display it prints the CLI's summary of the same mesh instead.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$root/scripts/install-dependencies.sh"
"$root/scripts/build.sh"
build=${CONESCOPE_BUILD_DIR:-$root/build}
mesh=${1:-$root/datasets/fandisk.off}
if [[ -n "${DISPLAY:-}" && -x "$build/ui/conescope" ]]; then
  exec "$build/ui/conescope" "$mesh"
fi
echo "conescope: no display; running the command-line statistics instead (see README for the GUI)" >&2
# A short summary for people (mesh, clusters, efficiency, losses, worst clusters), whatever stdout is.
exec "$build/src/cli/conescope-cli" stats "$mesh" --views 32 --format text
