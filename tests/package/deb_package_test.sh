#!/usr/bin/env bash
# Builds the Debian package from this build folder, checks what it installs, unpacks it into a
# scratch root and starts the unpacked HMI (a screenshot of the simulated mill): the package a
# shop installs must hold a working Kerf, its desktop entry, icon and licence.
# Usage: deb_package_test.sh BUILD_DIR   (needs a display: the suite runs under xvfb-run)
set -euo pipefail
build=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cpack -G DEB --config "$build/CPackConfig.cmake" -B "$work" >"$work/cpack.log"
deb=$(ls "$work"/kerf_*.deb)
contents=$(dpkg-deb -c "$deb")
for path in ./usr/bin/kerf ./usr/libexec/kerf/kerf-gui ./usr/bin/kerf-drive-sim ./usr/share/applications/kerf.desktop \
  ./usr/share/icons/hicolor/scalable/apps/kerf.svg ./usr/share/doc/kerf/LICENSE; do
  grep -q " $path\$" <<<"$contents" || { echo "missing from the package: $path"; exit 1; }
done
depends=$(dpkg-deb -f "$deb" Depends)
grep -q libqt5widgets5 <<<"$depends" || { echo "Depends lacks Qt: $depends"; exit 1; }
grep -q "GNU GENERAL PUBLIC LICENSE" <(dpkg-deb --fsys-tarfile "$deb" | tar -xO ./usr/share/doc/kerf/LICENSE)
dpkg-deb -x "$deb" "$work/root"
grep -q '^Exec=kerf$' "$work/root/usr/share/applications/kerf.desktop"
"$work/root/usr/bin/kerf" --screenshot "$work/shot.png" --size 1280x800
[[ -s "$work/shot.png" ]] || { echo "the unpacked kerf wrote no screenshot"; exit 1; }
"$work/root/usr/bin/kerf" check --help >/dev/null
echo "package $(basename "$deb") installs kerf, kerf-gui, kerf-drive-sim, desktop entry, icon, licence; the HMI starts"
