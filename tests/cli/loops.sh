#!/usr/bin/env bash
# Loops (docs/language.md §10) through the command line: --emit=chart writes the loops of
# tests/run/loops.sfc and loops.fsm back as chart text that compiles to the same engine in both
# forms (the charts themselves are in gfec fmt's layout); gfec run stops a runaway loop with a located error
# (exit 1); --check refuses a loop that can never end.
# Usage: loops.sh GFEC SOURCE_DIR
set -euo pipefail
gfec=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
dir=$(cd "$2" && pwd)/tests/run
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

cd "$work"
for chart in loops.sfc loops.fsm; do
  rm -rf direct back && mkdir direct back
  cp "$dir/$chart" direct/
  "$gfec" fmt --check "direct/$chart" > /dev/null || fail "$chart: not in gfec fmt's layout"
  "$gfec" --emit=chart "direct/$chart" -o "back/$chart"
  grep -q 'for (' "back/$chart" || fail "$chart: --emit=chart wrote no 'for'"
  for form in readable scalable; do
    (cd direct && "$gfec" "$chart" --engine=$form --no-line-directives -o engine.c)
    (cd back && "$gfec" "$chart" --engine=$form --no-line-directives -o engine.c)
    cmp <(tail -n +2 direct/engine.c) <(tail -n +2 back/engine.c) || fail "$chart: the converted chart compiles to another $form engine"
  done
done

cat > runaway.sfc << 'CHART'
sfc Runaway {
  in bool go;
  var int i = 0;
  initial place A {
    while (go) { i += 1; }
  }
}
CHART
printf 'go\n0\n1\n' > trace.csv
if "$gfec" run runaway.sfc --inputs trace.csv --observable > out.txt 2> err.txt; then fail "a runaway loop: gfec run succeeded"; fi
grep -q '^runaway.sfc:5:5: error: this loop ran more than 1000000 times in one tick.* during tick 2 \[runtime\]$' err.txt ||
  fail "a runaway loop: $(cat err.txt)"
grep -q '^tick 1$' out.txt || fail "a runaway loop: tick 1 was not printed"

sed 's/while (go)/while (true)/' runaway.sfc > forever.sfc
if "$gfec" --check forever.sfc 2> err.txt; then fail "while (true) without break: --check succeeded"; fi
grep -q "^forever.sfc:5:12: error: this 'while' loop never ends.*\[loop\]$" err.txt || fail "while (true): $(cat err.txt)"
echo "loops: ok"
