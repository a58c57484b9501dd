#!/usr/bin/env bash
# tools/avr-run on small avr-gcc programs: the UART's bytes reach stdout exactly (newlines,
# 0x00..0xff, repeats), a halt exits 0, main's non-zero status exits 1, a program that never
# halts exits 3 at --max-cycles, the GPIOR0 markers count a known loop's cycles exactly, and
# --pins / --pin-log drive inputs and record outputs at the cycles given.
# Usage: avr_run_test.sh AVR_RUN TEST_DIR
set -euo pipefail
avr_run=$1 dir=$2
if ! command -v avr-gcc >/dev/null; then
  echo "avr-gcc is not installed (scripts/install-deps.sh installs Debian's gcc-avr and avr-libc)"
  [ -n "${CI:-}" ] && exit 1
  exit 77
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
build() {  # build NAME [FLAGS...]
  local name=$1
  shift
  avr-gcc -mmcu=atmega328p -DF_CPU=16000000UL -Os -std=c99 -Wall -Wextra -Werror "$@" \
    -o "$work/$name.elf" "$dir/$name.c" "$dir/avr_support.c"
}
run() { "$avr_run" --mcu atmega328p "$@"; }

# Bytes, exactly.
build hello
run "$work/hello.elf" > "$work/hello.out" || fail "hello exited $?"
{
  printf 'hello, avr\n\n  two newlines above\r\n'
  for i in $(seq 0 255); do printf "\\$(printf %03o "$i")"; done
  printf 'AAA\n'
} > "$work/hello.expected"
cmp "$work/hello.out" "$work/hello.expected" || fail "UART bytes differ (od -c $work/hello.out)"

# A program that never halts: exit 3 at the limit, with what it wrote before.
build spin
status=0
run --max-cycles 200000 "$work/spin.elf" > "$work/spin.out" 2> "$work/spin.err" || status=$?
[ "$status" -eq 3 ] || fail "spin: exit $status, expected 3 (timeout)"
grep -q timeout "$work/spin.err" || fail "spin: no timeout message: $(cat "$work/spin.err")"
[ "$(cat "$work/spin.out")" = x ] || fail "spin: stdout '$(cat "$work/spin.out")'"

# Cycle markers: three stretches of 302 cycles each (marker.c counts them).
build marker
run --cycles "$work/marker.elf" > "$work/marker.out" 2> "$work/marker.err" || fail "marker exited $?"
grep -qx 'marked-cycles 906 (3 stretches)' "$work/marker.err" || fail "markers: $(cat "$work/marker.err")"
total=$(sed -n 's/^cycles \([0-9]*\)$/\1/p' "$work/marker.err")
[ -n "$total" ] && [ "$total" -gt 906 ] || fail "cycles: $(cat "$work/marker.err")"

# main's status.
build marker -DSTATUS=7
status=0
run "$work/marker.elf" > /dev/null 2> "$work/status.err" || status=$?
[ "$status" -eq 1 ] && grep -q 'exit status 7' "$work/status.err" || fail "status 7: exit $status, $(cat "$work/status.err")"

# Bad usage and a file that is no program.
for args in "" "--mcu atmega328p" "--mcu nosuch $work/marker.elf" "--mcu atmega328p --freq x $work/marker.elf" \
  "--mcu atmega328p $dir/pins.c"; do
  status=0
  # shellcheck disable=SC2086
  "$avr_run" $args > /dev/null 2>&1 || status=$?
  [ "$status" -eq 2 ] || fail "avr-run $args: exit $status, expected 2"
done

# Pins: inputs at given times (cycles and microseconds at 16 MHz), outputs logged when they change.
build pins
cat > "$work/pins.script" <<'SCRIPT'
# time  pins
1000 PD2=1
125us PD3=1   # 2000 cycles
3000 PD2=0
4000 PD4=1
SCRIPT
run --pins "$work/pins.script" --pin-log "$work/pins.log" "$work/pins.elf" || fail "pins exited $?"
# Each output follows its input within one pass of the loop (a few cycles).
expected=("1000 PB0=1" "2000 PB1=1" "3000 PB0=0")
mapfile -t got < "$work/pins.log"
[ "${#got[@]}" -eq 3 ] || fail "pin log: $(cat "$work/pins.log")"
for i in 0 1 2; do
  read -r at change <<< "${expected[$i]}"
  read -r when what <<< "${got[$i]}"
  [ "$what" = "$change" ] && [ "$when" -ge "$at" ] && [ "$when" -le $((at + 40)) ] ||
    fail "pin log line $((i + 1)): '${got[$i]}', expected $change within 40 cycles after $at"
done
# A script's errors name the file and line.
printf '10ms PD2=1\n5ms PD2=0\n' > "$work/bad.script"
status=0
run --pins "$work/bad.script" "$work/pins.elf" 2> "$work/bad.err" || status=$?
[ "$status" -eq 2 ] && grep -q 'bad.script:2:' "$work/bad.err" || fail "bad script: exit $status, $(cat "$work/bad.err")"
echo "avr-run: bytes, halt, status, timeout, markers and pins as expected"
