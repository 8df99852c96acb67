#!/usr/bin/env bash
# Builds Kerf with warnings as errors and runs every test (GUI tests on a virtual X display).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$root/scripts/setup.sh" ci
cd "$root"
xvfb-run -a ctest --preset ci -j2
