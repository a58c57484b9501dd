#!/usr/bin/env bash
# Small things a new user trips over (issue 41 point 11): the toolbox skeleton's default names are
# the ones the plans' wiring includes.
# Usage: first_hour.sh GFEC SOURCE_DIR
set -euo pipefail
gfec=$1 source_dir=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
cd "$work"
cp "$source_dir"/samples/{square.plan,square_side.plan,carbot.toolbox} .

# Without -o, the skeleton is written under the names the wiring of a plan includes.
"$gfec" --emit=toolbox-skeleton carbot.toolbox
"$gfec" square.plan
included=$(sed -n 's/^#include "\(.*_toolbox\.h\)"$/\1/p' square.cpp square.hpp | sort -u)
[ -n "$included" ] || fail "the wiring includes no toolbox header"
for h in $included; do [ -f "$h" ] || fail "the wiring includes $h, which the skeleton did not write: $(ls)"; done
[ -f carbot_toolbox.cpp ] || fail "no skeleton source beside the header: $(ls)"
grep -q '#include "carbot_toolbox.h"' carbot_toolbox.cpp || fail "the skeleton source does not include its header"
echo "first_hour: all checks passed"
