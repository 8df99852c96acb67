#!/bin/sh
# `kerf` starts without Qt and VTK (docs/benchmarks.md: their dynamic linking cost as much CPU as
# 200,000 blocks); kerf-gui, which kerf starts for the panel and pictures, links them; and a kerf
# whose kerf-gui is missing says so instead of failing silently.
# Usage: gui_libraries_test.sh KERF KERF_GUI WITH_UI(ON/OFF)
set -eu
kerf=$1
gui=$2
with_ui=$3
needed() { readelf -d "$1" | sed -n 's/.*(NEEDED).*\[\(.*\)\]/\1/p'; }
needed "$kerf" | grep -q '^libc\.so' || { echo "readelf lists no libc for $kerf"; exit 1; }
if needed "$kerf" | grep -E '^lib(Qt|vtk)'; then
  echo "kerf links the GUI libraries above"
  exit 1
fi
needed "$gui" | grep -q '^libvtkRenderingCore' || { echo "kerf-gui does not link VTK"; exit 1; }
if [ "$with_ui" = ON ]; then
  needed "$gui" | grep -q '^libQt5Widgets' || { echo "kerf-gui does not link Qt Widgets"; exit 1; }
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir "$work/bin"
cp "$kerf" "$work/bin/kerf"
printf 'BEGIN PGM T MM\nL X+1 R0 FMAX\nEND PGM T MM\n' >"$work/t.H"
"$work/bin/kerf" check "$work/t.H"
status=0
"$work/bin/kerf" run "$work/t.H" --png "$work/t.png" 2>"$work/err" || status=$?
[ "$status" = 2 ] || { echo "exit $status without kerf-gui, expected 2"; exit 1; }
grep -q "cannot start the operator panel .*kerf-gui: No such file or directory" "$work/err" || {
  echo "unexpected message:"; cat "$work/err"; exit 1; }
[ ! -e "$work/t.png" ] || { echo "a picture appeared without kerf-gui"; exit 1; }
echo "kerf links neither Qt nor VTK, kerf-gui does; without kerf-gui kerf says so"
