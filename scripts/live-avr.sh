#!/usr/bin/env bash
# The line follower engine on the emulated AVR, shown live (docs/live.md "The emulated AVR live"):
# builds samples/line_follower.sfc with `gfec --trace` for the ATmega328P (examples/avr-live), runs
# it under tools/avr-run at the part's real speed (--real-time) with its IR sensors driven from
# tests/targets/avr/line_follower_trace.csv (looped), and pipes its UART into `gfec monitor`, by
# default serving the live page:
#
#   scripts/live-avr.sh                          # http://127.0.0.1:8080/ until Ctrl-C
#   scripts/live-avr.sh --seconds 120 --http 127.0.0.1:0
#   scripts/live-avr.sh --seconds 2 --log        # the decoded log instead (gfec monitor --log)
#
# Options: --seconds S (emulated time, default 60); everything else goes to `gfec monitor`
# (default: --http 127.0.0.1:8080). Builds gfec and avr-run in build/ first when they are missing
# or stale (scripts/install-deps.sh installs what that needs). GFEC, AVR_RUN: other executables.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
seconds=60
monitor_args=()
while [ $# -gt 0 ]; do
  case $1 in
    --seconds)
      [ $# -ge 2 ] || { echo "live-avr.sh: --seconds needs a number" >&2; exit 2; }
      seconds=$2
      shift 2
      ;;
    *) monitor_args+=("$1"); shift ;;
  esac
done
[[ $seconds =~ ^[0-9]+([.][0-9]+)?$ ]] || { echo "live-avr.sh: --seconds $seconds: not a number of seconds" >&2; exit 2; }
[ ${#monitor_args[@]} -gt 0 ] || monitor_args=(--http 127.0.0.1:8080)

gfec=${GFEC:-} avr_run=${AVR_RUN:-}
if [ -z "$gfec" ] || [ -z "$avr_run" ]; then
  if [ ! -f "$root/build/build.ninja" ]; then
    cmake -S "$root" -B "$root/build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g1 -DNDEBUG" -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O2 -g1 -DNDEBUG" >&2
  fi
  cmake --build "$root/build" --target gfec avr-run >&2
  gfec=${gfec:-$root/build/gfec}
  avr_run=${avr_run:-$root/build/tools/avr-run/avr-run}
fi

# Paths given relative to where the script was started stay right after the cd below.
case $gfec in */*) gfec=$(realpath "$gfec") ;; esac
case $avr_run in */*) avr_run=$(realpath "$avr_run") ;; esac
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$root"  # the page and the log name the chart as the repository does
chart=samples/line_follower.sfc
"$gfec" "$chart" --trace -o "$work/line_follower.c"
avr-gcc -mmcu=atmega328p -DF_CPU=16000000UL -Os -std=c99 -Wall -Wextra -I "$work" \
  -o "$work/line_follower.elf" "$root/examples/avr-live/line_follower_uart.c" "$work/line_follower.c"

# The sensors (D2 = PD2 left, D3 = PD3 right, high over black): tick k's row of the trace, looped,
# set 5 ms before the tick (tick k runs at (k - 1) x 10 ms = 160000 cycles a tick at 16 MHz).
per=160000
ticks=$(awk -v s="$seconds" 'BEGIN { printf "%d", s * 100 }')
[ "$ticks" -ge 1 ] || { echo "live-avr.sh: --seconds $seconds is less than a tick" >&2; exit 2; }
awk -F, -v per=$per -v ticks="$ticks" 'NR > 1 { row[n++] = "PD2=" $1 " PD3=" $3 }
  END { for (k = 1; k <= ticks; ++k) { at = (k - 1) * per - per / 2; if (at < 0) at = 0; print at, row[(k - 1) % n] } }' \
  "$root/tests/targets/avr/line_follower_trace.csv" > "$work/pins.script"

# avr-run stops the program (which never halts) in the middle of the last tick: exit 3, its end
# (its "timeout" line is then no error); anything else is said.
run_avr() {
  local status=0
  # Under the sanitizer pass (tests/sanitize.sh) LeakSanitizer would turn exit 3 into another code
  # for what libsimavr itself keeps at a timeout (its core and IRQ tables): not avr-run's own.
  ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0 \
  "$avr_run" --mcu atmega328p --real-time --max-cycles $(((ticks - 1) * per + per / 2)) --pins "$work/pins.script" \
    "$work/line_follower.elf" 2> "$work/avr-run.err" || status=$?
  [ "$status" -eq 3 ] || { cat "$work/avr-run.err" >&2; return 1; }
}
run_avr | "$gfec" monitor "$chart" "${monitor_args[@]}"
