#!/usr/bin/env bash
# gfec on ALICA plans as CI and make use it (docs/alica.md): --check over a folder of plans,
# located errors, -MD naming every file a plan references, -x, SARIF, the other back ends.
# Usage: alica.sh GFEC SOURCE_DIR
set -euo pipefail
gfec=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
cp -r "$src/tests/alica/." "$work/"
cd "$work"

# A folder of good plans: nothing to say, exit 0.
set +e
"$gfec" --check plans/*.pml >out 2>err; code=$?
set -e
[ $code -eq 0 ] || fail "good plans: exit $code: $(cat err)"
[ ! -s err ] || fail "good plans printed: $(cat err)"

# The broken ones: every file reported, each error located in its .pml, exit 1.
set +e
"$gfec" --check plans/broken/*.pml 2>err; code=$?
set -e
[ $code -eq 1 ] || fail "broken plans: exit $code"
for expect in \
  "^plans/broken/SelfLoop.pml:[0-9]*:[0-9]*: error: transition from state 'Spin' to itself \[self-transition\]" \
  "^plans/broken/SecondPair.pml:[0-9]*:[0-9]*: error: second transition from 'A' to 'B'" \
  "^plans/broken/LeavesTerminal.pml:[0-9]*:[0-9]*: error: transition leaves terminal state 'Finished'" \
  "^plans/broken/Disconnected.pml:[0-9]*:[0-9]*: error: state 'Island' is not connected" \
  "^plans/broken/TerminalBody.pml:[0-9]*:[0-9]*: error: terminal state 'Parked' cannot have a body" \
  "^plans/broken/NoEntryPoint.pml:1:1: error: plan 'NoEntryPoint' (id 1800000000200) has no entry point" \
  "^plans/broken/SharedEntry.pml:[0-9]*:[0-9]*: error: entry point 'Right' (id 1800000000304) starts in state 'Both'" \
  "^plans/broken/MissingFile.pml:37:28: error: cannot find 'Behaviours/SerchItem.beh'" \
  "note: did you mean 'Behaviours/SearchItem.beh'?" \
  "^plans/broken/MissingId.pml:37:28: error: 'plans/Behaviours/Park.beh' has no element with id 1700000000099" \
  "^plans/broken/Malformed.pml:8:3: error: malformed JSON" \
  "^plans/broken/Ignored.pml:[0-9]*:[0-9]*: warning: synchronisation 'Together' (id 1800000000040)" \
  "note: this is ALICA transition 'Again' (id 1800000000020) of plan 'SelfLoop' (id 1800000000000)"; do
  grep -q "$expect" err || fail "missing '$expect' in: $(cat err)"
done

# A member named twice: an error where gfec reads it and the second differs, located at the second
# name with a note at the first and the plan element it is in; a warning where it changes nothing.
set +e
"$gfec" --check published/etc/plans/Conflict.pml 2>err; code=$?
set -e
[ $code -eq 1 ] || fail "conflicting key: exit $code"
for expect in \
  "^published/etc/plans/Conflict.pml:9:7: error: member \"state\" is given a second time.*\[conflicting-key\]" \
  "^published/etc/plans/Conflict.pml:7:7: note: the first \"state\" is here" \
  "note: this is ALICA entry point .*(id 2100000000000000051) of plan 'Conflict'"; do
  grep -q "$expect" err || fail "missing '$expect' in: $(cat err)"
done
"$gfec" --check published/etc/plans/Twice.pml 2>err || fail "duplicate keys that change nothing: $(cat err)"
[ "$(grep -c 'warning: .*\[-Wduplicate-key\]' err)" = 3 ] || fail "duplicate keys: $(cat err)"
"$gfec" --check -Wno-duplicate-key published/etc/plans/Twice.pml 2>err && [ ! -s err ] ||
  fail "-Wno-duplicate-key: $(cat err)"

# A plan compiles like a chart; -MD lists the plan, its behaviours and the task repository.
mkdir build
"$gfec" plans/Fetch.pml -o build/fetch.c -MD
[ -s build/fetch.c ] && [ -s build/fetch.h ] || fail "no engine"
grep -q "void DriveToItem(void);" build/fetch.h || fail "no prototype in the header"
for dep in plans/Fetch.pml plans/Behaviours/DriveToItem.beh plans/Behaviours/PickUp.beh tasks/TaskRepository.tsk; do
  grep -q "$dep" build/fetch.d || fail "-MD misses $dep: $(cat build/fetch.d)"
done
"$gfec" --emit=json plans/Fetch.pml -o build/fetch.json
# The model's expressions, as --emit=chart writes them; never the JSON the condition was read from.
grep -q '"when": "Arrived()"' build/fetch.json || fail "--emit=json: $(grep '"when"' build/fetch.json)"
! grep -q '"\(when\|text\)": "{' build/fetch.json || fail "--emit=json writes JSON as an expression's text"
"$gfec" --emit=dot plans/Master.pml -o build/master.dot
grep -q "digraph" build/master.dot || fail "no DOT"

# -x: any file name as ALICA, or a .pml as chart text.
cp plans/Fetch.pml plans/fetch.json
"$gfec" -x alica --check plans/fetch.json || fail "-x alica"
set +e
"$gfec" -x gfec --check plans/Fetch.pml 2>err; code=$?
set -e
[ $code -eq 1 ] || fail "-x gfec on JSON: exit $code"
grep -q "^plans/Fetch.pml:1:1: error:" err || fail "-x gfec: $(cat err)"

# SARIF for code scanning, located in the .pml.
set +e
"$gfec" --check -fdiagnostics-format=sarif-stderr plans/broken/SelfLoop.pml 2>err; code=$?
set -e
[ $code -eq 1 ] || fail "sarif: exit $code"
grep -q '"uri": *"plans/broken/SelfLoop.pml"' err || fail "sarif: $(cat err)"
grep -q '"ruleId": *"self-transition"' err || fail "sarif rule: $(cat err)"

# ALICA's current folder layout (etc/plans, etc/behaviours, etc/conditions, etc/placeholders,
# etc/tasks) is found with no -I, a stale path by the search below etc/, and the engine compiles
# with gcc and clang without a warning.
"$gfec" --check -Wno-alica-ignored layout/etc/plans/Patrol.pml
"$gfec" -Wno-alica-ignored layout/etc/plans/Patrol.pml -o build/patrol.c -MD
grep -q "layout/etc/behaviours/Turn.beh" build/patrol.d || fail "-MD misses the file found below etc/: $(cat build/patrol.d)"
for cc in gcc clang; do
  command -v $cc >/dev/null || continue
  $cc -std=c99 -Wall -Wextra -Wpedantic -Werror -c build/patrol.c -o build/patrol.o || fail "$cc on patrol.c"
done
# ALICA's other files say what they are, located, exit 1; never read as chart text.
for f in layout/etc/behaviours/Look.beh layout/etc/plans/sub/Sweeps.pty layout/etc/tasks/taskrepository.tsk \
         layout/etc/conditions/ConditionRepository.cnd layout/etc/placeholders/Anything.plc; do
  set +e
  "$gfec" --check "$f" 2>err; code=$?
  set -e
  [ $code -eq 1 ] || fail "$f: exit $code"
  grep -q "^$f:1:1: error: '$f' is not an ALICA plan" err || fail "$f: $(cat err)"
  grep -q "note: this is an ALICA" err || fail "$f: $(cat err)"
done

# Converted to chart text, the plan compiles again.
"$gfec" --emit=chart plans/Master.pml -o build/master.sfc
"$gfec" build/master.sfc -o build/master.c
echo "alica: ok"
