#!/usr/bin/env bash
# gfec monitor on a plan's stream (docs/live.md "Plans"): the wiring gfec generates for
# samples/wall_follow.plan, samples/square.plan (a sub-plan) and tests/golden/cpp/formulas.plan (a
# failure) is compiled with the scripted test toolboxes and the run harness of the cpp back end's
# tests (tests/run/cpp/run_plan.cc), which logs what its afp::TraceObserver hears and, beside it,
# writes an afp::LinkTrace's frames to a file. `gfec monitor PLAN --log` must print the harness's
# event lines exactly. Then a garbled stream, a cut one, another plan's stream, a chart engine's
# stream given to a plan and a plan's to a chart (exit 1, located); the square once on the threaded
# executor. About 20 s (three compiles).
# Usage: monitor_plan.sh GFEC SOURCE_DIR RUNTIME_LIBRARY [LINK_FLAGS]
set -euo pipefail
gfec=$(realpath "$1") source_dir=$(realpath "$2") runtime=$(realpath "$3") link_flags=${4:-}
work=$(mktemp -d)
[ -z "${KEEP:-}" ] || echo "scratch: $work"
trap '[ -n "${KEEP:-}" ] || rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
cd "$work"
run_dir=$source_dir/tests/run/cpp

# build NAME PLAN_FILE FACTORY ENV: the generated wiring and the harness, as ./NAME.
build() {
  "$gfec" "$2" -w -o "$1.cpp"
  # shellcheck disable=SC2086 # LINK_FLAGS are words
  c++ -std=c++17 -Wall -Wextra -Werror -I . -I "$run_dir" -I "$source_dir/runtime/include" \
    "-DPLAN_HEADER=\"$1.hpp\"" "-DPLAN_FACTORY=make_$3" "-DPLAN_ENV=$4" "$run_dir/run_plan.cc" "$1.cpp" \
    "$runtime" $link_flags -pthread -o "$1"
}
# check NAME PLAN_FILE SCRIPT: runs the harness on the script (one line a 10 ms step); the monitor's
# log of the frames must be the harness's event lines (those that begin with the plan time).
check() {
  printf '%b' "$3" | "./$1" "link=$1.bin" > "$1.out"
  grep -E '^[0-9]+ ' "$1.out" > "$1.expected" || true
  [ -s "$1.expected" ] || fail "$1: the harness logged no event"
  "$gfec" monitor "$2" --log < "$1.bin" > "$1.log" 2> "$1.err" || fail "$1: $(cat "$1.err")"
  diff "$1.expected" "$1.log" || fail "$1: the decoded stream differs from the observer's log"
  grep -q " 0 lost, 0 bytes garbled" "$1.err" || fail "$1: $(cat "$1.err")"
  echo "$1: $(wc -l < "$1.log") events as the observer heard them, $(wc -c < "$1.bin") bytes"
}

wall=$source_dir/samples/wall_follow.plan
build wall "$wall" WallFollow Carbot
# The lane closes, a wall is found and followed, the application sets walldist, a touch, escape.
check wall "$wall" '\n\nlane=25\nwall=15\n\nset:walldist=40\nblocked\n\n\ntouch\n\n\n\n\nwall=-20\n\nescape\n'

square=$source_dir/samples/square.plan
build square "$square" Square Carbot
check square "$square" 'set:sides=2\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n'
# Escape, global in Square, stops the sub-plan from outside (its `end Side stopped`).
printf '\n\n\nescape\n' | ./square link=escape.bin > escape.out
"$gfec" monitor "$square" --log < escape.bin > escape.log 2> /dev/null
diff <(grep -E '^[0-9]+ ' escape.out) escape.log || fail "square, escape: the decoded stream differs"
grep -q '^30 end Side stopped$' escape.log || fail "square, escape: $(cat escape.log)"

# The threaded executor (the observer called from its thread only): the same events; the harness
# leaves its real plan times out, so they are compared without them.
printf 'set:sides=2\n' | ./square threaded link=threaded.bin > threaded.out
"$gfec" monitor "$square" --log < threaded.bin 2> /dev/null | sed -E 's/^[0-9]+ //' > threaded.log
diff <(grep -E '^(start|finish|interrupt|fail|end) ' threaded.out) threaded.log ||
  fail "square, threaded: the decoded stream differs"
grep -q '^end Square succeeded$' threaded.log || fail "square, threaded: $(cat threaded.log)"

formulas=$source_dir/tests/golden/cpp/formulas.plan
build formulas "$formulas" Formulas Probe
check formulas "$formulas" '\n\ntimeout\n\n'
grep -q '^30 fail Formulas.ee: division by zero in a formula$' formulas.log || fail "no failure: $(cat formulas.log)"

