#!/usr/bin/env bash
# Builds a libFuzzer target with clang 14 and fuzzes it on one core.
# Usage: scripts/fuzz.sh [SECONDS] [TARGET]   (default 600 s, klartext; TARGET: klartext, fagor, tnciso)
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
seconds=${1:-600}
target=${2:-klartext}
sudo=""
[[ $(id -u) -eq 0 ]] || sudo="sudo"
if ! dpkg-query -W clang-14 libclang-rt-14-dev >/dev/null 2>&1; then
  export DEBIAN_FRONTEND=noninteractive
  $sudo apt-get update -q
  $sudo apt-get install -y -q --no-install-recommends clang-14 libclang-rt-14-dev
fi
cd "$root"
export CCACHE_BASEDIR="$root" CCACHE_NOHASHDIR=1
cmake --preset fuzz >/dev/null
cmake --build --preset fuzz --target "fuzz_$target"
# Seeds: the golden programs of the dialect (each case's program.*), named after their case.
work=$(mktemp -d)
for program in tests/golden/"$target"/*/program.*; do
  cp "$program" "$work/$(basename "$(dirname "$program")")"
done
exec build/fuzz/tests/fuzz/"fuzz_$target" "$work" -max_total_time="$seconds" -timeout=10 \
  -rss_limit_mb=2048 -max_len=4096 -dict="tests/fuzz/$target.dict"
