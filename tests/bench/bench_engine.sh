#!/usr/bin/env bash
# The engine's tick: instructions per tick (callgrind, the run function and every call it makes)
# and nanoseconds per tick (a timing loop), for each chart in each engine form gfec writes and
# for the hand-written switch machine of the same chart, side by side. The checksum (what the
# actions did) must be the same on a row's chart in every form: the machines do the same thing.
#
#   tests/bench/bench_engine.sh GFEC GEN [CC]        (CC default: gcc; engines at -O2)
#
# Charts: the line follower (samples/), a ring of 10 and of 1000 places with one token, and a
# fork into 100 parallel two-place loops (gfec_bench_gen). The stubs (stubs.c) make a token move
# on one tick in four. Measures; never fails on time.
set -euo pipefail
shopt -s inherit_errexit
gfec=$(realpath "$1") gen=$(realpath "$2") cc=${3:-gcc}
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
work=$(mktemp -d "${TMPDIR:-/tmp}/gfec-bench-engine.XXXXXX")
trap 'rm -rf "$work"' EXIT
ticks_time=${BENCH_TICKS:-2000000}   # for ns per tick
ticks_count=20000                    # under callgrind

forms=(readable)
if "$gfec" --help 2>&1 | grep -q -- '--engine'; then forms+=(scalable); fi
forms+=(hand)
have_callgrind=0
command -v valgrind > /dev/null && have_callgrind=1

# One machine: engine source(s) in $work/$id/, chart name $2. Prints "<Ir/tick> <ns/tick> <sum>".
measure() {
  local dir=$1 chart=$2 ir="-"
  "$cc" -O2 -std=c99 -DCHART="$chart" -I"$dir" "$here/engine_main.c" "$here/stubs.c" "$dir"/*.c -o "$dir/bench"
  read -r ns sum <<< "$("$dir/bench" "$ticks_time")"
  if ((have_callgrind)); then
    valgrind --tool=callgrind --collect-atstart=no --toggle-collect="${chart}_run" \
      --callgrind-out-file="$dir/callgrind.out" "$dir/bench" "$ticks_count" > /dev/null 2>&1
    local total
    total=$(awk '/^(summary|totals):/ { print $2; exit }' "$dir/callgrind.out")
    ir=$(awk -v t="$total" -v n="$ticks_count" 'BEGIN { printf "%.0f", t / n }')
  fi
  echo "$ir $ns $sum"
}

# chart_source NAME: writes the chart of a benchmark case to $work/NAME.sfc (with its imports)
# and the hand-written machine to $work/NAME_hand.c; sets `chart` to the chart's name.
chart_source() {
  case $1 in
    line_follower)
      cp "$root/samples/line_follower.sfc" "$root/samples/linebot.iface" "$work/"
      cp "$here/hand/line_follower_hand.c" "$work/line_follower_hand.c"
      chart=LineFollower ;;
    ring*)
      "$gen" chart ring "${1#ring}" > "$work/$1.sfc"
      "$gen" hand ring "${1#ring}" > "$work/$1_hand.c"
      chart=Ring ;;
    branches*)
      "$gen" chart branches "${1#branches}" > "$work/$1.sfc"
      "$gen" hand branches "${1#branches}" > "$work/$1_hand.c"
      chart=Branches ;;
  esac
}

declare -A ir_of
echo "engines: $cc -O2; $("$cc" --version | head -1); ${ticks_time} ticks timed, ${ticks_count} under callgrind"
printf "%-15s %-9s %12s %10s %9s %14s\n" "chart" "form" "instr/tick" "ns/tick" "vs hand" "checksum"
for name in line_follower ring10 ring1000 branches100; do
  chart_source "$name"
  declare -A result=()
  for form in "${forms[@]}"; do
    dir=$work/$name-$form
    mkdir -p "$dir"
    if [[ $form == hand ]]; then
      cp "$work/${name}_hand.c" "$dir/"
    else
      opt=()
      [[ $form == readable ]] || opt=(--engine="$form")
      if [[ $form == readable ]] && "$gfec" --help 2>&1 | grep -q -- '--engine'; then opt=(--engine=readable); fi
      (cd "$work" && "$gfec" "$name.sfc" "${opt[@]}" -o "$dir/engine.c")
    fi
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
