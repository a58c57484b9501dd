#!/usr/bin/env bash
# The Arduino line follower (examples/arduino-line-follower) as a teacher builds it and as the
# board would run it: `make` with Debian's arduino-mk in a scratch copy (gfec makes the engine
# from samples/line_follower.sfc), the ELF within an Uno's flash and RAM, then the ELF under
# tools/avr-run with the IR sensor pins driven from line_follower_trace.csv. Tick by tick, the
# motor driver's pins must be what the reference interpreter's calls say for the same trace
# (`gfec run --inputs --observable`): Left_FW -> ENA=1 IN1=1 IN2=0, Left_Stop -> all three 0.
#
# Timing (16 MHz, the chart's 10 ms = 160000 cycles): the sketch runs tick k at about
# (k-1) x 10 ms (millis() steps by 1.024 ms, so up to ~1.1 ms late). The script sets tick k's
# sensors 5 ms before that and the test reads the motors 5 ms after it, and every motor pin
# change must fall in the first 2 ms of a tick: a sketch on another period fails.
# Usage: arduino_line_follower_test.sh GFEC AVR_RUN SOURCE_DIR
set -euo pipefail
gfec=$(realpath "$1") avr_run=$(realpath "$2") source_dir=$(realpath "$3")
arduino_mk=/usr/share/arduino/Arduino.mk
for tool in avr-gcc avr-size make "$arduino_mk"; do
  if ! command -v "$tool" > /dev/null && [ ! -f "$tool" ]; then
    echo "$tool is missing (scripts/install-deps.sh installs Debian's gcc-avr, avr-libc and arduino-mk)"
    [ -n "${CI:-}" ] && exit 1
    exit 77
  fi
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
here=$(cd "$(dirname "$0")" && pwd)
trace=$here/line_follower_trace.csv
cycles_per_tick=160000

# The build, in a copy of the sketch's own files (nothing is written under the source tree).
sketch=$work/arduino-line-follower
mkdir "$sketch"
cp "$source_dir/examples/arduino-line-follower/Makefile" "$source_dir/examples/arduino-line-follower/"*.ino "$sketch/"
charts=$work/charts
mkdir "$charts"
cp "$source_dir/samples/line_follower.sfc" "$source_dir/samples/linebot.iface" "$charts/"
start=$SECONDS
make -C "$sketch" GFEC="$gfec" CHARTS="$charts" > "$work/make.log" 2>&1 ||
  { tail -30 "$work/make.log"; fail "make"; }
echo "make: $((SECONDS - start)) s"
[ -s "$sketch/build-uno/line-follower.hex" ] || fail "no build-uno/line-follower.hex"
elf=$sketch/build-uno/line-follower.elf
read -r text data bss _ < <(avr-size "$elf" | tail -1)
flash=$((text + data)) ram=$((data + bss))
echo "line-follower.elf: flash $flash B (.text $text + .data $data), static RAM $ram B (.data $data + .bss $bss)"
[ "$flash" -le 32256 ] || fail "flash $flash B is over the Uno's 32256 (32 KiB less the bootloader)"
[ "$ram" -le 2048 ] || fail "RAM $ram B is over the Uno's 2048"
# Made again only when the chart or its interface changes: a second make leaves the engine alone,
# a newer interface file (gfec's dependency file names it) makes it again.
remake() { make -C "$sketch" GFEC="$gfec" CHARTS="$charts" > "$work/remake.log" 2>&1 || fail "make again"; }
engine_time() { stat -c %Y "$sketch/line_follower.c"; }
before=$(engine_time)
sleep 1
remake
[ "$(engine_time)" = "$before" ] || fail "a second make regenerated the engine"
touch "$charts/linebot.iface"
remake
[ "$(engine_time)" != "$before" ] || fail "make did not regenerate the engine after linebot.iface changed"

