#!/usr/bin/env bash
# Cost on the target (docs/performance.md "On the targets"): for each sample chart and the
# hand-written switch line follower, on each target of tests/targets/targets.txt that is
# installed: flash (.text + .data of the engine's object), RAM (.data + .bss of it + sizeof the
# engine's state), and the time of one tick -- cycles on the AVR (tools/avr-run's GPIOR0
# markers), instructions on the qemu targets (qemu -singlestep -d exec,nochain: one trace line
# per instruction executed, counted between two calls of bench_mark, less an empty stretch).
# A tick includes the interface functions it calls (tests/bench/target_stubs.sh: a few
# instructions each, the same for every machine).
#
#   tests/bench/bench_target.sh GFEC [TARGET...]     ($GFEC_TARGET_BIN: the tree with tools/avr-run)
set -euo pipefail
shopt -s inherit_errexit
gfec=$(realpath "$1")
shift
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
table=$root/tests/targets/targets.txt
bin=${GFEC_TARGET_BIN:-$(dirname "$gfec")}
ticks=16
work=$(mktemp -d "${TMPDIR:-/tmp}/gfec-bench-target.XXXXXX")
trap 'rm -rf "$work"' EXIT
cp "$root"/samples/*.sfc "$root"/samples/*.fsm "$root"/samples/*.iface "$work/"
charts=(line_follower.sfc hand work_cell.sfc mission.fsm cleanup.fsm fetch_team.fsm)

trim() { sed -e 's/^ *//' -e 's/ *$//' <<< "$1"; }

# size_of TOOL FILE: "text data bss" (Berkeley).
size_of() { "$1" "$2" | awk 'NR == 2 { print $1, $2, $3 }'; }

# measure DIR: cycles or instructions per tick of DIR/prog.elf on the current target.
measure() {
  local dir=$1 elf=$1/prog.elf
  if [[ $cc == avr-gcc ]]; then
    local line
    line=$(eval "$(sed "s#{elf}#$elf#; s#{bin}#$bin#; s#avr-run #avr-run --cycles #" <<< "$run")" 2>&1 > /dev/null < /dev/null |
      grep marked-cycles)
    awk -v n="$ticks" '{ printf "%.0f", $2 / n }' <<< "$line"
    return
  fi
  local mark
  mark=$(printf '%x' "0x$("${cc%gcc}nm" "$elf" | awk '$3 == "bench_mark" { print $1 }')")
  eval "$(sed "s#{elf}#$elf#; s#{bin}#$bin#" <<< "$run") -singlestep -d exec,nochain -D $dir/exec.log" > /dev/null < /dev/null
  # The instructions from each bench_mark entry to the next: stretches alternate start, end.
  awk -v mark="$mark" -v n="$ticks" '
    /^Trace/ {
      ++count
      split($0, f, /[\[\/\]]/)
      pc = f[3]
      sub(/^0+/, "", pc)
      if (pc == mark) at[k++] = count
    }
    END {
      for (i = 0; i < n; ++i) empty += at[2 * i + 1] - at[2 * i]
      for (i = n; i < 2 * n; ++i) full += at[2 * i + 1] - at[2 * i]
      printf "%.0f", (full - empty) / n
    }' "$dir/exec.log"
}

printf "%-12s %-16s %7s %6s %7s %6s %10s\n" target chart flash ram "(state)" "" "per tick"
while IFS='|' read -r name _double cc flags link support run _ram _flash; do
  name=$(trim "$name") cc=$(trim "$cc") flags=$(trim "$flags") link=$(trim "$link") support=$(trim "$support")
  run=$(trim "$run")
  [[ -n $name && $name != \#* ]] || continue
  if [[ $# -gt 0 && " $* " != *" $name "* ]]; then continue; fi
  emulator=${run%% *}
  emulator=${emulator//\{bin\}/$bin}
  if ! command -v "$cc" > /dev/null || ! command -v "$emulator" > /dev/null; then
    echo "$name: skipped ($cc or $emulator is not installed)"
    continue
  fi
  size=${cc%gcc}size unit=instructions
  [[ $cc == avr-gcc ]] && unit=cycles
  for chart in "${charts[@]}"; do
    dir=$work/$name-$chart
    mkdir -p "$dir"
    if [[ $chart == hand ]]; then
      (cd "$work" && "$gfec" line_follower.sfc --no-line-directives -o "$dir/engine.c")
      cp "$here/hand/line_follower_hand.c" "$dir/machine.c"
      label="line_follower (hand)"
    else
      (cd "$work" && "$gfec" "$chart" --no-line-directives -o "$dir/engine.c")
      cp "$dir/engine.c" "$dir/machine.c"
      label=${chart}
    fi
    name_c=$(sed -n 's/^void \([A-Za-z0-9_]*\)_init(.*/\1/p' "$dir/engine.h" | head -1)
    # shellcheck disable=SC2086 # the table's flags are words
    if ! (cd "$dir" && $cc $flags -fno-common -c machine.c -o machine.o) > "$dir/build.log" 2>&1; then
      if grep -q '#error' "$dir/build.log"; then
        printf "%-12s %-22s refused: %s\n" "$name" "$label" "$(grep -m1 -o '#error.*' "$dir/build.log" | cut -c1-70)"
      else
        printf "%-12s %-22s does not compile (see below)\n" "$name" "$label"
        cat "$dir/build.log"
      fi
      continue
    fi
    read -r text data bss <<< "$(size_of "$size" "$dir/machine.o")"
    # The state: sizeof the machine's struct, as a zeroed global of it (bss, not common).
    if [[ $chart == hand ]]; then
      { cat "$dir/machine.c"; echo "struct $name_c bench_state;"; } > "$dir/state.c"
    else
      printf '#include "engine.h"\nstruct %s bench_state;\n' "$name_c" > "$dir/state.c"
    fi
    # shellcheck disable=SC2086
    (cd "$dir" && $cc $flags -fno-common -c state.c -o state.o)
    state=$(size_of "$size" "$dir/state.o" | awk '{ print $3 }')
    [[ $chart != hand ]] || state=$((state - bss))
    "$here/target_stubs.sh" "$dir/engine.h" "$name_c" > "$dir/stubs.c"
    # shellcheck disable=SC2086
    header=()
    [[ $chart == hand ]] || header=(-I. -DENGINE_HEADER='"engine.h"')
    (cd "$dir" && $cc $flags -DCHART="$name_c" -DSTATE_BYTES="$state" -DTICKS=$ticks "${header[@]}" -o prog.elf \
      "$here/target_main.c" machine.c stubs.c "$root/tests/targets/$support" $link)
    per_tick=$(measure "$dir")
    printf "%-12s %-22s %7d %6d %7s %10s %s\n" "$name" "$label" $((text + data)) $((data + bss + state)) "($state)" \
      "$per_tick" "$unit"
  done
done < "$table"
echo "(bytes; flash = .text + .data of the machine's object, RAM = its .data + .bss + state, state = sizeof its struct;"
echo " per tick: the mean of $ticks ticks, with the sensing and action functions it calls)"
