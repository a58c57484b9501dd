#!/usr/bin/env bash
# The next tool in a firmware build: the C compiler on gfec's engines for large charts. For a
# ring of 1,000 and 10,000 places (one token: the sequential form, split into parts above 1,024
# places) and an fsm chain of 1,000 and 10,000 states (split likewise): `CC -O2 -c` on engine.c,
# wall and user time and peak memory (GNU time's maximum RSS; the fastest of three runs), the
# engine's size in lines, and the instructions of a tick (callgrind, 2,000 ticks from the start,
# the stubs of stubs.c: a token moves on one tick in four). The target (docs/performance.md):
# the 10,000-place engines build in under 5 s and 200 MB. Measures; never fails on time.
#
#   tests/bench/bench_cc.sh GFEC GEN [CC]        (CC default: gcc)
set -euo pipefail
gfec=$(realpath "$1") gen=$(realpath "$2") cc=${3:-gcc}
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d "${TMPDIR:-/tmp}/gfec-bench-cc.XXXXXX")
trap 'rm -rf "$work"' EXIT
ticks=2000
# shellcheck source=tests/bench/bench_measure.sh
source "$here/bench_measure.sh"

echo "$cc -O2 -std=c99 -c engine.c ($("$cc" --version | head -1)); the fastest of 3 runs"
printf "%-12s %-11s %9s %9s %9s %9s %11s\n" "chart" "form" "C lines" "wall s" "user s" "peak MB" "instr/tick"
for spec in "ring 1000 Ring sfc" "ring 10000 Ring sfc" "chain 1000 Chain fsm" "chain 10000 Chain fsm"; do
  read -r kind n chart ext <<< "$spec"
  dir=$work/$kind$n
  mkdir -p "$dir"
  "$gen" chart "$kind" "$n" > "$dir/chart.$ext"
  "$gfec" "$dir/chart.$ext" -o "$dir/engine.c"
  if grep -q "_update_parts\[" "$dir/engine.c"; then form=parts
  elif grep -q "switch (m->" "$dir/engine.c"; then form=switch
  else form=chain; fi
  fastest best 3 "$cc" -O2 -std=c99 -c "$dir/engine.c" -o "$dir/engine.o"
  read -r wall user kb <<< "$best"
  "$cc" -O2 -std=c99 -DCHART="$chart" -I"$dir" "$here/engine_main.c" "$here/stubs.c" "$dir/engine.c" -o "$dir/bench"
  ir=$(tick_instructions "$dir/bench" "$chart" "$ticks")
  printf "%-12s %-11s %9s %9s %9s %9.0f %11s\n" "$kind$n" "$form" "$(wc -l < "$dir/engine.c")" "$wall" "$user" \
    "$(awk -v k="$kb" 'BEGIN { print k / 1024 }')" "$ir"
done