# The trace: two sensors, each with its Black and White column; White is not Black on a board.
awk -F, 'NR > 1 && ($1 == $2 || $3 == $4) { print "row " NR ": White must be the opposite of Black"; bad = 1 }
         END { exit bad }' "$trace" || fail "$trace"
ticks=$(($(wc -l < "$trace") - 1))

# What the reference interpreter calls in each tick: the motor state after tick k, "L R" (1 on).
"$gfec" run "$source_dir/samples/line_follower.sfc" --inputs "$trace" --observable > "$work/reference.log"
awk '/^tick / { if (tick) print left, right; tick = $2 }
     /^call Left_FW\(\)/ { left = 1 } /^call Left_Stop\(\)/ { left = 0 }
     /^call Right_FW\(\)/ { right = 1 } /^call Right_Stop\(\)/ { right = 0 }
     END { print left, right }' left=0 right=0 "$work/reference.log" > "$work/expected"
[ "$(wc -l < "$work/expected")" -eq "$ticks" ] || fail "gfec run printed $(wc -l < "$work/expected") ticks, not $ticks"

# The sensors as pins (Uno D2 = PD2 left, D3 = PD3 right; high over black): tick k's 5 ms early.
awk -F, -v per=$cycles_per_tick 'NR > 1 { k = NR - 1; at = (k - 1) * per - per / 2; if (at < 0) at = 0
                                          print at, "PD2=" $1, "PD3=" $3 }' "$trace" > "$work/pins.script"

# Run until the middle of the last tick: the sketch never halts, so avr-run ends it (exit 3).
status=0
"$avr_run" --mcu atmega328p --max-cycles $(((ticks - 1) * cycles_per_tick + cycles_per_tick / 2)) \
  --pins "$work/pins.script" --pin-log "$work/pins.log" "$elf" > "$work/uart.out" 2> "$work/avr-run.err" || status=$?
[ "$status" -eq 3 ] || fail "avr-run exited $status, expected 3 (the run's end): $(cat "$work/avr-run.err")"

# Every motor pin change in the first 2 ms of a tick.
awk -v per=$cycles_per_tick '$1 % per >= per / 5 { print "pin change at cycle " $1 " (" $2 "), " ($1 % per) / 16000 " ms into a tick"; bad = 1 }
                             END { exit bad }' "$work/pins.log" || fail "motor pins changed outside a tick's start"

# The motors 5 ms into each tick, from the driver's pins: ENA D5 = PD5, IN1 D7 = PD7, IN2 D8 = PB0,
# ENB D6 = PD6, IN3 D9 = PB1, IN4 D10 = PB2.
awk -v per=$cycles_per_tick -v ticks="$ticks" '
  function motor(en, in1, in2) {
    if (en && in1 && !in2) return 1
    if (!en && !in1 && !in2) return 0
    return "EN=" en "/IN1=" in1 "/IN2=" in2
  }
  { split($2, kv, "="); at[NR] = $1; pin[NR] = kv[1]; value[NR] = kv[2] }
  END {
    i = 1
    for (k = 1; k <= ticks; ++k) {
      t = (k - 1) * per + per / 2
      while (i <= NR && at[i] <= t) { level[pin[i]] = value[i]; ++i }
      print motor(level["PD5"] + 0, level["PD7"] + 0, level["PB0"] + 0), motor(level["PD6"] + 0, level["PB1"] + 0, level["PB2"] + 0)
    }
  }' "$work/pins.log" > "$work/got"

if ! diff "$work/expected" "$work/got" > "$work/diff"; then
  echo "tick: expected (interpreter) | got (Uno under simavr), 'left right', 1 = forward"
  paste -d'|' "$work/expected" "$work/got" | awk '{ print NR ": " $0 }' >&2
  fail "the motors differ from gfec run's calls"
fi
transitions=$(awk 'NR > 1 && $0 != prev { ++n } { prev = $0 } END { print n + 0 }' "$work/expected")
echo "Uno under simavr: $ticks ticks, motors as gfec run says in every one ($transitions ticks changed them)"
