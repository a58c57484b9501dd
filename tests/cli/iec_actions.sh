#!/usr/bin/env bash
# Named actions under action control (docs/iec.md "Action control"): `gfec run --observable` on
# tests/iec/actions.sfc prints actions.expected (checked by hand against docs/iec.md, tick by
# tick); the C engine in both forms, fed the same inputs by a small caller, prints the same
# lines; --emit=chart writes the actions and associations back and the converted text compiles
# to the same engine byte for byte; --emit=json lists them.
# Usage: iec_actions.sh GFEC SOURCE_DIR
set -euo pipefail
gfec=$1
dir=$2/tests/iec
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

"$gfec" run "$dir/actions.sfc" --inputs "$dir/actions.csv" --observable --ticks 14 > "$work/run.txt"
diff -u "$dir/actions.expected" "$work/run.txt" || fail "gfec run differs from actions.expected"

cd "$work"
cat > main.c <<'C'
#include "engine.h"
#include <stdio.h>
int main(void)
{
    /* tick, Go, Level: the rows of actions.csv, which hold until the next row's tick */
    static const int rows[][3] = {{1, 0, 0}, {2, 1, 0}, {6, 1, 30}, {8, 0, 30}};
    Cycle m;
    int tick;
    int row = 0;
    Cycle_init(&m);
    for (tick = 1; tick <= 14; ++tick) {
        int p;
        if (row < 4 && rows[row][0] == tick) {
            m.Go = rows[row][1] != 0;
            m.Level = rows[row][2];
            ++row;
        }
        Cycle_run(&m);
        printf("tick %d\nav", tick);
        for (p = 0; p < Cycle_PLACE_COUNT; ++p) printf(" %u", (unsigned)Cycle_activation(&m, p));
        printf("\nout n = %d\nout p = %d\nout e = %d\nout s = %d\nout l = %d\nout d = %d\n", (int)m.n, (int)m.p,
               (int)m.e, (int)m.s, (int)m.l, (int)m.d);
    }
    return 0;
}
C
mkdir direct back
cp "$dir/actions.sfc" direct/actions.sfc
"$gfec" --emit=chart direct/actions.sfc -o back/actions.sfc
grep -q '^ *action Brief {' back/actions.sfc || fail "--emit=chart lost 'action Brief'"
grep -q '^ *L Brief 30ms;' back/actions.sfc || fail "--emit=chart lost 'L Brief 30ms'"
for form in readable scalable; do
  "$gfec" "$dir/actions.sfc" --engine=$form -o engine.c
  cc -std=c99 -Wall -Wextra -Wpedantic -Werror main.c engine.c -o run || fail "the $form engine does not build"
  ./run > engine.txt
  diff -u "$dir/actions.expected" engine.txt || fail "the $form engine differs from gfec run"
  for d in direct back; do (cd $d && "$gfec" actions.sfc --engine=$form --no-line-directives -o engine.c); done
  cmp direct/engine.c back/engine.c || fail "the converted chart compiles to another $form engine"
  cmp direct/engine.h back/engine.h || fail "the converted chart compiles to another $form header"
done

"$gfec" --emit=json "$dir/actions.sfc" -o model.json
grep -q '"qualifier": "P0"' model.json || fail "--emit=json lost the P0 association"
grep -q '"name": "Never"' model.json || fail "--emit=json lost action Never"
echo "iec_actions: ok"
