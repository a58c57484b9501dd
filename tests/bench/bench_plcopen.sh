#!/usr/bin/env bash
# The PLCopen XML reader's cost (docs/performance.md "PLCopen XML"): a generated project
# (tests/iec/plcopen/gen_plcopen.sh: a 500-step program Big beside 23 programs of 20 steps)
# read and checked (`gfec --check`: every program, with the analyses), and read, checked and
# compiled to C (`gfec --chart Big -o big.c`). Prints the fastest of 5 runs. Then the engine of
# the 500-step Big: instructions per scan and state of gfec's two C forms, and of MatIEC's engine
# of the same program in structured text when MATIEC names a MatIEC tree built by hand
# (tests/iec/matiec/README.md), by tests/iec/matiec/measure_matiec.py (needs valgrind).
#   [MATIEC=DIR] bench_plcopen.sh GFEC SOURCE_DIR [STEPS...]
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

echo
echo "engine of Big, 500 steps: instructions per scan over gen_plcopen.sh --trace (1000 scans), 50 times"
if ! command -v valgrind > /dev/null; then
  echo "(valgrind missing: no engine rows)"
  exit 0
fi
"$root/tests/iec/plcopen/gen_plcopen.sh" 500 1 > "$work/big.xml"
"$root/tests/iec/plcopen/gen_plcopen.sh" --st 500 > "$work/Big.st"
"$root/tests/iec/plcopen/gen_plcopen.sh" --trace > "$work/Big.csv"
"$gfec" "$work/big.xml" --chart Big --emit=chart -o "$work/Big.sfc"
matiec=()
if [[ -n ${MATIEC:-} ]]; then
  matiec=(--matiec "$MATIEC")
else
  echo "(MatIEC side skipped: give MATIEC=DIR, a MatIEC tree with iec2c built, tests/iec/matiec/README.md)"
fi
python3 "$root/tests/iec/matiec/measure_matiec.py" "${matiec[@]}" --gfec "$gfec" "$work/Big.st"
