#!/usr/bin/env bash
# gfec monitor as a user runs it (docs/live.md): the line follower engine built with --trace in a
# host program (tests/cli/monitor/lf_robot.c) that writes its frames to stdout or serves them on a
# TCP port of 127.0.0.1; `gfec monitor --log` decodes them and must print what `gfec run
# --observable` prints for the same inputs, call lines removed. Then a stream that goes quiet
# (--silence), a stream cut short, another chart's stream (exit 1, located), a file that is no
# serial port, and usage errors. About 3 s.
# Usage: monitor.sh GFEC SOURCE_DIR
set -euo pipefail
gfec=$(realpath "$1") source_dir=$(realpath "$2")
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
robot_pid=
cleanup() {
  if [ -n "$robot_pid" ]; then kill "$robot_pid" 2> /dev/null || true; fi
  rm -rf "$work"
}
trap cleanup EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
cd "$work"

# A run long enough for several full frames: the AVR test's trace, repeated.
csv=$work/inputs.csv
head -1 "$source_dir/tests/targets/avr/line_follower_trace.csv" > "$csv"
for _ in 1 2 3 4 5 6; do tail -n +2 "$source_dir/tests/targets/avr/line_follower_trace.csv" >> "$csv"; done
chart=$source_dir/samples/line_follower.sfc
"$gfec" run "$chart" --inputs "$csv" --observable | grep -v '^call ' > expected.log
[ "$(grep -c '^tick' expected.log)" -ge 90 ] || fail "the reference run is too short"

"$gfec" "$chart" --trace -o lf.c
cc -std=c99 -Wall -Wextra -Werror -I. "$here/monitor/lf_robot.c" lf.c -o robot

# stdin
./robot "$csv" | "$gfec" monitor "$chart" --log > got.log 2> summary.txt
diff expected.log got.log || fail "the decoded stdin stream differs from gfec run --observable"
grep -q "ticks decoded, 0 lost, 0 bytes garbled" summary.txt || fail "summary: $(cat summary.txt)"
echo "stdin: $(grep -c '^tick' got.log) ticks as gfec run --observable"

# --trace=calls: the whole observable log, calls with their results.
mkdir calls
"$gfec" "$chart" --trace=calls -o calls/lf.c
cc -std=c99 -Wall -Wextra -Werror -Icalls "$here/monitor/lf_robot.c" calls/lf.c -o robot-calls
"$gfec" run "$chart" --inputs "$csv" --observable > expected-calls.log
./robot-calls "$csv" | "$gfec" monitor "$chart" --log > got-calls.log 2> /dev/null
diff expected-calls.log got-calls.log || fail "--trace=calls: the decoded stream differs from gfec run --observable"
echo "stdin, --trace=calls: the same, calls included"

# TCP: the robot listens, the monitor connects.
./robot "$csv" --listen port.txt &
robot_pid=$!
for _ in $(seq 100); do [ -s port.txt ] && break; sleep 0.05; done
[ -s port.txt ] || fail "the robot did not listen"
"$gfec" monitor "$chart" --log --tcp "127.0.0.1:$(cat port.txt)" > tcp.log 2> tcp.err || fail "tcp: $(cat tcp.err)"
wait "$robot_pid"
robot_pid=
diff expected.log tcp.log || fail "the decoded TCP stream differs"
echo "tcp: the same"

# A link that goes quiet for 2 s after tick 10: reported, and nothing lost.
./robot "$csv" --pause-after 10 2 | "$gfec" monitor "$chart" --log --silence 0.5 > quiet.log 2> /dev/null
grep -q '^# silent for' quiet.log || fail "no silence reported"
grep -q '^# data again' quiet.log || fail "no end of the silence reported"
diff expected.log <(grep -v '^#' quiet.log) || fail "a quiet link changed the log"

# A stream cut inside a frame: the ticks before it, and the loss said.
./robot "$csv" > stream.bin
head -c 700 stream.bin | "$gfec" monitor "$chart" --log > cut.log 2> /dev/null
grep -q '^# lost: the stream ended inside a frame' cut.log || fail "a cut stream: $(tail -2 cut.log)"
diff <(grep -v '^#' cut.log) <(head -n "$(grep -vc '^#' cut.log)" expected.log) || fail "a cut stream's ticks differ"

# Another chart's stream: exit 1, an error located at that chart's name.
status=0
"$gfec" monitor "$source_dir/samples/work_cell.sfc" -I "$source_dir/samples" --log < stream.bin > other.log 2> other.err ||
  status=$?
[ "$status" = 1 ] || fail "another chart's stream: exit $status, not 1"
grep -Eq '^.*work_cell\.sfc:[0-9]+:[0-9]+: error: the stream comes from another chart: its fingerprint is [0-9a-f]{8}, the chart.s [0-9a-f]{8}' other.err ||
  fail "another chart's stream: $(cat other.err)"
grep -q '\[stream-refused\]$' other.err || fail "another chart's stream: not reported as a diagnostic: $(cat other.err)"
[ ! -s other.log ] || fail "another chart's stream printed ticks"

# Sources and usage.
status=0
"$gfec" monitor "$chart" --log --serial /dev/null < /dev/null 2> serial.err || status=$?
{ [ "$status" = 2 ] && grep -q "not a serial port" serial.err; } || fail "--serial /dev/null: exit $status, $(cat serial.err)"
status=0
"$gfec" monitor "$chart" --log --serial /dev/null --baud 12345 2> baud.err || status=$?
{ [ "$status" = 2 ] && grep -q "not a rate" baud.err; } || fail "--baud 12345: exit $status, $(cat baud.err)"
status=0
"$gfec" monitor "$chart" < stream.bin 2> nolog.err || status=$?
{ [ "$status" = 2 ] && grep -q "give --log" nolog.err; } || fail "no --log: exit $status"
status=0
"$gfec" monitor "$chart" --log --tcp nowhere < /dev/null 2> tcp.err || status=$?
{ [ "$status" = 2 ] && grep -q "HOST:PORT" tcp.err; } || fail "--tcp nowhere: exit $status, $(cat tcp.err)"
# The engine's options.
for bad in "--trace-full-every 5|needs --trace" "--trace --trace-full-every 0|must be 1 ... 65535"; do
  status=0
  # shellcheck disable=SC2086 # the options are words
  "$gfec" "$chart" ${bad%|*} -o bad.c 2> bad.err || status=$?
  { [ "$status" = 2 ] && grep -q -- "${bad#*|}" bad.err; } || fail "gfec ${bad%|*}: exit $status, $(cat bad.err)"
done
# A chart whose frame would not fit the 16-bit length: refused, nothing written.
{
  echo "interface B { bool Go(); }"
  echo "sfc Big {"
  echo "  initial place P0;"
  for i in $(seq 1 8200); do echo "  place P$i;"; done
  for i in $(seq 0 8199); do echo "  transition P$i -> P$((i + 1)) when Go();"; done
  echo "}"
} > big.sfc
status=0
"$gfec" big.sfc --trace -o big.c 2> big.err || status=$?
{ [ "$status" = 2 ] && grep -q "8201 values a frame" big.err && [ ! -e big.c ]; } ||
  fail "a chart too large for a frame: exit $status, $(cat big.err)"
"$gfec" "$chart" --trace --trace-full-every 1 -o every.c
[ "$(grep -c 'm->trace_left = 0u;' every.c)" = 2 ] || fail "--trace-full-every 1: not every frame full"
echo "monitor: all checks passed"
