#!/usr/bin/env bash
# Installs what a Debian 12 machine is missing to build Kerf, then configures and builds a preset.
# Usage: scripts/setup.sh PRESET   (dev, release, ci ...)
set -euo pipefail

preset=${1:-release}
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)

packages=(
  g++ cmake ninja-build ccache pkg-config
  qtbase5-dev qttools5-dev qttools5-dev-tools libqt5svg5-dev
  qttranslations5-l10n  # Qt's own dialog buttons (Cancel, Save ...) in the HMI's languages
  libvtk9-dev libvtk9-qt-dev libeigen3-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  libpolyclipping-dev libtomlplusplus-dev nlohmann-json3-dev libcli11-dev
  xvfb xauth
  dpkg-dev file  # cpack -G DEB: dpkg-shlibdeps finds the package's dependencies
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "Installing: ${missing[*]}"
  sudo=""
  [[ $(id -u) -eq 0 ]] || sudo="sudo"
  export DEBIAN_FRONTEND=noninteractive
  $sudo apt-get update -q
  $sudo apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

cd "$root"
# Let clones in other folders (CI uses a fresh clone) share ccache's results.
export CCACHE_BASEDIR="$root" CCACHE_NOHASHDIR=1
cmake --preset "$preset" >/dev/null
cmake --build --preset "$preset"
