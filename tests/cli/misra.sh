#!/usr/bin/env bash
# The C engines against MISRA C:2012, as cppcheck's misra addon checks it: the sample charts in
# every engine form that applies (an sfc readable and scalable -- both sparse; a sequential chart
# in the scalable form, single switch and in parts above 1,024 places; an fsm readable and
# scalable, a switch on the state, and in parts above 1,024 states; with --trace (and =calls) three
# samples, both forms among them), each
# in every build mode (plain, -DX_HOOKS, -DX_CHECKS, both). Any finding whose rule is not in the
# deviation record fails the test, and so does a deviation that no finding needs any more: the
# record (tests/cli/misra_deviations.txt, explained in docs/misra.md) stays exactly what the
# engines need.
# Usage: misra.sh GFEC SOURCE_DIR [--counts]   (--counts: print the findings per rule, never fail)
set -euo pipefail
gfec=$1 source_dir=$2 counts_only=${3:-}
work=${MISRA_KEEP:-$(mktemp -d)}
[ -n "${MISRA_KEEP:-}" ] || trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
command -v cppcheck >/dev/null || fail "no cppcheck (Debian: cppcheck; scripts/install-deps.sh)"
deviations="$source_dir/tests/cli/misra_deviations.txt"
[ -f "$deviations" ] || fail "no deviation record $deviations"

# A ring of 1,100 places, one token: the sequential layout written in parts (docs/c-engine.md,
# "Large charts"). P0 has entry and exit code and a timer, so every part kind is written.
ring="$work/ring.sfc"
{
  echo "interface Bench { bool Go(int i); void Act(int i); void Mark(); }"
  echo "sfc Ring {"
  echo "  period 10ms;"
  echo "  initial place P0 { entry { Mark(); } exit { Mark(); } Act(0); }"
  for i in $(seq 1 1099); do echo "  place P$i { Act($i); }"; done
  echo "  transition T0: P0 -> P1 when Go(0) && elapsed(P0) >= 20ms;"
  for i in $(seq 1 1099); do echo "  transition T$i: P$i -> P$(((i + 1) % 1100)) when Go($i);"; done
  echo "}"
} >"$ring"

# An fsm of 1,100 states: its scalable form, switches on the state written in parts (docs/c-engine.md,
# "Large fsms"). S0 has entry and exit code and a timer; S1 ends in success, S1099 in failure.
chain="$work/chain.fsm"
{
  echo "interface Bench { bool Go(int i); void Act(int i); void Mark(); }"
  echo "fsm Chain {"
  echo "  period 10ms;"
  echo "  initial state S0 { entry { Mark(); } exit { Mark(); } Act(0); }"
  echo "  success state S1;"
  for i in $(seq 2 1098); do echo "  state S$i { Act($i); }"; done
  echo "  failure state S1099;"
  echo "  S0 -> S1 when Go(0) && elapsed(S0) >= 20ms;"
  echo "  S0 -> S2 when Go(1);"
  for i in $(seq 2 1098); do echo "  S$i -> S$((i + 1)) when Go($i);"; done
  echo "  S1098 -> S0 when Go(0);"
  echo "}"
} >"$chain"

