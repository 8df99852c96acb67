#!/usr/bin/env bash
# Interpreter throughput of Kerf, side by side with LinuxCNC's rs274 when it is installed
# (apt-get install --no-install-recommends linuxcnc-uspace). Median of RUNS runs each.
# Usage: [KERF=path/to/kerf] scripts/bench/interpreter.sh [RUNS]   (default: the release build,
# scripts/setup.sh release)
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
runs=${1:-5}
kerf="${KERF:-$root/build/release/app/kerf}"  # KERF=... measures another build
gen="$root/../shared/tools/gen_nc.py"
[[ -f $gen ]] || gen=/work/shared/tools/gen_nc.py
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# median wall time, max RSS and median CPU time (user + sys, every thread) of a command over
# $runs runs: prints "seconds rss_kb cpu_seconds". On a loaded machine wall time measures the
# scheduler more than the program: compare CPU times then (docs/benchmarks.md).
measure() {
  local times=() cpus=() rss=0 t r u s
  for ((i = 0; i < runs; i++)); do
    /usr/bin/time -o "$work/time.txt" -f "%e %M %U %S" "$@" >/dev/null 2>&1 || true
    read -r t r u s < <(tail -1 "$work/time.txt")
    times+=("$t")
    cpus+=("$(echo "$u + $s" | bc -l)")
    ((r > rss)) && rss=$r
  done
  local middle=$(((runs + 1) / 2))
  printf '%s %s %s\n' "$(printf '%s\n' "${times[@]}" | sort -n | sed -n "${middle}p")" "$rss" \
    "$(printf '%s\n' "${cpus[@]}" | sort -n | sed -n "${middle}p")"
}

# Kerf is measured twice: trace to a file, and trace to standard output sent to /dev/null. The
# ratio uses the first: rs274 writes its canonical text to a file too (FIGURES.md's side-by-side run).
printf '%-22s %10s %14s %14s %10s %12s\n' program blocks "kerf blk/s" "kerf>null" "kerf RSS" "rs274 blk/s"
# ONLY="klartext tnciso" measures those dialects only (first word of each row).
for spec in "klartext 200000" "klartext 1000000" "klartext-q 200000" "klartext-q 1000000" \
  "tnciso 200000" "tnciso 1000000" "tnciso-q 200000" "tnciso-q 1000000" "fagor 200000" "fagor 1000000"; do
  read -r dialect blocks <<<"$spec"
  [[ -n ${ONLY:-} && " $ONLY " != *" ${dialect%-q} "* ]] && continue
  ext=H; args=(); [[ $dialect == fagor ]] && { ext=pim; args=(--machine lathe --dialect fagor); }
  if [[ $dialect == tnciso* ]]; then
    # The same path as the conversational program, written as DIN/ISO blocks.
    ext=I
    python3 "$gen" "$blocks" --dialect "${dialect/tnciso/klartext}" |
      python3 "$root/scripts/bench/klartext_to_iso.py" >"$work/p.$ext"
  else
    python3 "$gen" "$blocks" --dialect "$dialect" -o "$work/p.$ext"
  fi
  read -r kf kr kc < <(measure "$kerf" run "$work/p.$ext" "${args[@]}" --trace "$work/t.txt" --state-dir "$work")
  read -r kt _ < <(measure "$kerf" run "$work/p.$ext" "${args[@]}" --trace - --state-dir "$work")
  line=$(printf '%-22s %10s %14.0f %14.0f %9sK' "$dialect $blocks" "$blocks" "$(echo "$blocks / $kf" | bc -l)" \
    "$(echo "$blocks / $kt" | bc -l)" "$kr")
  if command -v rs274 >/dev/null && [[ $dialect != fagor ]]; then
    if [[ $dialect == klartext || $dialect == tnciso ]]; then
      python3 "$gen" "$blocks" --dialect rs274 -o "$work/p.ngc"
    else
      python3 "$root/scripts/bench/rs274_loops.py" "$blocks" -o "$work/p.ngc"
    fi
    read -r rt rr rc < <(measure rs274 -g "$work/p.ngc" "$work/r.txt")  # canonical text to a file
    line+=$(printf ' %12.0f  (wall: rs274 %ss, kerf %ss, ratio %.1f; CPU: rs274 %ss, kerf %ss, ratio %.1f; rs274 RSS %sK)' \
      "$(echo "$blocks / $rt" | bc -l)" "$rt" "$kf" "$(echo "$rt / $kf" | bc -l)" \
      "$rc" "$kc" "$(echo "$rc / $kc" | bc -l)" "$rr")
  fi
  echo "$line"
done
