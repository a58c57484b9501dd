#!/usr/bin/env bash
# gfec's children, signals, time and sizes as a hostile chart or a careless caller would test
# them (docs/security.md, "Child processes and signals", "Time and size limits"): Graphviz under
# a time limit, SIGTERM while dot, cc or a test harness runs, gfec run's memory and --ticks, and
# gfec test's tick budget and harness output. Every run is under `timeout` and `ulimit -v`, so a
# regression fails the test instead of taking the machine down. A slow stand-in for dot or cc
# (a script on PATH or in $CC that writes its pid and sleeps) makes the signal cases exact.
# Usage: reliability.sh GFEC SOURCE_DIR
set -euo pipefail
# Memory bounds on the runs; none under AddressSanitizer (tests/sanitize.sh), which reserves
# terabytes of address space for its shadow memory and aborts under any such limit.
vmem=2000000 vmem_small=300000
[ -z "${ASAN_OPTIONS:-}" ] || vmem=unlimited vmem_small=unlimited
gfec=$1 source_dir=$2
work=$(mktemp -d)
stray=()  # pids of stand-ins that survived, killed on the way out so a failure leaves none
cleanup() {
  for p in "${stray[@]}"; do kill -9 "$p" 2>/dev/null || true; done
  if [ -f "$work/pids" ]; then while read -r p; do kill -9 "$p" 2>/dev/null || true; done < "$work/pids"; fi
  rm -rf "$work"
}
trap cleanup EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
if ! command -v dot >/dev/null; then
  [ "${CI:-}" = true ] && fail "Graphviz's dot is missing (scripts/install-deps.sh installs it)"
  echo "skipped: Graphviz's dot is not installed"; exit 0
fi
real_dot=$(command -v dot)
cd "$work"
cp "$source_dir"/samples/{line_follower.sfc,linebot.iface,line_follower.test} .
mkdir bin slow tmp
# bin/dot: the real dot, its pid written down; slow/dot and slow/cc: pid written, then a sleep.
printf '#!/bin/sh\necho $$ >>"%s/pids"\nexec "%s" "$@"\n' "$work" "$real_dot" > bin/dot
printf '#!/bin/sh\necho $$ >>"%s/pids"\nexec sleep 300\n' "$work" > slow/dot
cp slow/dot slow/cc
chmod +x bin/dot slow/dot slow/cc
limited() { (ulimit -v "$vmem"; TMPDIR="$work/tmp" timeout 120 "$@"); }
# No stand-in may outlive the run, and TMPDIR must be as it was.
no_survivors() {
  local what=$1 p
  sleep 0.2
  if [ -f pids ]; then
    while read -r p; do
      if kill -0 "$p" 2>/dev/null; then stray+=("$p"); fail "$what: child $p survived"; fi
    done < pids
    rm pids
  fi
  [ -z "$(ls -A tmp)" ] || fail "$what: left in TMPDIR: $(ls -A tmp)"
}
wait_for_pid() { for _ in $(seq 100); do [ -s pids ] && return; sleep 0.1; done; fail "$1: the stand-in never started"; }

# 1. Item 5: a legal hierarchy 12 levels deep takes Graphviz minutes; under a 1 s limit, gfec
#    stops dot and says so: exit 1, nothing written, nothing left.
{
  echo 'interface Deep { bool Go(); void Step(); }'
  echo 'sfc C12 { initial place A { Step(); } place B; A -> B when Go(); B -> A when Go(); }'
  for ((k = 11; k >= 0; k--)); do
    echo "sfc C$k { initial place A runs C$((k + 1)); place B runs C$((k + 1)); A -> B when Go(); B -> A when Go(); }"
  done
} > deep.sfc
set +e
start=$SECONDS
PATH="$work/bin:$PATH" GFEC_TOOL_TIMEOUT=1 limited "$gfec" --emit=svg deep.sfc -o deep.svg 2>err; code=$?
set -e
[ $code -eq 1 ] || fail "deep hierarchy: exit $code, not 1 ($(cat err))"
grep -q "took longer than 1 s and was stopped" err || fail "deep hierarchy: message: $(cat err)"
grep -q GFEC_TOOL_TIMEOUT err || fail "deep hierarchy: the message does not name the setting"
[ $((SECONDS - start)) -lt 30 ] || fail "deep hierarchy: the limit was not kept"
[ ! -e deep.svg ] || fail "deep hierarchy: an output was written"
no_survivors "deep hierarchy"
# ... and gfec run --html the same: the picture is drawn before the run, which costs nothing then.
set +e
PATH="$work/bin:$PATH" GFEC_TOOL_TIMEOUT=1 limited "$gfec" run deep.sfc --html deep.html >/dev/null 2>err; code=$?
set -e
[ $code -eq 1 ] || fail "run --html on the deep hierarchy: exit $code ($(cat err))"
grep -q "took longer than 1 s" err || fail "run --html on the deep hierarchy: message: $(cat err)"
no_survivors "run --html on the deep hierarchy"

