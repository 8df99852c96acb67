#!/bin/sh
# The rapid-collision benchmark (docs/benchmarks.md, "Rapid collisions on a drilled plate"):
# wall time of `kerf run` and `kerf run --motion` on a generated program that peck-drills 400
# holes (cycle 200, 4 pecks each: 1600 feed moves, 3602 rapids, each checked against the blank
# as drilled so far), alternating the binaries given, RUNS times each; medians.
# Usage: scripts/bench/rapid_collision.sh [RUNS] [KERF...] (from the repository; default: the
# build/ci kerf alone). Give a kerf built from before the check as well to compare the two.
set -e
runs=${1:-5}
[ $# -gt 0 ] && shift
[ $# -eq 0 ] && set -- build/ci/app/kerf
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp examples/probing/TOOL.T "$work/"
# 210 x 210 x 40 plate; tool 5 (D10) drills 20 deep in pecks of 5 on a 10 mm grid of 20 x 20.
awk 'BEGIN {
  n = 0
  print n++ " BEGIN PGM DRILL400 MM"
  print n++ " BLK FORM 0.1 Z X+0 Y+0 Z-40"
  print n++ " BLK FORM 0.2 X+210 Y+210 Z+0"
  print n++ " TOOL CALL 5 Z S3000 F250"
  print n++ " L Z+50 R0 FMAX M3"
  print n++ " CYCL DEF 200 DRILLING ~"
  print "  Q200=2 ;SET-UP CLEARANCE ~"
  print "  Q201=-20 ;DEPTH ~"
  print "  Q206=250 ;FEED RATE FOR PLNGNG ~"
  print "  Q202=5 ;PLUNGING DEPTH ~"
  print "  Q210=0 ;DWELL TIME AT TOP ~"
  print "  Q203=+0 ;SURFACE COORDINATE ~"
  print "  Q204=20 ;2ND SET-UP CLEARANCE ~"
  print "  Q211=0 ;DWELL TIME AT DEPTH ~"
  print "  Q395=0 ;DEPTH REFERENCE"
  for (i = 0; i < 400; i++)
    print n++ " L X+" (10 + 10 * (i % 20)) " Y+" (10 + 10 * int(i / 20)) " R0 FMAX M99"
  print n++ " L Z+100 R0 FMAX M30"
  print n++ " END PGM DRILL400 MM"
}' >"$work/DRILL400.H"
time_of() {  # wall seconds of one run
  start=$(date +%s.%N)
  "$@" >/dev/null 2>"$work/errors" || { cat "$work/errors"; exit 1; }
  end=$(date +%s.%N)
  echo "$end - $start" | bc
}
for options in "" "--motion"; do
  i=0
  while [ "$i" -lt "$runs" ]; do
    k=0
    for kerf in "$@"; do
      # shellcheck disable=SC2086
      t=$(time_of "$kerf" run $options --state-dir "$work/state" "$work/DRILL400.H")
      eval "t_$k=\"\$t_$k $t\""
      k=$((k + 1))
    done
    i=$((i + 1))
  done
  k=0
  for kerf in "$@"; do
    eval "list=\$t_$k"
    median=$(echo "$list" | tr ' ' '\n' | grep . | sort -n | awk '{a[NR]=$1} END{print a[int((NR+1)/2)]}')
    echo "$kerf run $options DRILL400.H: median ${median} s of$list"
    eval "t_$k=''"
    k=$((k + 1))
  done
done
