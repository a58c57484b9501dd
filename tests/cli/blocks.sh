#!/usr/bin/env bash
# Blocks in chart text (docs/language.md §15, docs/iec.md "The standard blocks"): for each chart
# of tests/blocks, `gfec run --observable` on its trace prints NAME.expected (checked by hand);
# the C engine in both forms, built by gcc and clang with -Werror and driven by a caller that
# feeds the same trace, prints the same lines; --emit=chart writes chart text that compiles to the
# same engine; --emit=json lists the instances. Usage: blocks.sh GFEC SOURCE_DIR
set -euo pipefail
gfec=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
caller=$(cd "$(dirname "$0")" && pwd)/engine_caller.py
dir=$(cd "$2" && pwd)/tests/blocks
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
command -v python3 > /dev/null || fail "python3 is needed (scripts/install-deps.sh installs it)"
compilers=()
for cc in gcc clang; do
  if command -v "$cc" > /dev/null; then compilers+=("$cc")
  elif [ "${CI:-}" = true ]; then fail "$cc is needed (scripts/install-deps.sh installs it)"
  else echo "blocks: $cc not found, skipped"; fi
done

cd "$work"
for sfc in "$dir"/*.sfc; do
  name=$(basename "$sfc" .sfc)
  chart=$(grep -m1 -o '^sfc  *[A-Za-z_0-9]*' "$sfc" | awk '{print $2}')
  "$gfec" run "$sfc" --inputs "$dir/$name.csv" --observable > run.txt
  diff -u "$dir/$name.expected" run.txt || fail "$name: gfec run differs from $name.expected"
  "$gfec" --emit=json "$sfc" -o model.json
  grep -q '"instances"' model.json || fail "$name: --emit=json lists no instances"
  rm -rf direct back && mkdir direct back
  cp "$sfc" direct/prog.sfc
  "$gfec" --emit=chart direct/prog.sfc -o back/prog.sfc
  for form in readable scalable; do
    "$gfec" "$sfc" --engine=$form -o engine.c
    python3 "$caller" engine.h "$dir/$name.csv" "$chart" > main.c
    for cc in "${compilers[@]}"; do
      "$cc" -std=c99 -Wall -Wextra -Wpedantic -Werror main.c engine.c -o run || fail "$name: $cc cannot build the $form engine"
      ./run > engine.txt
      diff -u "$dir/$name.expected" engine.txt || fail "$name: the $form engine ($cc) differs from gfec run"
    done
    (cd direct && "$gfec" prog.sfc --engine=$form --no-line-directives -o engine.c)
    (cd back && "$gfec" prog.sfc --engine=$form --no-line-directives -o engine.c)
    cmp <(tail -n +2 direct/engine.c) <(tail -n +2 back/engine.c) || fail "$name: the converted chart compiles to another $form engine"
  done
done
echo "blocks: ok"
