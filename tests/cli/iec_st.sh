#!/usr/bin/env bash
# IEC structured text read end to end (docs/iec.md): for each program of tests/iec/st,
# `gfec run --observable` on its trace prints NAME.expected (checked by hand against docs/iec.md
# "The scan" and "Action control"); the C engine in both forms, driven by a caller generated from
# the engine's header and fed the same trace, prints the same lines; --emit=chart writes chart
# text that compiles to the same engine byte for byte; --check, --analyze and --emit=json|dot
# succeed, and -x iec-st reads the file under another extension.
# Usage: iec_st.sh GFEC SOURCE_DIR
set -euo pipefail
gfec=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
caller=$(cd "$(dirname "$0")" && pwd)/engine_caller.py
dir=$(cd "$2" && pwd)/tests/iec/st
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
command -v python3 > /dev/null || fail "python3 is needed (scripts/install-deps.sh installs it)"


cd "$work"
for st in "$dir"/*.st; do
  name=$(basename "$st" .st)
  chart=$(grep -i -m1 -o '^ *program  *[A-Za-z_0-9]*' "$st" | awk '{print $2}')
  "$gfec" run "$st" --inputs "$dir/$name.csv" --observable > run.txt
  diff -u "$dir/$name.expected" run.txt || fail "$name: gfec run differs from $name.expected"
  "$gfec" --check "$st" || fail "$name: --check"
  "$gfec" --analyze "$st" > /dev/null || fail "$name: --analyze"
  "$gfec" --emit=json "$st" -o model.json && grep -q '"name": "'"$chart"'"' model.json || fail "$name: --emit=json"
  "$gfec" --emit=dot "$st" -o chart.dot && grep -q digraph chart.dot || fail "$name: --emit=dot"
  rm -rf direct back && mkdir direct back
  cp "$st" direct/prog.st
  "$gfec" --emit=chart direct/prog.st -o back/prog.sfc
  cp "$st" program.txt
  "$gfec" -x iec-st --check program.txt || fail "$name: -x iec-st"
  for form in readable scalable; do
    "$gfec" "$st" --engine=$form -o engine.c
    python3 "$caller" engine.h "$dir/$name.csv" "$chart" > main.c
    cc -std=c99 -Wall -Wextra -Wpedantic -Werror main.c engine.c -o run || fail "$name: the $form engine does not build"
    ./run > engine.txt
    diff -u "$dir/$name.expected" engine.txt || fail "$name: the $form engine differs from gfec run"
    (cd direct && "$gfec" prog.st --engine=$form --no-line-directives -o engine.c)
    (cd back && "$gfec" prog.sfc --engine=$form --no-line-directives -o engine.c)
    # Byte for byte but for the first line, which names the source file (prog.st, prog.sfc).
    cmp <(tail -n +2 direct/engine.c) <(tail -n +2 back/engine.c) || fail "$name: the converted chart compiles to another $form engine"
    cmp <(tail -n +2 direct/engine.h) <(tail -n +2 back/engine.h) || fail "$name: the converted chart compiles to another $form header"
  done
done
# Several PROGRAMs: the one the CONFIGURATION's task runs is compiled, --chart picks another;
# when the tasks run both, --chart is needed.
{ sed '/^CONFIGURATION/,$d' "$dir/tank.st"
  printf 'PROGRAM Other\n VAR_OUTPUT o : BOOL; END_VAR\n INITIAL_STEP A: END_STEP\nEND_PROGRAM\n'
  sed -n '/^CONFIGURATION/,$p' "$dir/tank.st"; } > several.st
"$gfec" several.st -o several.c || fail "several PROGRAMs: the one the task runs does not compile"
grep -q 'void Tank_run' several.h || fail "several PROGRAMs: not the one the task runs"
"$gfec" several.st --chart Other -o several.c && grep -q 'void Other_run' several.h || fail "several PROGRAMs: --chart"
sed 's/^\( *\)PROGRAM Tank1 WITH Fast : Tank;/&\n\1PROGRAM Other1 WITH Fast : Other;/' several.st > both.st
grep -q 'Other1 WITH' both.st || fail "both.st not made"
if "$gfec" both.st -o both.c 2> err.txt; then fail "several PROGRAMs, both run: compiled one"; fi
grep -q 'choose one with --chart' err.txt || fail "several PROGRAMs, both run: $(cat err.txt)"
# Located variables keep their address in the model's JSON and as a comment of the chart text.
"$gfec" --emit=json "$dir/located.st" -o located.json
grep -q '"address": "%QD0"' located.json || fail "located.st: --emit=json has no address"
"$gfec" --emit=chart "$dir/located.st" -o located.sfc
grep -q '^ *in bool Start;  // AT %IX0.0$' located.sfc || fail "located.st: --emit=chart: $(cat located.sfc)"
# A byte-order mark and CR LF line ends, as Windows editors write them, read as any file.
"$gfec" --check "$dir/../../fuzz/corpus_iec/bom_crlf.st" || fail "a file with a byte-order mark and CR LF"
# gfec test against an imported IEC program (docs/testing-charts.md "Testing an IEC program"): a
# test file imports the .st file; each test runs on the interpreter and on the C engine, which
# must agree on the program's sized-integer and TIME outputs too. A wrong expectation fails.
tests=$2/tests/iec/test
source "$(dirname "$caller")/scenario_checks.sh"
tests_pass "$tests/blink.test" 4
# `set` of a program's VAR_INPUTs (a BOOL latch and an INT limit): honoured on both runs, so the
# expectations that would hold if it were ignored fail, each on both runs.
tests_pass "$tests/counter.test" 3
tests_fail_with "$tests/counter_wrong.test" \
  "counter_wrong.test:8:3: error: expectation failed: Count == 0 \[expectation\]" \
  "counter_wrong.test:14:3: error: expectation failed: Count == 3 \[expectation\]"
tests_fail_with "$tests/wrong.test" "wrong.test:25:3: error: expectation failed: Cycles == 11 \[expectation\]"
echo "iec_st: ok"
