#!/usr/bin/env bash
# A program compiled against the header of another version of a chart must not link with the
# engine (docs/c-engine.md "Header and engine together"): the undefined name says to regenerate.
# And an engine compiled against a header that is not its own stops with #error. The same
# version of the chart, generated twice (by make in the folder, by CMake in its build folder),
# links: the fingerprint depends on the header's text, not on where or when it was written.
# Usage: stale_header.sh GFEC
set -euo pipefail
gfec=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
cd "$work"
mkdir old new same
printf 'interface Board { void Led(bool on); bool Button(); }\n' >board.iface
cat >old/blink.sfc <<'CHART'
import "../board.iface";
sfc Blink {
  period 100ms;
  initial place Off { Led(false); }
  place On { Led(true); }
  Off -> On when elapsed(Off) >= 500ms;
  On -> Off when elapsed(On) >= 500ms || Button();
}
CHART
# Two more places: a larger struct, the size the stale header gets wrong.
sed 's/^  place On { Led(true); }$/  place On { Led(true); }\n  place Dim { Led(false); }\n  place Dark { Led(false); }\n  On -> Dim when Button();\n  Dim -> Dark when Button();/' \
  old/blink.sfc >new/blink.sfc
cp old/blink.sfc same/blink.sfc
"$gfec" old/blink.sfc -o old/blink.c
"$gfec" new/blink.sfc -o new/blink.c
"$gfec" same/blink.sfc -o same/blink.c
cat >main.c <<'C'
#include "blink.h"
void Led(bool on) { (void)on; }
bool Button(void) { return false; }
int main(void) {
  Blink m;
  Blink_init(&m);
  Blink_run(&m);
  return 0;
}
C
for cc in ${CC_LIST:-cc clang}; do
  command -v "$cc" >/dev/null || { [ -z "${CI:-}" ] || fail "no $cc"; echo "skip $cc: not installed"; continue; }
  flags="-std=c99 -Wall -Wextra -Wpedantic -Werror"
  # The stale header first on the include path, the new engine linked.
  if $cc $flags -Iold main.c new/blink.c -o stale 2>link.txt; then fail "$cc: a program with a stale header linked"; fi
  grep -q "undefined reference to .Blink_init_regenerate_if_undefined_" link.txt ||
    grep -q "Blink_init_regenerate_if_undefined_.*referenced from\|undefined symbol: Blink_init_regenerate_if_undefined_" link.txt ||
    { cat link.txt; fail "$cc: the link error does not name the stamped Blink_init"; }
  # The new engine compiled where the stale header is found first.
  cp new/blink.c old/engine_new.c
  if $cc $flags -c old/engine_new.c -o engine.o 2>compile.txt; then fail "$cc: an engine compiled against a stale header"; fi
  grep -q "regenerate both from the chart" compile.txt || { cat compile.txt; fail "$cc: no #error naming regenerate"; }
  # The same chart generated elsewhere: one fingerprint, the program links and runs.
  $cc $flags -Iold main.c same/blink.c -o fresh && ./fresh
  $cc $flags -Inew main.c new/blink.c -o fresh && ./fresh
done
echo "stale headers refused"