# 2. Item 6: SIGTERM while dot runs (--emit=svg, gfec run --html) stops dot and removes the
#    temporary files /tmp/gfec-tool-*; the signal then ends gfec as it would have (143).
for cmd in "--emit=svg line_follower.sfc -o lf.svg" "run line_follower.sfc --html lf.html"; do
  rm -f pids
  # shellcheck disable=SC2086 # the words of $cmd are gfec's arguments
  PATH="$work/slow:$PATH" limited "$gfec" $cmd >/dev/null 2>&1 &
  pid=$!
  wait_for_pid "$cmd"
  kill -TERM "$(pgrep -P "$pid")"  # gfec itself, not timeout(1)
  set +e; wait "$pid"; code=$?; set -e
  [ $code -eq 143 ] || fail "SIGTERM during '$cmd': exit $code, not 143"
  no_survivors "SIGTERM during '$cmd'"
  [ ! -e lf.svg ] && [ ! -e lf.html ] || fail "SIGTERM during '$cmd': an output was written"
done

# 3. Item 6: SIGTERM to gfec test while the C compiler runs: the compiler's process group is
#    stopped and the build folder ($TMPDIR/gfec-test-*) removed.
rm -f pids
CC="$work/slow/cc" limited "$gfec" test line_follower.test >/dev/null 2>&1 &
pid=$!
wait_for_pid "gfec test"
kill -TERM "$(pgrep -P "$pid")"
set +e; wait "$pid"; code=$?; set -e
[ $code -eq 143 ] || fail "SIGTERM during gfec test: exit $code, not 143"
no_survivors "SIGTERM during gfec test"

# 4. Item 9: --ticks is 1 to 10,000,000 (CLI11's check names the option); the log is printed as
#    it goes, so a million ticks fit in 300 MB of address space (they took 782 MB of RSS before).
for bad in -1 0 10000001 1e3; do
  set +e; limited "$gfec" run line_follower.sfc --ticks "$bad" >/dev/null 2>err; code=$?; set -e
  [ $code -eq 2 ] || fail "--ticks $bad: exit $code, not 2"
  grep -q -- "--ticks" err || fail "--ticks $bad: message: $(cat err)"
done
set +e; limited "$gfec" run line_follower.sfc --ticks 100001 --html big.html >/dev/null 2>err; code=$?; set -e
[ $code -eq 2 ] && grep -q "at most 100000" err || fail "--html past its tick bound: exit $code: $(cat err)"
(ulimit -v "$vmem_small"; timeout 120 "$gfec" run line_follower.sfc --ticks 1000000 > log.txt) ||
  fail "a million ticks do not run in 300 MB"
[ "$(grep -c '^tick ' log.txt)" -eq 1000000 ] || fail "a million ticks: $(grep -c '^tick ' log.txt) tick lines"
rm log.txt

# 5. Item 20: all the tests of a file run at most 10,000,000 ticks: an error at the step past it,
#    before anything runs; and the harness's records come through a pipe, so a long test writes
#    nothing that grows in TMPDIR (an 8 MB file-size limit: the 300,000-tick test's output was 28 MB).
{
  echo 'import "line_follower.sfc";'
  for i in $(seq 11); do printf 'test "t%d" of LineFollower {\n  tick 1000000;\n}\n' "$i"; done
} > budget.test
set +e; timeout 30 "$gfec" test budget.test 2>err >/dev/null; code=$?; set -e
[ $code -eq 1 ] || fail "tick budget: exit $code, not 1"
grep -q "budget.test:33:8: error: the tests of this file run more than 10000000 ticks in all" err ||
  fail "tick budget: message: $(cat err)"
printf 'import "line_follower.sfc";\ntest "long" of LineFollower {\n  tick 300000;\n  expect active(LeftFw);\n}\n' > long.test
(ulimit -f 8192; limited "$gfec" test long.test > out.txt 2>&1) || fail "a long test under a file-size limit: $(tail -5 out.txt)"
grep -q "1 passed, 0 failed" out.txt || fail "a long test: $(tail -5 out.txt)"
no_survivors "a long test"
echo "reliability: all passed"
