#!/usr/bin/env bash
# Engine size: code (text), initialised and zeroed data (data, bss) of the engine's object file,
# the engine's state (sizeof the chart's struct: the RAM of one engine, which the caller
# allocates) and the run function's stack frame, on the host (CC -O2) and for a Cortex-M4
# (clang --target=thumbv7em-none-eabi -mcpu=cortex-m4 -mthumb -Os, llvm-size), for each chart
# in each engine form and for the hand-written machine (the cases: bench_cases.sh).
#
#   tests/bench/bench_size.sh GFEC GEN [CC]
#
# Interface functions stay external (they are the robot library's), so text is the engine only.
set -euo pipefail
shopt -s inherit_errexit
gfec=$(realpath "$1") gen=$(realpath "$2") cc=${3:-gcc}
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
work=$(mktemp -d "${TMPDIR:-/tmp}/gfec-bench-size.XXXXXX")
trap 'rm -rf "$work"' EXIT
m4=(clang --target=thumbv7em-none-eabi -mcpu=cortex-m4 -mthumb -Os -ffreestanding -I"$here/freestanding")
have_m4=0
if command -v clang > /dev/null && command -v llvm-size > /dev/null; then have_m4=1; fi

# shellcheck source=tests/bench/bench_cases.sh
source "$here/bench_cases.sh"

# sizes DIR SOURCE CHART COMPILER... : "<text> <data> <bss> <state> <stack>"
sizes() {
  local dir=$1 source=$2 chart=$3
  shift 3
  local size_tool=size
  [[ $1 == clang ]] && size_tool=llvm-size
  (cd "$dir" && "$@" -fstack-usage -c "$source" -o engine.o)
  read -r text data bss _ <<< "$("$size_tool" "$dir/engine.o" | awk 'NR == 2')"
  # The state: a zeroed global of the chart's struct is all bss.
  local include=engine.h
  [[ $source == engine.c ]] || include=$source
  printf '#include "%s"\nstruct %s bench_state;\n' "$include" "$chart" > "$dir/state.c"
  (cd "$dir" && "$@" -c state.c -o state.o)
  local state_bss
  state_bss=$("$size_tool" "$dir/state.o" | awk 'NR == 2 { print $3 }')
  local stack
  stack=$(awk -v f="${chart}_run" '$0 ~ ":" f "\t" { print $2; exit }' "$dir"/engine.su)
  echo "$text $data $bss $state_bss ${stack:--}"
}

echo "host: $cc -O2 ($("$cc" --version | head -1)); Cortex-M4: ${m4[*]}"
printf "%-15s %-9s | %8s %6s %6s %7s %6s | %8s %6s %6s %7s %6s\n" "" "" "host" "" "" "" "" "M4" "" "" "" ""
printf "%-15s %-9s | %8s %6s %6s %7s %6s | %8s %6s %6s %7s %6s\n" "chart" "form" "text" "data" "bss" "state" "stack" \
  "text" "data" "bss" "state" "stack"
for name in "${bench_cases[@]}"; do
  chart_source "$name"
  for form in "${forms[@]}"; do
    dir=$work/$name-$form
    machine "$name" "$form" "$dir" --no-line-directives
    host=$(sizes "$dir" "$source" "$chart" "$cc" -O2 -std=c99)
    m4_row="- - - - -"
    if ((have_m4)); then m4_row=$(sizes "$dir" "$source" "$chart" "${m4[@]}"); fi
    # shellcheck disable=SC2086
    printf "%-15s %-9s | %8s %6s %6s %7s %6s | %8s %6s %6s %7s %6s\n" "$name" "$form" $host $m4_row
  done
done
echo "(bytes; state = sizeof the chart's struct, the RAM of one engine; stack = the run function's frame)"