# chart|form: the samples (an fsm's readable form is its chain of tests, its scalable form a
# switch on the state), a sequential chart of the golden tests, a chart with inputs and outputs.
jobs=()
for chart in "$source_dir"/samples/*.sfc; do jobs+=("$chart|readable" "$chart|scalable"); done
for chart in "$source_dir"/samples/*.fsm; do jobs+=("$chart|readable" "$chart|scalable"); done
jobs+=("$source_dir/tests/golden/c/door_scalable.sfc|scalable" "$ring|scalable" "$chain|scalable")
# A chart with inputs and outputs (docs/language.md §14): the caller's fields.
jobs+=("$source_dir/tests/iec/mixer.sfc|readable" "$source_dir/tests/iec/mixer.sfc|scalable")
# Named actions under action control (docs/iec.md "Action control"): a sequential chart, so its
# scalable form is the switch on the one active place.
jobs+=("$source_dir/tests/iec/actions.sfc|readable" "$source_dir/tests/iec/actions.sfc|scalable")
# SD, DS and SL: the flags and timers of stored actions.
jobs+=("$source_dir/tests/iec/stored.sfc|readable" "$source_dir/tests/iec/stored.sfc|scalable")
# --trace (docs/live.md): the frame writer in both forms, with sub-chart instances and a team.
jobs+=("$source_dir/samples/line_follower.sfc|scalable+trace" "$source_dir/samples/mission.fsm|readable+calls"
  "$source_dir/samples/fetch_team.fsm|scalable+trace")

findings="$work/findings"
: >"$findings"
runs=0
for job in "${jobs[@]}"; do
  chart=${job%|*} form=${job#*|}
  base=$(basename "${chart%.*}")
  dir="$work/$base-$form"
  mkdir -p "$dir"
  trace=()
  [[ $form == *+trace ]] && trace=(--trace)
  [[ $form == *+calls ]] && trace=(--trace=calls)
  "$gfec" --engine="${form%+*}" "${trace[@]}" -I "$source_dir/samples" -I "$(dirname "$chart")" -o "$dir/$base.c" "$chart" ||
    fail "gfec $chart"
  name=$(sed -n 's/^void \([A-Za-z0-9_]*\)_init(.*/\1/p' "$dir/$base.h")
  [ -n "$name" ] || fail "no _init in $base.h"
  # Rule 20.13 (a directive is a valid one) is deviated for #line only, which cppcheck 2.10's
  # addon does not know: no other directive may appear.
  grep -hE '^[[:space:]]*#' "$dir/$base.c" "$dir/$base.h" |
    grep -vE '^#(include|define|undef|if|ifdef|ifndef|elif|else|endif|line|error|pragma) ?' &&
    fail "$base ($form): a directive other than the standard ones"
  for mode in plain hooks checks both; do
    # What cppcheck reads is valid C99 in this mode (cppcheck itself takes much that gcc rejects).
    # -D selects one configuration; -U keeps cppcheck from trying the others.
    case $mode in
      plain) defines=(-U"${name}_HOOKS" -U"${name}_CHECKS") ;;
      hooks) defines=(-D"${name}_HOOKS" -U"${name}_CHECKS") ;;
      checks) defines=(-U"${name}_HOOKS" -D"${name}_CHECKS") ;;
      both) defines=(-D"${name}_HOOKS" -D"${name}_CHECKS") ;;
    esac
    gcc -std=c99 -Wall -Wextra -Wpedantic -Werror -fsyntax-only -I "$dir" "${defines[@]}" "$dir/$base.c" 2>"$work/out" ||
      fail "$base ($form, $mode) does not compile: $(cat "$work/out")"
    (cd "$dir" && cppcheck --addon=misra --std=c99 --quiet --error-exitcode=0 -I . "${defines[@]}" \
      --template='{id}|{file}:{line}|{severity}: {message}' "$base.c") 2>"$work/out" ||
      fail "cppcheck on $base ($form, $mode)"
    # The addon's findings, and cppcheck's own errors (a syntax error would hide the rest); not
    # its information notes (which checks it skipped), which vary between versions.
    grep -E '^(misra-[^|]*\|.*|[^|]*\|[^|]*\|error: .*)$' "$work/out" | sed "s/^/$base-$form|$mode|/" >>"$findings" || true
    runs=$((runs + 1))
  done
done
[ "$runs" -ge 32 ] || fail "only $runs cppcheck runs"

# Findings per rule (cppcheck's counts, summed over every engine and mode).
echo "cppcheck misra findings per rule ($runs runs: engine x form x mode):"
cut -d'|' -f3 "$findings" | sed 's/^misra-c2012-//' | sort -V | uniq -c | awk '{ printf "  %-8s %d\n", $2, $1 }'
echo "  total    $(wc -l <"$findings")"
[ "$counts_only" = --counts ] && exit 0

# The record: `RULE WHERE` per line ('#' starts a comment line), WHERE an extended regular
# expression that the flagged line of the generated file must match, or `*` for any line (a rule
# whose findings cppcheck places at lines of the chart, through #line).
mapfile -t records < <(grep -vE '^[[:space:]]*(#|$)' "$deviations")
declare -A used=()
status=0
while IFS='|' read -r engine mode id where message; do
  rule=${id#misra-c2012-}
  file=${where%:*} line=${where##*:}
  [[ $file == /* ]] || file="$work/$engine/$file"
  text=
  ok=0
  for k in "${!records[@]}"; do
    read -r r pattern <<<"${records[$k]}"
    [ "$r" = "$rule" ] || continue
    if [ "$pattern" != '*' ]; then
      [ -n "$text" ] || text=$(sed -n "${line}p" "$file" 2>/dev/null)
      grep -qE -- "$pattern" <<<"$text" || continue
    fi
    ok=1 used[$k]=1
    break
  done
  if [ $ok -eq 0 ]; then
    echo "FAIL: $engine ($mode) $where: $id is not in the deviation record: $message" >&2
    [ -n "$text" ] && echo "  $text" >&2
    status=1
  fi
done <"$findings"
for k in "${!records[@]}"; do
  [ -n "${used[$k]:-}" ] ||
    { echo "FAIL: deviation '${records[$k]}' is recorded but no finding needs it any more: remove it" >&2; status=1; }
done
[ $status -eq 0 ] || exit 1
echo "misra: $runs cppcheck runs, every finding is one of the ${#records[@]} recorded deviations"
