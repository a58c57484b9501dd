#!/usr/bin/env bash
# A transition written 'else' (docs/language.md §5) changes no tick: the C engine of a chart with
# 'else' is the one of the same chart without it, byte for byte; a scenario written by hand from
# §5.1 holds on the interpreter and the C engine; --emit=chart writes 'else' back and gfec reads it.
# Usage: else_transition.sh GFEC
set -euo pipefail
gfec=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
mkdir "$work/with" "$work/without" "$work/back"
cat > "$work/with/light.sfc" <<'CHART'
interface Lamp { bool Black(); bool White(); bool Arrived(); void Go(); void Stop(); }
sfc Light {
  initial place Wait;
  place Run { Go(); }
  place Park { Stop(); }
  place Idle;
  Wait -> Run when Black();
  Wait -> Park else when Arrived();
  Wait -> Idle else;
  Run -> Wait when White();
  Park -> Wait when White();
  Idle -> Wait when White();
}
CHART
sed 's/ else//' "$work/with/light.sfc" > "$work/without/light.sfc"
grep -q ' else' "$work/without/light.sfc" && fail "sed left an else"

# Without 'else', -Wall -Werror refuses the chart; with it, the chart passes.
if "$gfec" --check -Wall -Werror "$work/without/light.sfc" 2>"$work/err"; then fail "no -Wconflict without else"; fi
grep -q '\[-Werror=conflict\]' "$work/err" || fail "expected -Wconflict: $(cat "$work/err")"
"$gfec" --check -Wall -Werror "$work/with/light.sfc" || fail "-Wconflict despite else"

for d in with without; do (cd "$work/$d" && "$gfec" --emit=c light.sfc -o light.c); done
cmp "$work/with/light.c" "$work/without/light.c" || fail "'else' changed the engine"
cmp "$work/with/light.h" "$work/without/light.h" || fail "'else' changed the header"

# Black and Arrived both true: the first transition wins; then 'else when', then plain 'else'.
cat > "$work/with/light.test" <<'CHART'
import "light.sfc";
test "else follows declaration order" of Light {
  set Black = true; set Arrived = true;
  tick;
  expect active(Run) && !active(Park) && !active(Idle);
  set Black = false; set White = true;
  tick;
  expect active(Wait);
  set White = false;
  tick;
  expect active(Park) && !active(Idle);
  set Arrived = false; set White = true;
  tick;
  expect active(Wait);
  set White = false;
  tick;
  expect active(Idle);
}
CHART
(cd "$work/with" && "$gfec" test light.test) >"$work/out" 2>&1 || fail "scenario: $(cat "$work/out")"
grep -q '1 passed, 0 failed' "$work/out" || fail "scenario: $(cat "$work/out")"

# --emit=chart writes 'else' back; the chart it writes compiles to the same engine.
(cd "$work/with" && "$gfec" --emit=chart light.sfc -o "$work/back/light.sfc")
grep -q 'transition Wait -> Park else when Arrived();' "$work/back/light.sfc" || fail "$(cat "$work/back/light.sfc")"
grep -q 'transition Wait -> Idle else;' "$work/back/light.sfc" || fail "$(cat "$work/back/light.sfc")"
(cd "$work/back" && "$gfec" --check -Wall -Werror light.sfc && "$gfec" --emit=c light.sfc -o light.c --no-line-directives)
(cd "$work/with" && "$gfec" --emit=c light.sfc -o plain.c --no-line-directives)
diff <(sed 1,3d "$work/with/plain.c") <(sed 1,3d "$work/back/light.c") || fail "the chart written back compiles differently"
echo "ok"
