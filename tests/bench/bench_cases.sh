# shellcheck shell=bash disable=SC2034,SC2154 # shares variables both ways with the scripts that source it
# The benchmark cases bench_engine.sh and bench_size.sh share, sourced by both (they set `gfec`,
# `gen`, `here`, `root` and `work` first): the charts, the engine forms and how each machine is
# made. Charts: the line follower (samples/), a ring of 10 and of 1000 places with one token,
# and a fork into 100 parallel two-place loops (gfec_bench_gen).
bench_cases=(line_follower ring10 ring1000 branches100)

# The forms measured: the readable engine, the scalable one where this gfec writes it, and the
# hand-written switch machine of the same chart. (The help is read whole: `grep -q` on a pipe
# may close it before gfec is done writing, and under pipefail that SIGPIPE reads as "no".)
forms=(readable)
engine_opt=()
if [[ $("$gfec" --help 2>&1) == *--engine* ]]; then
  forms+=(scalable)
  engine_opt=(--engine=readable)
fi
forms+=(hand)

# chart_source NAME: writes the chart of a benchmark case to $work/NAME.sfc (with its imports)
# and the hand-written machine to $work/NAME_hand.c; sets `chart` to the chart's name.
chart_source() {
  case $1 in
    line_follower)
      cp "$root/samples/line_follower.sfc" "$root/samples/linebot.iface" "$work/"
      cp "$here/hand/line_follower_hand.c" "$work/line_follower_hand.c"
      chart=LineFollower ;;
    ring*)
      "$gen" chart ring "${1#ring}" > "$work/$1.sfc"
      "$gen" hand ring "${1#ring}" > "$work/$1_hand.c"
      chart=Ring ;;
    branches*)
      "$gen" chart branches "${1#branches}" > "$work/$1.sfc"
      "$gen" hand branches "${1#branches}" > "$work/$1_hand.c"
      chart=Branches ;;
  esac
}

# machine NAME FORM DIR [GFEC OPTION...]: puts case NAME's machine in FORM into DIR (after
# chart_source NAME): the hand-written NAME_hand.c, or the engine gfec writes (engine.c and
# engine.h); sets `source` to its C file.
machine() {
  local name=$1 form=$2 dir=$3
  shift 3
  mkdir -p "$dir"
  if [[ $form == hand ]]; then
    source=${name}_hand.c
    cp "$work/$source" "$dir/"
  else
    source=engine.c
    local opt=("${engine_opt[@]}")
    [[ $form == readable ]] || opt=(--engine="$form")
    (cd "$work" && "$gfec" "$name.sfc" "${opt[@]}" "$@" -o "$dir/engine.c")
  fi
}
