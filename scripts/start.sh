#!/usr/bin/env bash
# Builds Kerf and starts the operator panel on the built-in simulated mill.
# Extra arguments go to kerf (for example: --machine lathe).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$root/scripts/setup.sh" release
if [[ -z ${DISPLAY:-} && -z ${WAYLAND_DISPLAY:-} ]]; then
  echo "No display: starting the HMI on a virtual X display (xvfb-run)." >&2
  exec xvfb-run -a "$root/build/release/app/kerf" "$@"
fi
exec "$root/build/release/app/kerf" "$@"
