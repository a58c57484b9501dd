# shellcheck shell=bash
# How the benchmarks measure, sourced by each (they set `work`, a scratch folder, first): the
# fastest of a few timed runs, and the instructions of an engine's tick under callgrind.

# fastest OUT_VAR RUNS command...: runs the command RUNS times and sets OUT_VAR to
# "<wall seconds> <user seconds> <peak KB>" (GNU time; the maximum RSS) of the fastest run. The
# cores are shared: the fastest run is the least disturbed one. A failing run stops the bench.
fastest() {
  # The locals are prefixed: OUT_VAR is set by name, and a local of that name would take it.
  local _var=$1 _runs=$2 _best="" _i _this
  shift 2
  for ((_i = 0; _i < _runs; ++_i)); do
    /usr/bin/time -f "%e %U %M" -o "$work/time" "$@" > /dev/null 2> "$work/err" || {
      echo "$(basename "$0"): failed: $*" >&2
      cat "$work/err" >&2
      exit 1
    }
    _this=$(tail -1 "$work/time")
    if [[ -z $_best ]] || awk -v a="${_this%% *}" -v b="${_best%% *}" 'BEGIN { exit !(a < b) }'; then _best=$_this; fi
  done
  printf -v "$_var" '%s' "$_best"
}

# tick_instructions PROGRAM CHART TICKS: the instructions of CHART's run function and every call
# it makes, per tick, over TICKS ticks of PROGRAM (built from engine_main.c); "-" without
# valgrind.
tick_instructions() {
  local program=$1 chart=$2 ticks=$3
  if ! command -v valgrind > /dev/null; then
    echo "-"
    return
  fi
  # A generated engine's run function carries the chart's fingerprint: X_run_regenerate_if_undefined_<hash>.
  valgrind --tool=callgrind --collect-atstart=no --toggle-collect="${chart}_run" \
    --toggle-collect="${chart}_run_regenerate_if_undefined_*" \
    --callgrind-out-file="$work/callgrind.out" "$program" "$ticks" > /dev/null 2>&1
  awk -v n="$ticks" '/^(summary|totals):/ { printf "%.0f\n", $2 / n; exit }' "$work/callgrind.out"
}

# engine_header DIR: the flag with which engine_main.c includes the generated header in DIR (its
# functions' names carry the chart's fingerprint, which only the header knows); nothing for a
# hand-written machine, which has none.
engine_header() {
  local h
  h=$(grep -l 'regenerate_if_undefined' "$1"/*.h 2> /dev/null | head -n 1 || true)
  [ -z "$h" ] || printf -- '-DENGINE_HEADER="%s"\n' "$(basename "$h")"
}
