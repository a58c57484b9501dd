#!/usr/bin/env bash
# The live trace on the emulated AVR (docs/live.md): the line follower engine built with --trace
# for an ATmega328P (tests/targets/avr/trace_robot.c), run by tools/avr-run on the sensors of
# line_follower_trace.csv (repeated, for several full frames); its UART bytes piped into `gfec
# monitor --log` must be what `gfec run --observable` prints for the same trace, call lines
# removed. Prints the cost: bytes per tick (full frames, frames of changes) and cycles per tick
# with and without --trace. About 5 s.
# Usage: trace_test.sh GFEC AVR_RUN SOURCE_DIR [--bench]   (--bench: the numbers only, one line)
set -euo pipefail
gfec=$(realpath "$1") avr_run=$(realpath "$2") source_dir=$(realpath "$3") bench=${4:-}
if ! command -v avr-gcc > /dev/null; then
  echo "avr-gcc is missing (scripts/install-deps.sh installs Debian's gcc-avr and avr-libc)"
  [ -n "${CI:-}" ] && exit 1
  exit 77
fi
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
cd "$work"

csv=$work/inputs.csv
head -1 "$here/line_follower_trace.csv" > "$csv"
for _ in $(seq 6); do tail -n +2 "$here/line_follower_trace.csv" >> "$csv"; done
{
  echo "#define ROWS $(($(wc -l < "$csv") - 1))u"
  echo "static const uint8_t rows[ROWS][4] = {"
  tail -n +2 "$csv" | sed 's/^/    {/; s/$/},/'
  echo "};"
} > rows.h
chart=$source_dir/samples/line_follower.sfc
"$gfec" run "$chart" --inputs "$csv" --observable | grep -v '^call ' > expected.log

build() {  # build DIR [--trace]
  mkdir -p "$1"
  "$gfec" "$chart" ${2:+"$2"} -o "$1/lf.c"
  avr-gcc -mmcu=atmega328p -DF_CPU=16000000UL -Os -std=c99 -Wall -Wextra -Werror -I "$1" -I . \
    ${2:+-DTRACED} "$here/trace_robot.c" "$1/lf.c" "$here/avr_support.c" -o "$1/robot.elf"
}
build plain
build traced --trace
"$avr_run" --mcu atmega328p --cycles traced/robot.elf > stream.bin 2> traced.err || fail "avr-run: $(cat traced.err)"
"$avr_run" --mcu atmega328p --cycles plain/robot.elf > /dev/null 2> plain.err || fail "avr-run: $(cat plain.err)"
"$gfec" monitor "$chart" --log < stream.bin > got.log 2> monitor.err
diff expected.log got.log || fail "the AVR's decoded trace differs from gfec run --observable"

# The cost. Cycles: the marked stretches (the tick, and with --trace its frame) per tick.
per_tick() { sed -n 's/^marked-cycles \([0-9]*\) (\([0-9]*\) stretches).*/\1 \2/p' "$1" | awk '{ printf "%d", $1 / $2 }'; }
plain_cycles=$(per_tick plain.err) traced_cycles=$(per_tick traced.err)
# Bytes: each frame's length from its header (docs/live.md), full and changes apart.
read -r full_n full_bytes delta_n delta_bytes < <(od -An -v -tu1 stream.bin | tr -s ' \n' '\n' | grep -v '^$' | awk '
  { b[n++] = $1 }
  END {
    for (at = 0; at + 14 <= n; at += size) {
      size = 14 + b[at + 4] + 256 * b[at + 5] + 4
      if (b[at + 3] == 1) { fn++; fb += size } else { dn++; db += size }
    }
    printf "%d %d %d %d\n", fn, fb, dn, db
  }')
ticks=$(grep -c '^tick' expected.log)
[ $((full_n + delta_n)) = "$ticks" ] || fail "$((full_n + delta_n)) frames for $ticks ticks"
size_of() { avr-size "$1" | tail -1 | awk '{ print $1 + $2 }'; }
line=$(awk -v t="$ticks" -v pc="$plain_cycles" -v tc="$traced_cycles" -v fn="$full_n" -v fb="$full_bytes" \
  -v dn="$delta_n" -v db="$delta_bytes" -v pf="$(size_of plain/robot.elf)" -v tf="$(size_of traced/robot.elf)" 'BEGIN {
  printf "avr trace (line follower, atmega328p): %d ticks; cycles/tick %d plain, %d with --trace; bytes/tick: full frame %.1f, frame of changes %.1f, %.1f overall; flash %d B plain, %d B with --trace\n", t, pc, tc, fb / fn, (dn ? db / dn : 0), (fb + db) / t, pf, tf }')
echo "$line"
[ "$bench" = --bench ] && exit 0
echo "avr trace: $ticks ticks decoded from the UART as gfec run --observable"
