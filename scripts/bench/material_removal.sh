#!/bin/sh
# The cost of material removal for probing (docs/benchmarks.md, "Material removal"): a program of
# 1000 feed moves (a zigzag facing the block 1 mm deep with the D10 end mill, tool 5), then
# cycle 417 on the faced top. Run once with tool 5 cutting and once with the same moves made by
# the touch probe (tool 1, TP_NO: it removes nothing), alternating, in one minute.
# Usage: scripts/bench/material_removal.sh build/ci/app/kerf [rounds]
set -e
kerf=${1:?path to the kerf binary}
rounds=${2:-5}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp examples/probing/machine.toml examples/probing/TOOL.T examples/probing/tchprobe.tp "$work"
program() {  # $1: the tool that makes the 1000 moves
    echo "0 BEGIN PGM BENCH MM"
    echo "1 BLK FORM 0.1 Z X+0 Y+0 Z-40"
    echo "2 BLK FORM 0.2 X+100 Y+60 Z+0"
    echo "3 TOOL CALL $1 Z S3000"
    echo "4 L X+0 Y+0 Z+10 R0 FMAX M3"
    echo "5 L Z-1 F500"
    i=0
    while [ $i -lt 500 ]; do
        y=$(awk "BEGIN { printf \"%.3f\", $i * 0.12 }")
        if [ $((i % 2)) -eq 0 ]; then x=100; else x=0; fi
        echo "$((6 + 2 * i)) L X+$x Y+$y"
        echo "$((7 + 2 * i)) L Y+$(awk "BEGIN { printf \"%.3f\", ($i + 1) * 0.12 }")"
        i=$((i + 1))
    done
    echo "1006 L Z+50 R0 FMAX"
    echo "1007 TOOL CALL 1 Z"
    echo "1008 TCH PROBE 417 DATUM IN TS AXIS"
    for q in Q263=+50 Q264=+30 Q294=+0 Q320=0 Q260=+50 Q305=0 Q333=+0 Q303=+1; do
        echo "  $q"
    done
    echo "1009 END PGM BENCH MM"
}
program 5 >"$work/CUT.H"
program 1 >"$work/AIR.H"
for round in $(seq "$rounds"); do
    for name in CUT AIR; do
        start=$(date +%s.%N)
        "$kerf" run --machine "$work/machine.toml" "$work/$name.H" --report "$work/$name.json" >/dev/null
        end=$(date +%s.%N)
        echo "$name round $round: $(awk "BEGIN { printf \"%.3f\", $end - $start }") s"
    done
done
grep -o '"final_position":{[^}]*}' "$work/CUT.json" "$work/AIR.json" || true
