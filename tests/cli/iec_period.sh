#!/usr/bin/env bash
# --period (docs/iec.md "Time"): an IEC program without a TASK runs with it as it runs in a TASK
# of that INTERVAL; over a TASK's INTERVAL it wins (Step.T counts its scans: a log checked by hand
# below); the PLCopen reader takes it alike; chart text refuses it (a located error, exit 1); a
# value that is not a duration above 0 is a usage error (exit 2) of every command.
# Usage: iec_period.sh GFEC SOURCE_DIR
set -euo pipefail
gfec=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
st=$(cd "$2" && pwd)/tests/iec/st
xml=$(cd "$2" && pwd)/tests/iec/plcopen
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
cd "$work"

# timing.st without its CONFIGURATION: no task runs it, so its time reads have no period.
sed '/^CONFIGURATION/,$d' "$st/timing.st" > notask.st
grep -q TASK notask.st && fail "notask.st still has a TASK"
if "$gfec" --check notask.st 2> err.txt; then fail "a program without a TASK compiled without --period"; fi
grep -q "missing-period" err.txt || fail "no missing-period error: $(cat err.txt)"
grep -q "'--period 10ms'" err.txt || fail "the missing-period note does not name --period: $(cat err.txt)"

# With --period it runs as in its 100 ms TASK (timing.expected), whichever way it is written.
for p in 100ms 0.1s T#100ms TIME#100ms t#100MS; do
  "$gfec" run notask.st --inputs "$st/timing.csv" --observable --period "$p" > run.txt ||
    fail "--period $p: gfec run failed"
  diff -u "$st/timing.expected" run.txt || fail "--period $p differs from the 100 ms TASK"
done
"$gfec" --check notask.st --period 100ms || fail "gfec --check --period"
# gfec test reads the program as gfec does (the file has no tests: that error alone remains).
"$gfec" test notask.st > /dev/null 2> err.txt && fail "gfec test: a file without tests passed"
grep -q "missing-period" err.txt || fail "gfec test without --period: $(cat err.txt)"
"$gfec" test notask.st --period 100ms > /dev/null 2> err.txt && fail "gfec test: a file without tests passed"
grep -q "missing-period" err.txt && fail "gfec test --period 100ms still misses the period: $(cat err.txt)"
grep -q "declares no test" err.txt || fail "gfec test --period 100ms: $(cat err.txt)"
# gfec monitor too: with --period it gets as far as the device it cannot open.
"$gfec" monitor notask.st --log --serial "$work/no-such-tty" < /dev/null > /dev/null 2> err.txt &&
  fail "gfec monitor: a missing device opened"
grep -q "missing-period" err.txt || fail "gfec monitor without --period: $(cat err.txt)"
"$gfec" monitor notask.st --log --period 100ms --serial "$work/no-such-tty" < /dev/null > /dev/null 2> err.txt &&
  fail "gfec monitor: a missing device opened"
grep -q "cannot open" err.txt || fail "gfec monitor --period 100ms: $(cat err.txt)"

# Over the TASK's 100 ms: at 50 ms Wait.T is 50 ms in scan n, so `Wait.T = T#250ms` holds in scan
# 5 alone, `Wait.T > T#250ms` from scan 6, and `Wait.T > T#650ms` (700 ms) moves to Done in scan 14.
printf 'Hold\n' > hold.csv
for _ in $(seq 15); do printf '0\n' >> hold.csv; done
"$gfec" run "$st/timing.st" --inputs hold.csv --observable --period 50ms > run.txt
summary=$(awk '/^tick/ {t = $2} /^av/ {print t, $2 $3} /^out (Gt|Eq) = true/ {print t, $2}' run.txt | paste -sd' ')
expected="1 10 2 10 3 10 4 10 5 10 5 Eq 6 10 6 Gt 7 10 7 Gt 8 10 8 Gt 9 10 9 Gt 10 10 10 Gt 11 10 11 Gt"
expected="$expected 12 10 12 Gt 13 10 13 Gt 14 01 14 Gt 15 01 15 Gt"
[ "$summary" = "$expected" ] || fail "timing.st at --period 50ms: got '$summary', expected '$expected'"

# PLCopen: --period over the task's INTERVAL runs as a task of that INTERVAL does, and a file
# whose task is gone runs with --period as with its task.
sed 's/interval="T#100ms"/interval="T#50ms"/' "$xml/openplc.xml" > fifty.xml
grep -q 'interval="T#50ms"' fifty.xml || fail "fifty.xml kept its interval"
"$gfec" run fifty.xml --inputs "$xml/mixer.csv" --observable > task50.txt
"$gfec" run "$xml/openplc.xml" --inputs "$xml/mixer.csv" --observable --period 50ms > period50.txt
diff -u task50.txt period50.txt || fail "PLCopen: --period 50ms differs from a 50 ms task"
"$gfec" run "$xml/openplc.xml" --inputs "$xml/mixer.csv" --observable > task100.txt
cmp -s task50.txt task100.txt && fail "PLCopen: the period changes nothing in openplc.xml's log"
sed '/<task /,/<\/task>/d' "$xml/openplc.xml" > notask.xml
grep -q '<task' notask.xml && fail "notask.xml still has a task"
if "$gfec" --check notask.xml 2> err.txt; then fail "PLCopen: no task and no --period compiled"; fi
grep -q "missing-period" err.txt || fail "PLCopen: no missing-period error: $(cat err.txt)"
"$gfec" run notask.xml --inputs "$xml/mixer.csv" --observable --period T#100ms > period100.txt
diff -u task100.txt period100.txt || fail "PLCopen: --period T#100ms differs from the 100 ms task"

# Chart text declares its own period: --period is a located error there.
printf 'sfc A {\n  period 10ms;\n  initial place p;\n}\n' > a.sfc
"$gfec" --check a.sfc || fail "a.sfc does not compile"
set +e
"$gfec" --check a.sfc --period 10ms 2> err.txt
rc=$?
set -e
[ "$rc" = 1 ] || fail "chart text with --period: exit $rc, expected 1"
grep -q '^a.sfc:1:1: error: --period is for IEC programs.*\[period\]' err.txt || fail "chart text: $(cat err.txt)"

# A bad value: usage error, exit 2, for every command that reads a program.
for v in 0ms 10 abc -5ms T#0s 1.5ms. 10m; do
  for cmd in "" run test monitor; do
    set +e
    # shellcheck disable=SC2086
    "$gfec" $cmd notask.st --period "$v" > /dev/null 2> err.txt
    rc=$?
    set -e
    [ "$rc" = 2 ] || fail "gfec $cmd --period '$v': exit $rc, expected 2"
    grep -q "is not a duration above 0" err.txt || fail "gfec $cmd --period '$v': $(cat err.txt)"
  done
done
echo "iec_period: ok"
