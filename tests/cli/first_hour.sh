#!/usr/bin/env bash
# Small things a new user trips over (issue 41 point 11): the toolbox skeleton's default names are
# the ones the plans' wiring includes; the C engine's header and --analyze name one activation bound.
# Usage: first_hour.sh GFEC SOURCE_DIR
set -euo pipefail
gfec=$1 source_dir=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
cd "$work"
cp "$source_dir"/samples/{square.plan,square_side.plan,carbot.toolbox,work_cell.sfc,cellbot.iface} .

# Without -o, the skeleton is written under the names the wiring of a plan includes.
"$gfec" --emit=toolbox-skeleton carbot.toolbox
"$gfec" square.plan
included=$(sed -n 's/^#include "\(.*_toolbox\.h\)"$/\1/p' square.cpp square.hpp | sort -u)
[ -n "$included" ] || fail "the wiring includes no toolbox header"
for h in $included; do [ -f "$h" ] || fail "the wiring includes $h, which the skeleton did not write: $(ls)"; done
[ -f carbot_toolbox.cpp ] || fail "no skeleton source beside the header: $(ls)"
grep -q '#include "carbot_toolbox.h"' carbot_toolbox.cpp || fail "the skeleton source does not include its header"
# One activation bound: the header's comment on the counters and --analyze agree (work_cell forks,
# so its weights alone would prove 2 where no place ever holds more than 1). merge.sfc's C does
# hold 2.
cat > merge.sfc <<'CHART'
interface M { bool go(); }
sfc Merge { initial place A; initial place B; place C; A -> C when go(); B -> C; C -> A when go(); }
CHART
for chart in work_cell merge; do
  "$gfec" -w --emit=c "$chart.sfc" -o "$chart.c"
  header=$(sed -n 's/.*activation counter of each place (never above \([0-9]*\)).*/\1/p' "$chart.h")
  summary=$("$gfec" --analyze "$chart.sfc" 2>/dev/null | sed -n 's/.*safe: no place ever holds more than one activation.*/1/p;
                                                       s/.*bounded: no place holds more than \([0-9]*\) activations.*/\1/p')
  [ -n "$header" ] && [ "$header" = "$summary" ] || fail "$chart: the header says ${header:-nothing}, --analyze ${summary:-nothing}"
done
echo "first_hour: all checks passed"
