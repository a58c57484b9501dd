#!/usr/bin/env bash
# The PLCopen XML reader's cost (docs/performance.md "PLCopen XML"): a generated project
# (tests/iec/plcopen/gen_plcopen.sh: a 500-step program Big beside 23 programs of 20 steps)
# read and checked (`gfec --check`: every program, with the analyses), and read, checked and
# compiled to C (`gfec --chart Big -o big.c`). Prints the fastest of 5 runs.
#   bench_plcopen.sh GFEC SOURCE_DIR [STEPS...]
set -euo pipefail
gfec=$1
root=$2
shift 2
sizes=("$@")
[[ ${#sizes[@]} -gt 0 ]] || sizes=(500 2000)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# shellcheck source=tests/bench/bench_measure.sh
source "$root/tests/bench/bench_measure.sh"
printf '%-7s %-9s %-9s %-22s %-22s %-8s\n' steps programs file_KB 'check s (wall/user)' 'check+C s (wall/user)' peak_MB
for steps in "${sizes[@]}"; do
  "$root/tests/iec/plcopen/gen_plcopen.sh" "$steps" 24 > "$work/big.xml"
  kb=$(($(wc -c < "$work/big.xml") / 1024))
  fastest check 5 "$gfec" --check "$work/big.xml"
  fastest compile 5 "$gfec" "$work/big.xml" --chart Big -o "$work/big.c"
  read -r c_wall c_user _ <<< "$check"
  read -r o_wall o_user o_kb <<< "$compile"
  printf '%-7s %-9s %-9s %-22s %-22s %-8s\n' "$steps" 24 "$kb" "$c_wall / $c_user" "$o_wall / $o_user" "$((o_kb / 1024))"
done
