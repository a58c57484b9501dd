#!/usr/bin/env bash
# What a sub-chart instance costs: instructions per tick (callgrind, the run function and every
# call it makes) of the line follower compiled alone, and of the same chart run by a place of a
# one-place sfc (`Wrap`), and by a state of a one-state fsm run by that place (`Wrap2`, two
# levels), in each engine form. The checksum (what the actions did) must be the same on every
# row: the machines do the same thing. docs/performance.md gives the figures.
#
#   tests/bench/bench_subchart.sh GFEC [CC]        (CC default: gcc; engines at -O2)
set -euo pipefail
shopt -s inherit_errexit
gfec=$(realpath "$1") cc=${2:-gcc}
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
work=$(mktemp -d "${TMPDIR:-/tmp}/gfec-bench-subchart.XXXXXX")
trap 'rm -rf "$work"' EXIT
ticks=20000
command -v valgrind > /dev/null || { echo "bench_subchart: needs valgrind (callgrind)" >&2; exit 2; }
# shellcheck source=tests/bench/bench_measure.sh
source "$here/bench_measure.sh"

cp "$root/samples/line_follower.sfc" "$root/samples/linebot.iface" "$work/"
cat > "$work/wrap.sfc" <<'CHART'
import "line_follower.sfc";

sfc Wrap {
  period 10ms;
  initial place Run runs LineFollower;
}
CHART
cat > "$work/wrap2.sfc" <<'CHART'
import "line_follower.sfc";

fsm Mid {
  period 10ms;
  initial state Run runs LineFollower;
}

sfc Wrap2 {
  period 10ms;
  initial place Run runs Mid;
}
CHART

# measure DIR CHART: "<instructions per tick> <checksum>"
measure() {
  local dir=$1 chart=$2
  local header
  header=$(engine_header "$dir")
  # shellcheck disable=SC2086 # empty for a hand-written machine
  "$cc" -O2 -std=c99 -DCHART="$chart" $header -I"$dir" "$here/engine_main.c" "$here/stubs.c" "$dir"/*.c -o "$dir/bench"
  local sum
  sum=$("$dir/bench" "$ticks" | awk '{ print $2 }')
  echo "$(tick_instructions "$dir/bench" "$chart" "$ticks") $sum"
}

echo "engines: $cc -O2; $("$cc" --version | head -1); $ticks ticks under callgrind"
printf "%-9s %-34s %11s %9s %12s\n" "form" "chart" "instr/tick" "overhead" "checksum"
for form in readable scalable; do
  base=
  for row in "LineFollower:line_follower.sfc:alone" "Wrap:wrap.sfc:run by a place of an sfc" \
             "Wrap2:wrap2.sfc:in an fsm state in an sfc (2 levels)"; do
    IFS=: read -r chart file label <<< "$row"
    dir=$work/$form-$chart
    mkdir -p "$dir"
    (cd "$work" && "$gfec" "$file" --chart "$chart" --engine="$form" -o "$dir/engine.c")
    read -r ir sum <<< "$(measure "$dir" "$chart")"
    [[ -z $base ]] && base=$ir
    printf "%-9s %-34s %11s %9s %12s\n" "$form" "$label" "$ir" "+$((ir - base))" "$sum"
  done
done
