#!/usr/bin/env bash
# The engine's tick: instructions per tick (callgrind, the run function and every call it makes)
# and nanoseconds per tick (a timing loop), for each chart in each engine form gfec writes and
# for the hand-written switch machine of the same chart, side by side. The checksum (what the
# actions did) must be the same on a row's chart in every form: the machines do the same thing.
#
#   tests/bench/bench_engine.sh GFEC GEN [CC]        (CC default: gcc; engines at -O2)
#
# Charts: bench_cases.sh. The stubs (stubs.c) make a token move on one tick in four. Measures;
# never fails on time.
set -euo pipefail
shopt -s inherit_errexit
gfec=$(realpath "$1") gen=$(realpath "$2") cc=${3:-gcc}
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
work=$(mktemp -d "${TMPDIR:-/tmp}/gfec-bench-engine.XXXXXX")
trap 'rm -rf "$work"' EXIT
ticks_time=${BENCH_TICKS:-2000000}   # for ns per tick
ticks_count=20000                    # under callgrind

# shellcheck source=tests/bench/bench_cases.sh
source "$here/bench_cases.sh"
# shellcheck source=tests/bench/bench_measure.sh
source "$here/bench_measure.sh"

# One machine: engine source(s) in $work/$id/, chart name $2. Prints "<Ir/tick> <ns/tick> <sum>".
measure() {
  local dir=$1 chart=$2
  local header
  header=$(engine_header "$dir")
  # shellcheck disable=SC2086 # empty for a hand-written machine
  "$cc" -O2 -std=c99 -DCHART="$chart" $header -I"$dir" "$here/engine_main.c" "$here/stubs.c" "$dir"/*.c -o "$dir/bench"
  read -r ns sum <<< "$("$dir/bench" "$ticks_time")"
  echo "$(tick_instructions "$dir/bench" "$chart" "$ticks_count") $ns $sum"
}

declare -A ir_of
echo "engines: $cc -O2; $("$cc" --version | head -1); ${ticks_time} ticks timed, ${ticks_count} under callgrind"
printf "%-15s %-9s %12s %10s %9s %14s\n" "chart" "form" "instr/tick" "ns/tick" "vs hand" "checksum"
for name in "${bench_cases[@]}"; do
  chart_source "$name"
  declare -A result=()
  for form in "${forms[@]}"; do
    dir=$work/$name-$form
    machine "$name" "$form" "$dir"
    result[$form]=$(measure "$dir" "$chart")
  done
  read -r hand_ir _ _ <<< "${result[hand]}"
  for form in "${forms[@]}"; do
    read -r ir ns sum <<< "${result[$form]}"
    ir_of[$name-$form]=$ir
    ratio=$(awk -v a="$ir" -v b="$hand_ir" 'BEGIN { if (b > 0 && a != "-") printf "%.2fx", a / b; else printf "-" }')
    printf "%-15s %-9s %12s %10s %9s %14s\n" "$name" "$form" "$ir" "$ns" "$ratio" "$sum"
  done
done
echo
echo "ring of 1000 places over ring of 10 (instructions per tick; the target is at most 3x):"
for form in "${forms[@]}"; do
  awk -v a="${ir_of[ring1000-$form]}" -v b="${ir_of[ring10-$form]}" -v f="$form" \
    'BEGIN { if (b > 0) printf "  %-9s %.2fx\n", f, a / b }'
done
