#!/usr/bin/env bash
# gfec --check as CI runs it: every file validated, every diagnostic reported, nothing written;
# exit 1 on any error, 0 on warnings alone unless -Werror, 2 for an unreadable file.
# Usage: check.sh GFEC
set -euo pipefail
gfec=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
mkdir "$work/charts"
cd "$work/charts"
# What gfec prints goes outside the folder being checked, whose listing must not change.
out="$work/out" err="$work/err"

cat > robot.iface <<'CHART'
interface Robot { bool Ready(); void Go(); }
CHART
cat > good.sfc <<'CHART'
import "robot.iface";
sfc Good { initial place A { Go(); } place B; A -> B when Ready(); B -> A when !Ready(); }
CHART
cat > warn.sfc <<'CHART'
import "robot.iface";
sfc Warn { initial place A { Go(); } place B; place Island; A -> B when Ready(); B -> A; }
CHART
cat > bad1.sfc <<'CHART'
import "robot.iface";
sfc Bad1 { initial place A { Go(); } A -> Nowhere when Ready(); }
CHART
cat > bad2.sfc <<'CHART'
sfc Bad2 { initial place A
CHART
listing() { ls -lA --time-style=full-iso "$work/charts"; stat -c %y "$work/charts"; }
before=$(listing)

set +e
"$gfec" --check good.sfc >"$out" 2>"$err"; code=$?
set -e
[ $code -eq 0 ] || fail "a good file: exit $code"
[ ! -s "$err" ] && [ ! -s "$out" ] || fail "a good file printed something"

set +e
"$gfec" --check warn.sfc 2>"$err"; code=$?
set -e
[ $code -eq 0 ] || fail "warnings alone must exit 0, not $code"
grep -q "warn.sfc:2:.*warning: .*Island.*\[-Wunreachable-place\]" "$err" || fail "no warning: $(cat "$err")"
set +e
"$gfec" --check -Werror warn.sfc 2>"$err"; code=$?
set -e
[ $code -eq 1 ] || fail "-Werror: exit $code"
grep -q "error: .*Island.*\[-Werror=unreachable-place\]" "$err" || fail "-Werror: $(cat "$err")"

# Every file is checked and every diagnostic reported, the bad ones around a good one.
set +e
"$gfec" --check bad1.sfc good.sfc warn.sfc bad2.sfc 2>"$err"; code=$?
set -e
[ $code -eq 1 ] || fail "errors: exit $code"
grep -q "^bad1.sfc:2:.*error: .*Nowhere" "$err" || fail "bad1 not reported: $(cat "$err")"
grep -q "^warn.sfc:2:.*warning:" "$err" || fail "warn not reported: $(cat "$err")"
grep -q "^bad2.sfc:.*error:" "$err" || fail "bad2 not reported: $(cat "$err")"
grep -q "good.sfc" "$err" && fail "good.sfc reported: $(cat "$err")"

# An unreadable file is an I/O error (2), and the others are still checked.
set +e
"$gfec" --check missing.sfc bad1.sfc 2>"$err"; code=$?
set -e
[ $code -eq 2 ] || fail "missing file: exit $code"
grep -q "cannot read 'missing.sfc'" "$err" || fail "$(cat "$err")"
grep -q "^bad1.sfc:2:" "$err" || fail "bad1 not checked after a missing file"

# --check writes nothing, whatever the format; -o and -MD are refused.
"$gfec" --check -fdiagnostics-format=json good.sfc 2>/dev/null
"$gfec" --check -fdiagnostics-format=sarif-stderr good.sfc 2>/dev/null
[ "$(listing)" = "$before" ] || fail "--check wrote something: $(listing)"
set +e
"$gfec" --check -o x.c good.sfc 2>/dev/null; c1=$?
"$gfec" --check -MD good.sfc 2>/dev/null; c2=$?
set -e
[ $c1 -eq 2 ] && [ $c2 -eq 2 ] || fail "--check with -o/-MD: exit $c1 $c2"
# gcc's flags as CI passes them: the gutter, -Werror's closing line, -w, -Werror=NAME,
# -Wno-error=NAME, colour only when asked (a file is not a terminal), the error limit's wording.
"$gfec" --check -Werror warn.sfc 2>"$err" && fail "-Werror passed"
grep -q "^    2 | sfc Warn" "$err" || fail "no line-number gutter: $(cat "$err")"
grep -q "^      | .*\^~~~~~" "$err" || fail "no caret under the gutter: $(cat "$err")"
grep -q "^gfec: some warnings being treated as errors$" "$err" || fail "no -Werror summary: $(cat "$err")"
"$gfec" --check -w -Werror warn.sfc 2>"$err" || fail "-w -Werror failed"
[ ! -s "$err" ] || fail "-w printed: $(cat "$err")"
"$gfec" --check -Werror=unreachable-place warn.sfc 2>"$err" && fail "-Werror=NAME passed"
grep -q "\[-Werror=unreachable-place\]" "$err" || fail "-Werror=NAME: $(cat "$err")"
"$gfec" --check -Werror -Wno-error=unreachable-place warn.sfc 2>"$err" || fail "-Wno-error=NAME failed"
grep -q "warning: .*\[-Wunreachable-place\]" "$err" || fail "-Wno-error=NAME: $(cat "$err")"
"$gfec" --check warn.sfc 2>"$err"
grep -q $'\33' "$err" && fail "colour in a file"
"$gfec" --check -fdiagnostics-color=always warn.sfc 2>"$err"
grep -q $'\33\\[01;35m\33\\[Kwarning:' "$err" || fail "no colour with always: $(cat -v "$err")"
NO_COLOR=1 "$gfec" --check -fdiagnostics-color=auto warn.sfc 2>"$err"
grep -q $'\33' "$err" && fail "colour despite NO_COLOR"
if command -v script >/dev/null; then
  # A terminal: auto colours it, unless NO_COLOR says not to.
  script -qec "'$gfec' --check warn.sfc" /dev/null >"$out" 2>&1 || true
  grep -q $'\33\\[01;35m' "$out" || fail "no colour on a terminal: $(cat -v "$out")"
  NO_COLOR=1 script -qec "'$gfec' --check warn.sfc" /dev/null >"$out" 2>&1 || true
  grep -q $'\33' "$out" && fail "colour on a terminal despite NO_COLOR: $(cat -v "$out")"
fi
"$gfec" --check -fno-diagnostics-show-line-numbers warn.sfc 2>"$err"
grep -q " | " "$err" && fail "gutter despite -fno-diagnostics-show-line-numbers"
"$gfec" --check -fdiagnostics-parseable-fixits bad1.sfc 2>"$err" && fail "bad1 passed"
printf 'sfc Two { initial place A; A -> X; A -> Y; }\n' > two.sfc
"$gfec" --check -fmax-errors=1 two.sfc 2>"$err" && fail "two errors passed"
grep -q "^compilation terminated due to -fmax-errors=1\.$" "$err" || fail "limit: $(cat "$err")"
printf 'sfc Fix { initial place Ready; place Done; Ready -> Dnoe; Done -> Ready; }\n' > fix.sfc
"$gfec" --check -fdiagnostics-parseable-fixits fix.sfc 2>"$err" && fail "fix.sfc passed"
grep -q '^fix-it:"fix.sfc":{1:53-1:57}:"Done"$' "$err" || fail "no parseable fix-it: $(cat "$err")"
# Counts in the --analyze summaries are singular or plural as they should be.
printf 'sfc One { initial place A; place B; A -> B; }\n' > one.sfc
"$gfec" --analyze one.sfc >"$out" 2>"$err" || fail "--analyze one.sfc: $(cat "$err")"
grep -q "sfc One: 2 places, 1 transition$" "$out" || fail "plural: $(cat "$out")"
grep -q "never active: 0 places; never firing: 0 transitions$" "$out" || fail "plural: $(cat "$out")"
# A folder: every file below it of a language gfec reads, sub-folders too, hidden ones not,
# other files left alone; the worst exit code wins.
mkdir -p "$work/tree/sub/deeper" "$work/tree/.hidden"
printf 'interface Bot { bool Ready(); void Go(); }\n' > "$work/tree/bot.iface"
printf 'import "bot.iface";\nsfc Top { initial place A { Go(); } place B; A -> B when Ready(); B -> A; }\n' > "$work/tree/top.sfc"
printf 'import "../../bot.iface";\nsfc Deep { initial place A; A -> Gone; }\n' > "$work/tree/sub/deeper/deep.sfc"
printf 'sfc Island { initial place A; place Lost; A -> A; }\n' > "$work/tree/sub/island.fsm"
printf 'sfc Hidden { initial place A; A -> Nowhere; }\n' > "$work/tree/.hidden/hidden.sfc"
printf 'not a chart\n' > "$work/tree/sub/notes.txt"
set +e
(cd "$work" && "$gfec" --check tree/) >"$out" 2>"$err"; code=$?
set -e
[ $code -eq 1 ] || fail "folder: exit $code: $(cat "$err")"
grep -q "^tree/sub/deeper/deep.sfc:2:.*error: .*Gone" "$err" || fail "folder: deep.sfc not checked: $(cat "$err")"
grep -q "^tree/sub/island.fsm:1:.*warning: .*Lost" "$err" || fail "folder: island.fsm not checked: $(cat "$err")"
grep -q "hidden\|notes" "$err" && fail "folder: a hidden folder or another file checked: $(cat "$err")"
(cd "$work/tree" && "$gfec" --check . sub/../top.sfc 2>/dev/null) && fail "folder '.' passed despite errors below it"
(cd "$work/tree" && "$gfec" --check top.sfc bot.iface) || fail "the good files of the folder fail"
mkdir "$work/nothing"
set +e
"$gfec" --check "$work/nothing" 2>"$err"; code=$?
set -e
[ $code -eq 2 ] || fail "an empty folder: exit $code"
grep -q "folder '.*nothing' holds no file" "$err" || fail "an empty folder: $(cat "$err")"
echo "gfec --check: all checks passed"