# A long run with heartbeats: walls followed for 2,000 steps (FORWARD_OK every 3 steps).
long_script="\n\nlane=20 wall=10\nwall=10\n$(for _ in $(seq 2000); do printf '\\n'; done)escape\n"
check wall "$wall" "$long_script"
cp wall.bin long.bin

# Garbled bytes in the middle: the loss is said, every event shown is one of the run's, in order.
size=$(wc -c < long.bin)
python3 - long.bin garbled.bin << 'PY'
import sys
data = bytearray(open(sys.argv[1], 'rb').read())
for at in range(len(data) // 3, len(data) // 3 + 60, 7):
    data[at] ^= 0x5A
open(sys.argv[2], 'wb').write(data)
PY
"$gfec" monitor "$wall" --log < garbled.bin > garbled.log 2> garbled.err || fail "garbled: $(cat garbled.err)"
grep -q '^# lost [0-9]* events\?: bad CRC or garbled bytes' garbled.log || fail "garbled: no loss said"
grep -Eq '^# at [0-9]+ ms running: (nothing|WallFollow\.)' garbled.log || fail "garbled: the state after the loss is not said"
grep -v '^#' garbled.log > garbled.events
[ "$(wc -l < garbled.events)" -lt "$(wc -l < wall.expected)" ] || fail "garbled: nothing lost?"
# Every event shown is the run's: the shown lines are a subsequence of the full log, in order.
python3 - wall.expected garbled.events << 'PY' || fail "garbled: an event was shown that the run did not have"
import sys
full = open(sys.argv[1]).read().splitlines()
shown = open(sys.argv[2]).read().splitlines()
i = 0
for line in shown:
    while i < len(full) and full[i] != line:
        i += 1
    if i == len(full):
        sys.exit(1)
    i += 1
PY
echo "garbled: $(wc -l < garbled.events) of $(wc -l < wall.expected) events shown, the loss said"

# A stream cut inside a frame: the events before it, and the loss said.
head -c $((size / 2)) long.bin | "$gfec" monitor "$wall" --log > cut.log 2> /dev/null
grep -q '^# lost: the stream ended inside a frame' cut.log || fail "a cut stream: $(tail -2 cut.log)"
diff <(grep -v '^#' cut.log) <(head -n "$(grep -vc '^#' cut.log)" wall.expected) || fail "a cut stream's events differ"

# A monitor that joins late: the first frame says what runs.
tail -c $((size / 2 + 3)) long.bin | "$gfec" monitor "$wall" --log > late.log 2> /dev/null
grep -Eq '^# lost [0-9]+ events?: (the stream joined the run at event|bad CRC)' late.log || fail "late: $(head -2 late.log)"
grep -Eq '^# at [0-9]+ ms running: (nothing|WallFollow\.)' late.log || fail "late: the state is not said"

# Another plan's stream: exit 1, located at the plan.
status=0
"$gfec" monitor "$square" --log < long.bin > other.log 2> other.err || status=$?
[ "$status" = 1 ] || fail "another plan's stream: exit $status, not 1"
grep -Eq '^.*square\.plan:[0-9]+:[0-9]+: error: the stream comes from another plan: its fingerprint is [0-9a-f]{8}, the plan.s [0-9a-f]{8}' other.err ||
  fail "another plan's stream: $(cat other.err)"
[ ! -s other.log ] || fail "another plan's stream printed events"

# A chart engine's stream given to a plan, and a plan's stream given to a chart.
chart=$source_dir/samples/line_follower.sfc
"$gfec" "$chart" --trace -o lf.c
cc -std=c99 -Wall -Wextra -Werror -I. "$source_dir/tests/cli/monitor/lf_robot.c" lf.c -o lf_robot
./lf_robot "$source_dir/tests/targets/avr/line_follower_trace.csv" > lf.bin
status=0
"$gfec" monitor "$wall" --log < lf.bin > /dev/null 2> chart.err || status=$?
[ "$status" = 1 ] && grep -q 'error: the stream comes from the C engine of a chart' chart.err ||
  fail "a chart's stream to a plan: exit $status, $(cat chart.err)"
status=0
"$gfec" monitor "$chart" --log < long.bin > /dev/null 2> plan.err || status=$?
[ "$status" = 1 ] && grep -q "error: the stream comes from a plan's afp::LinkTrace" plan.err ||
  fail "a plan's stream to a chart: exit $status, $(cat plan.err)"

# --http is for charts.
status=0
"$gfec" monitor "$wall" --http 127.0.0.1:0 < long.bin > /dev/null 2> http.err || status=$?
[ "$status" = 2 ] || fail "--http on a plan: exit $status, $(cat http.err)"
echo "refusals: another plan, a chart's engine, a plan to a chart monitor, --http: as documented"
