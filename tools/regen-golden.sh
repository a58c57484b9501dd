#!/usr/bin/env bash
# Regenerates the expected outputs of the golden tests with the real gfec.
#
#   tools/regen-golden.sh [BACKEND...]      e.g. tools/regen-golden.sh c
#
# Each folder tests/golden/<backend>/ holds charts (*.sfc, *.fsm, *.plan) with the files they
# import. For every chart <case>.<ext> the script runs, inside that folder (so that paths in the
# output stay short and stable):
#
#   gfec <case>.<ext> --emit=<backend> -o <case>.<backend> $(cat <case>.flags)
#
# which writes <case>.<backend> and whatever the back end puts beside it (the C back end also
# writes <case>.h, the cpp back end <case>.hpp). In tests/golden/cpp every toolbox <case>.toolbox
# also gets its skeleton: gfec <case>.toolbox --emit=toolbox-skeleton -o <case>_toolbox.h (and
# <case>_toolbox.cpp beside it), which is the header the plans there include.
# <case>.flags, if present, holds extra gfec options for that case. Without
# arguments every folder under tests/golden is regenerated; folders whose name is not a back end
# are skipped. Then read the diff (git diff tests/golden) before committing: that review is
# the point of golden tests.
#
# GFEC (default: $GFEC_BUILD_DIR/gfec, else build/gfec) names the compiler to use.
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
gfec=${GFEC:-${GFEC_BUILD_DIR:-$root/build}/gfec}
if [[ ! -x $gfec ]]; then
  echo "regen-golden: no gfec at $gfec (build it, or set GFEC=path/to/gfec)" >&2
  exit 2
fi
gfec=$(cd "$(dirname "$gfec")" && pwd)/$(basename "$gfec")

if [[ $# -gt 0 ]]; then
  backends=("$@")
else
  backends=()
  for dir in "$root"/tests/golden/*/; do backends+=("$(basename "$dir")"); done
fi

status=0
for backend in "${backends[@]}"; do
  dir=$root/tests/golden/$backend
  if [[ ! -d $dir ]]; then
    echo "regen-golden: no folder tests/golden/$backend" >&2
    status=2
    continue
  fi
  shopt -s nullglob
  inputs=("$dir"/*.sfc "$dir"/*.fsm "$dir"/*.plan)
  if [[ $backend == cpp ]]; then inputs+=("$dir"/*.toolbox); fi
  shopt -u nullglob
  for input in "${inputs[@]}"; do
    name=$(basename "$input")
    case=${name%.*}
    emit=$backend
    output=$case.$backend
    if [[ $name == *.toolbox ]]; then
      emit=toolbox-skeleton
      output=${case}_toolbox.h
    fi
    flags=()
    if [[ -f $dir/$case.flags ]]; then read -r -a flags < "$dir/$case.flags"; fi
    set +e
    message=$(cd "$dir" && "$gfec" "$name" --emit="$emit" -o "$output" ${flags[@]+"${flags[@]}"} 2>&1)
    rc=$?
    set -e
    if [[ $rc -ne 0 ]] && grep -q "unknown back end" <<<"$message"; then
      echo "regen-golden: skipping tests/golden/$backend: not a back end gfec knows"
      break
    fi
    if [[ $rc -ne 0 ]]; then
      echo "regen-golden: tests/golden/$backend/$name failed:" >&2
      echo "$message" >&2
      status=1
      continue
    fi
    echo "regenerated tests/golden/$backend/$output"
  done
done
exit $status
