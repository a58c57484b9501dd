#!/usr/bin/env bash
# The MatIEC comparison (docs/iec.md "Compared with MatIEC", README.md here): gfec runs every
# program of the corpus on its input trace and its `tick`/`out` lines are compared, scan by scan,
# with the logs MatIEC's engine printed for the same program and trace (kept in the repository;
# MatIEC is not a Debian package, so it is not built here).
#
#   random/NAME.{st,sfc,csv}  generated programs; NAME.matiec is MatIEC's log, NAME.matiec-final
#                             (where it differs) MatIEC's engine with the standard's final scan
#                             added. A scan that differs from NAME.matiec must equal
#                             NAME.matiec-final: it differs by the final scan and by nothing else.
#   agree/NAME.{...}          the same for programs written by hand (qualifiers MatIEC follows).
#   hand/NAME.{st,sfc,csv}    one case for each documented point: gfec must print NAME.standard
#                             (the standard's output, written by hand) and MatIEC's NAME.matiec
#                             must differ from it (the point shows).
#
# Usage: differential.sh GFEC SOURCE_DIR [st|sfc]
#   st  (the default) runs the structured text, sfc its chart-text translation (same description,
#   docs/iec.md "What a program is in gfec's chart language").
set -euo pipefail
gfec=$1
dir=$2/tests/iec/matiec
form=${3:-st}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

programs=0 identical=0 scans=0 differ=0 final=0 bad=0
run() { # FILE CSV OUT: gfec's tick and out lines
  if ! "$gfec" run "$1" --inputs "$2" --observable > "$work/full" 2> "$work/err"; then
    echo "FAIL: gfec run $1 --inputs $2 --observable:" >&2
    cat "$work/err" >&2
    return 1
  fi
  grep -E '^(tick|out) ' "$work/full" > "$3" || true
}
# Splits a log into one line per scan (the scan's lines joined), for a scan-by-scan comparison.
scanwise() { awk '/^tick /{if (s != "") print s; s = $0; next} {s = s " | " $0} END {if (s != "") print s}' "$1"; }

shopt -s nullglob
for csv in "$dir"/random/*.csv "$dir"/agree/*.csv; do
  base=${csv%.csv}
  name=$(basename "$base")
  programs=$((programs + 1))
  if ! run "$base.$form" "$csv" "$work/gfec"; then bad=$((bad + 1)); continue; fi
  scanwise "$work/gfec" > "$work/g"
  scanwise "$base.matiec" > "$work/m"
  if [ -f "$base.matiec-final" ]; then scanwise "$base.matiec-final" > "$work/f"; else cp "$work/m" "$work/f"; fi
  n=$(wc -l < "$work/m")
  if [ "$(wc -l < "$work/g")" -ne "$n" ]; then
    echo "FAIL: $name: gfec ran $(wc -l < "$work/g") scans, MatIEC $n" >&2
    bad=$((bad + 1))
    continue
  fi
  scans=$((scans + n))
  # per scan: 0 agree, 1 differs by the final scan, 2 differs otherwise
  verdicts=$(paste -d '\n' "$work/g" "$work/m" "$work/f" | awk 'NR % 3 == 1 {g = $0} NR % 3 == 2 {m = $0}
    NR % 3 == 0 {print (g == m) ? 0 : (g == $0) ? 1 : 2}')
  d=$(grep -c '[12]' <<< "$verdicts" || true)
  f=$(grep -c 1 <<< "$verdicts" || true)
  [ "$d" -eq 0 ] && identical=$((identical + 1))
  differ=$((differ + d))
  final=$((final + f))
  if [ "$d" -ne "$f" ]; then
    bad=$((bad + 1))
    echo "FAIL: $name: $((d - f)) scans differ from MatIEC by more than the final scan; first:" >&2
    diff <(scanwise "$work/gfec" | tr '|' '\n') <(tr '|' '\n' < "$work/f") | head -20 >&2 || true
  fi
done

hand=0
for csv in "$dir"/hand/*.csv; do
  base=${csv%.csv}
  name=$(basename "$base")
  hand=$((hand + 1))
  if ! run "$base.$form" "$csv" "$work/gfec"; then bad=$((bad + 1)); continue; fi
  if ! diff -u "$base.standard" "$work/gfec" > "$work/d"; then
    bad=$((bad + 1))
    echo "FAIL: hand/$name: gfec differs from the standard's output written by hand:" >&2
    head -30 "$work/d" >&2
  fi
  if cmp -s "$base.standard" "$base.matiec"; then
    bad=$((bad + 1))
    echo "FAIL: hand/$name: MatIEC's log equals the standard's: the case does not show its point" >&2
  fi
done

echo "matiec_differential ($form): $programs programs, $scans scans; $identical programs print" \
  "MatIEC's log; $differ scans differ from it, $final of them by the final scan alone (documented)," \
  "$((differ - final)) otherwise; $hand hand cases of documented differences; $bad failures"
[ "$bad" -eq 0 ]
