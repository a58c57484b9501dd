#!/usr/bin/env bash
# scripts/live-avr.sh, the one command that shows the line follower on the emulated AVR live
# (docs/live.md "The emulated AVR live"), with --log instead of the page: the UART's frames,
# decoded by gfec monitor, must be what the reference interpreter does on the same sensor values
# (gfec run --observable, call lines removed), tick for tick, none lost. About 5 s.
# Usage: live_avr.sh GFEC AVR_RUN SOURCE_DIR
set -euo pipefail
gfec=$(realpath "$1") avr_run=$(realpath "$2") source_dir=$(realpath "$3")
if ! command -v avr-gcc > /dev/null; then
  echo "avr-gcc is missing (scripts/install-deps.sh installs Debian's gcc-avr and avr-libc)"
  [ -n "${CI:-}" ] && exit 1
  exit 77
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

# 3 s: 300 ticks, the sensor trace's 16 rows looped.
GFEC=$gfec AVR_RUN=$avr_run "$source_dir/scripts/live-avr.sh" --seconds 3 --log > "$work/got.log" 2> "$work/err.txt" ||
  fail "live-avr.sh: $(cat "$work/err.txt")"
grep -q "^gfec monitor: 300 ticks decoded, 0 lost, 0 bytes garbled" "$work/err.txt" || fail "summary: $(cat "$work/err.txt")"
trace=$source_dir/tests/targets/avr/line_follower_trace.csv
{ head -1 "$trace"; for _ in $(seq 19); do tail -n +2 "$trace"; done; } | head -301 > "$work/inputs.csv"
"$gfec" run "$source_dir/samples/line_follower.sfc" --inputs "$work/inputs.csv" --observable | grep -v '^call ' \
  > "$work/expected.log"
diff "$work/expected.log" "$work/got.log" > "$work/diff.txt" || fail "the AVR's decoded run differs: $(head -20 "$work/diff.txt")"
echo "live-avr.sh --log: $(grep -c '^tick' "$work/got.log") ticks from the emulated ATmega328P as gfec run --observable"

# Bad use is said, not run.
status=0
GFEC=$gfec AVR_RUN=$avr_run "$source_dir/scripts/live-avr.sh" --seconds x --log > /dev/null 2>&1 || status=$?
[ "$status" -eq 2 ] || fail "--seconds x: exit $status, expected 2"
