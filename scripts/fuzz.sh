#!/usr/bin/env bash
# Builds the libFuzzer targets with clang 14 and fuzzes the conversational parser and interpreter.
# Usage: scripts/fuzz.sh [SECONDS]   (default 600)
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
seconds=${1:-600}
sudo=""
[[ $(id -u) -eq 0 ]] || sudo="sudo"
dpkg-query -W clang-14 libclang-rt-14-dev >/dev/null 2>&1 ||
  $sudo apt-get install -y -q --no-install-recommends clang-14 libclang-rt-14-dev
cd "$root"
cmake --preset fuzz >/dev/null
cmake --build --preset fuzz --target fuzz_klartext
work=$(mktemp -d)
cp tests/fuzz/corpus/klartext/* "$work/"
exec build/fuzz/tests/fuzz/fuzz_klartext "$work" -max_total_time="$seconds" -timeout=10 \
  -rss_limit_mb=2048 -max_len=4096
