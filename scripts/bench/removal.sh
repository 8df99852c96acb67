#!/bin/sh
# The material-removal benchmark (docs/benchmarks.md, "Touch probing on the machined part"):
# wall time of `kerf run` (and `kerf run --motion`) on examples/probing/REMOVAL.H (1000 cutting
# moves, then 423 and 417 on the pocket they cleared) and on the same program without the two
# probing cycles, alternating, RUNS times each: the difference is what the two cycles' touches
# cost on a part holding 1000 sweeps.
# Usage: scripts/bench/removal.sh [RUNS] (from the repository, build/ci built).
set -e
runs=${1:-5}
kerf=${KERF:-build/ci/app/kerf}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp examples/probing/TOOL.T examples/probing/tchprobe.tp examples/probing/machine.toml "$work/"
cp examples/probing/REMOVAL.H "$work/REMOVAL.H"
# Without the probing: blocks 25-27 (the probe's call and the two cycles with their parameters).
awk '/^25 TOOL CALL 1/{skip=1} /^28 /{skip=0} !skip' examples/probing/REMOVAL.H |
  sed 's/PGM REMOVAL/PGM NOPROBE/' >"$work/NOPROBE.H"
time_of() {  # wall seconds of one run
  start=$(date +%s.%N)
  "$kerf" run --machine "$work/machine.toml" "$@" >/dev/null 2>"$work/errors" || { cat "$work/errors"; exit 1; }
  end=$(date +%s.%N)
  echo "$end - $start" | bc
}
for options in "" "--motion"; do
  for program in REMOVAL NOPROBE; do eval "t_$program=''"; done
  i=0
  while [ "$i" -lt "$runs" ]; do
    for program in REMOVAL NOPROBE; do
      # shellcheck disable=SC2086
      t=$(time_of $options "$work/$program.H")
      eval "t_$program=\"\$t_$program $t\""
    done
    i=$((i + 1))
  done
  for program in REMOVAL NOPROBE; do
    eval "list=\$t_$program"
    median=$(echo "$list" | tr ' ' '\n' | grep . | sort -n | awk '{a[NR]=$1} END{print a[int((NR+1)/2)]}')
    echo "kerf run $options $program.H: median ${median} s of$list"
  done
done
