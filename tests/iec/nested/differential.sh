#!/usr/bin/env bash
# Nested SFCs held to the program's own SFC (README.md here; docs/iec.md): each random program of
# tests/iec/matiec/random is rewritten by wrap.py with its SFC inside an action (`action`) and as
# a function block's body called once a scan (`fb`); both mean the same as the original, so
# `gfec run --observable` on the same input trace must print the same `tick`/`out` lines, scan by
# scan. For every 10th program the C engine of each variant, in both forms, driven by
# tests/cli/engine_caller.py as in tests/cli/iec_st.sh, must print them too.
#
# Usage: differential.sh GFEC SOURCE_DIR
set -euo pipefail
gfec=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
src=$(cd "$2" && pwd)
caller=$src/tests/cli/engine_caller.py
wrap=$src/tests/iec/nested/wrap.py
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
command -v python3 > /dev/null || { echo "FAIL: python3 is needed (scripts/install-deps.sh installs it)" >&2; exit 1; }
cd "$work"

programs=0 scans=0 compared=0 mismatches=0 failures=0
run() { # FILE.st CSV OUT: gfec run's tick and out lines
  if ! "$gfec" run "$1" --inputs "$2" --observable > full.txt 2> err.txt; then
    echo "FAIL: gfec run $1 --inputs $2 --observable:" >&2
    head -20 err.txt >&2
    return 1
  fi
  grep -E '^(tick|out) ' full.txt > "$3" || true
}
engine() { # FILE.st CSV FORM OUT: the C engine's tick and out lines
  local chart
  chart=$(grep -i -m1 -o '^ *program  *[A-Za-z_0-9]*' "$1" | awk '{print $2}')
  if ! "$gfec" "$1" --engine="$3" -o engine.c 2> err.txt; then
    echo "FAIL: gfec $1 --engine=$3:" >&2
    head -20 err.txt >&2
    return 1
  fi
  python3 "$caller" engine.h "$2" "$chart" > main.c
  if ! cc -std=c99 -Wall -Wextra -Wpedantic -Werror main.c engine.c -o engine 2> err.txt; then
    echo "FAIL: the $3 engine of $1 does not build:" >&2
    head -20 err.txt >&2
    return 1
  fi
  ./engine | grep -E '^(tick|out) ' > "$4" || true
}
# One line per scan (the scan's lines joined), so that the first differing scan can be shown.
scanwise() { awk '/^tick /{if (s != "") print s; s = $0; next} {s = s " | " $0} END {if (s != "") print s}' "$1"; }
same() { # NAME WHAT OUT: OUT must be the original's lines (original.txt)
  compared=$((compared + 1))
  if ! cmp -s original.txt "$3"; then
    mismatches=$((mismatches + 1))
    echo "MISMATCH: $1 ($2): first differing scan:" >&2
    # awk reads to the end (no exit): paste must not die of a closed pipe under pipefail.
    paste -d '\n' <(scanwise original.txt) <(scanwise "$3") |
      awk 'NR % 2 == 1 {o = $0} NR % 2 == 0 && o != $0 && !n {print "  original: " o; print "  " w ": " $0; n = 1}
           END {if (!n) print "  (the same scans, but a different number of them or of lines)"}' w="$2" >&2
  fi
}

index=0
for st in "$src"/tests/iec/matiec/random/*.st; do
  name=$(basename "$st" .st)
  csv=${st%.st}.csv
  programs=$((programs + 1))
  if ! run "$st" "$csv" original.txt; then failures=$((failures + 1)); continue; fi
  scans=$((scans + $(grep -c '^tick ' original.txt)))
  for variant in action fb; do
    if ! "$wrap" "$variant" "$st" > "$name.$variant.st"; then failures=$((failures + 1)); continue; fi
    if run "$name.$variant.st" "$csv" variant.txt; then same "$name" "$variant" variant.txt; else failures=$((failures + 1)); fi
    if [ $((index % 10)) -eq 0 ]; then
      for form in readable scalable; do
        if engine "$name.$variant.st" "$csv" "$form" engine.txt; then
          same "$name" "$variant, $form engine" engine.txt
        else
          failures=$((failures + 1))
        fi
      done
    fi
    rm -f "$name.$variant.st"
  done
  index=$((index + 1))
done

echo "nested_differential: $programs programs, $scans scans; $compared variants compared with the" \
  "original (action and fb runs, and the C engines of every 10th program); $mismatches mismatches;" \
  "$failures gfec failures"
[ "$mismatches" -eq 0 ] && [ "$failures" -eq 0 ]
