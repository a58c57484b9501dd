#!/usr/bin/env bash
# The plan runtime builds with -fno-rtti (firmware C++ often turns RTTI off): every source of
# runtime/src compiled with -fno-rtti at -Wall -Wextra -Werror, linked with a plan that uses
# sub-plans, computations and Objects (tests/cli/no_rtti/no_rtti_plan.cc), which must run.
# Usage: runtime_no_rtti.sh SOURCE_DIR [CXX]
set -euo pipefail
source_dir=$1 cxx=${2:-c++}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

flags=(-std=c++17 -fno-rtti -Wall -Wextra -Werror -O1 -I "$source_dir/runtime/include" -I "$source_dir/runtime/src")
objects=()
for src in "$source_dir"/runtime/src/*.cc "$source_dir/tests/cli/no_rtti/no_rtti_plan.cc"; do
  obj="$work/$(basename "${src%.cc}").o"
  "$cxx" "${flags[@]}" -c "$src" -o "$obj" 2>"$work/err" || fail "$(basename "$src") with -fno-rtti: $(cat "$work/err")"
  objects+=("$obj")
done
"$cxx" -pthread -o "$work/no_rtti_plan" "${objects[@]}" || fail "link"
# No RTTI symbol may come from the runtime's own classes (typeinfo for afp::...), exceptions aside.
if nm -C "${objects[@]}" 2>/dev/null | grep 'typeinfo for afp::' | grep -v -e 'Error' -e 'Exception' | grep -q ' [VDRW] '; then
  fail "RTTI of the runtime's classes is still emitted"
fi
"$work/no_rtti_plan" || fail "the plan did not run as expected"
echo "runtime with -fno-rtti: all checks passed"
