#!/usr/bin/env bash
# Inputs and outputs of a chart (docs/language.md §14, docs/iec.md): `gfec run --observable` on
# tests/iec/mixer.sfc prints the `out` lines of mixer.expected (worked out by hand from §5.1: the
# trace's input columns set before each tick); the C engine, fed the same inputs through its
# fields by a small caller, prints the same lines; --emit=chart writes `in`/`out` back and the
# converted text compiles to the same engine byte for byte.
# Usage: iec_io.sh GFEC SOURCE_DIR
set -euo pipefail
gfec=$1
caller=$(cd "$(dirname "$0")" && pwd)/engine_caller.py
dir=$2/tests/iec
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

"$gfec" run "$dir/mixer.sfc" --inputs "$dir/mixer.csv" --observable > "$work/run.txt"
diff -u "$dir/mixer.expected" "$work/run.txt" || fail "gfec run differs from mixer.expected"

# The engine's caller: sets the inputs before each tick (as the trace's rows do), runs, prints.
cd "$work"
"$gfec" "$dir/mixer.sfc" -o engine.c
python3 "$caller" engine.h "$dir/mixer.csv" Mixer "$(grep -c '^tick ' "$dir/mixer.expected")" > main.c
for form in readable scalable; do
  "$gfec" "$dir/mixer.sfc" --engine=$form -o engine.c
  cc -std=c99 -Wall -Wextra -Wpedantic -Werror main.c engine.c -o run || fail "the $form engine does not build"
  ./run > engine.txt
  diff -u "$dir/mixer.expected" engine.txt || fail "the $form engine differs from gfec run"
done

# --emit=chart: in/out written back; the converted chart, under the same name, gives the same
# engine (without #line, which names the file and its lines).
mkdir direct back
cp "$dir/mixer.sfc" direct/mixer.sfc
"$gfec" --emit=chart direct/mixer.sfc -o back/mixer.sfc
grep -q '^ *in bool Start;' back/mixer.sfc || fail "--emit=chart lost 'in bool Start'"
grep -q '^ *out int Batches = 0;' back/mixer.sfc || fail "--emit=chart lost 'out int Batches'"
for d in direct back; do (cd $d && "$gfec" mixer.sfc --no-line-directives -o engine.c); done
cmp direct/engine.c back/engine.c || fail "the converted chart compiles to another engine"
cmp direct/engine.h back/engine.h || fail "the converted chart compiles to another header"

# gfec test sets the inputs (`set Start = true;`) on the interpreter and on the C engine: every
# type an input may have; an expectation that would hold if `set` were ignored fails on both.
tests=$2/tests/iec/test
source "$(dirname "$caller")/scenario_checks.sh"
tests_pass "$tests/inputs.test" 4
tests_fail_with "$tests/inputs_wrong.test" \
  "inputs_wrong.test:8:3: error: expectation failed: Seen == 5 \[expectation\]" \
  "inputs_wrong.test:16:3: error: expectation failed: Tally == 12 \[expectation\]"
echo "iec_io: ok"
