#!/usr/bin/env bash
# Named actions under action control (docs/iec.md "Action control"): `gfec run --observable` on
# tests/iec/actions.sfc (N R S P P0 P1 L D) and tests/iec/stored.sfc (SD DS SL) prints their
# .expected logs (checked by hand against docs/iec.md, tick by tick); the C engine in both forms,
# fed the same inputs by a small caller, prints the same lines; --emit=chart writes the actions
# and associations back and the converted text compiles to the same engine byte for byte;
# --emit=json lists them.
# Usage: iec_actions.sh GFEC SOURCE_DIR
set -euo pipefail
gfec=$1
caller=$(cd "$(dirname "$0")" && pwd)/engine_caller.py
dir=$2/tests/iec
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

cd "$work"

# check NAME TICKS: the interpreter, both engine forms and the round trip of tests/iec/NAME.sfc.
check() {
  local name=$1 ticks=$2 chart
  chart=$(grep -m1 -o '^sfc  *[A-Za-z_0-9]*' "$dir/$name.sfc" | awk '{print $2}')
  "$gfec" run "$dir/$name.sfc" --inputs "$dir/$name.csv" --observable --ticks "$ticks" > "$name.run"
  diff -u "$dir/$name.expected" "$name.run" || fail "gfec run differs from $name.expected"
  rm -rf direct back
  mkdir direct back
  cp "$dir/$name.sfc" direct/$name.sfc
  "$gfec" --emit=chart direct/$name.sfc -o back/$name.sfc
  for form in readable scalable; do
    "$gfec" "$dir/$name.sfc" --engine=$form -o engine.c
    python3 "$caller" engine.h "$dir/$name.csv" "$chart" "$ticks" > ${name}_main.c
    cc -std=c99 -Wall -Wextra -Wpedantic -Werror ${name}_main.c engine.c -o run || fail "the $form engine of $name does not build"
    ./run > engine.txt
    diff -u "$dir/$name.expected" engine.txt || fail "the $form engine of $name differs from gfec run"
    for d in direct back; do (cd $d && "$gfec" $name.sfc --engine=$form --no-line-directives -o engine.c); done
    cmp direct/engine.c back/engine.c || fail "the converted $name compiles to another $form engine"
    cmp direct/engine.h back/engine.h || fail "the converted $name compiles to another $form header"
  done
}

check actions 14
grep -q '^ *action Brief {' back/actions.sfc || fail "--emit=chart lost 'action Brief'"
grep -q '^ *L Brief 30ms;' back/actions.sfc || fail "--emit=chart lost 'L Brief 30ms'"
"$gfec" --emit=json "$dir/actions.sfc" -o model.json
grep -q '"qualifier": "P0"' model.json || fail "--emit=json lost the P0 association"
grep -q '"name": "Never"' model.json || fail "--emit=json lost action Never"

check stored 15
grep -q '^ *SD Horn 30ms;' back/stored.sfc || fail "--emit=chart lost 'SD Horn 30ms'"
grep -q '^ *DS Fan 20ms;' back/stored.sfc || fail "--emit=chart lost 'DS Fan 20ms'"
grep -q '^ *SL Lamp 40ms;' back/stored.sfc || fail "--emit=chart lost 'SL Lamp 40ms'"
grep -q '^ *SD Beep 0ms;' back/stored.sfc || fail "--emit=chart lost 'SD Beep 0ms'"
echo "iec_actions: ok"
