#!/usr/bin/env bash
# `cmake --install` into a DESTDIR puts the manual pages and the bash completion where man and
# bash-completion look; the pages render without a warning; the completion offers gfec's
# options, warning names (read from gfec --help), back ends and chart files.
# Usage: install_files.sh BUILD_DIR
set -euo pipefail
build_dir=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

DESTDIR="$work/dest" cmake --install "$build_dir" --prefix /usr/local >/dev/null || fail "cmake --install"
root="$work/dest/usr/local"
[ -x "$root/bin/gfec" ] || fail "no bin/gfec"
[ -f "$root/share/man/man1/gfec.1" ] || fail "no share/man/man1/gfec.1"
[ -f "$root/share/bash-completion/completions/gfec" ] || fail "no bash completion for gfec"
sim=$(grep -c '^GFEC_BUILD_SIM:BOOL=ON' "$build_dir/CMakeCache.txt" || true)
if [ "$sim" = 1 ]; then
  [ -f "$root/share/man/man1/carbot-sim.1" ] || fail "no share/man/man1/carbot-sim.1"
  [ -f "$root/share/bash-completion/completions/carbot-sim" ] || fail "no bash completion for carbot-sim"
fi

# The pages render, with every groff warning on and none given.
pages=("$root"/share/man/man1/*.1)
for page in "${pages[@]}"; do
  if command -v groff >/dev/null; then
    warnings=$(groff -man -Tutf8 -ww -z "$page" 2>&1)
    [ -z "$warnings" ] || fail "$(basename "$page"): $warnings"
  fi
  if command -v man >/dev/null; then
    text=$(MANWIDTH=80 man -l "$page" 2>"$work/man.err") || fail "man -l $(basename "$page")"
    [ ! -s "$work/man.err" ] || fail "man -l $(basename "$page"): $(cat "$work/man.err")"
    echo "$text" | grep -q "EXIT STATUS" || fail "$(basename "$page") has no EXIT STATUS"
  fi
done
man_text=$(MANWIDTH=200 man -l "$root/share/man/man1/gfec.1" 2>/dev/null || true)
if [ -n "$man_text" ]; then
  # Every option --help lists is in the page.
  for opt in --check --analyze --emit --chart --engine --no-line-directives -Werror= -Wno-error= \
             -fdiagnostics-color -fdiagnostics-parseable-fixits -fmax-errors -MD -MF -MP -MT; do
    echo "$man_text" | grep -q -- "$opt" || fail "gfec.1 does not mention $opt"
  done
fi

# The completion, driven as bash does: COMP_WORDS/COMP_CWORD in, COMPREPLY out.
mkdir "$work/charts" && cd "$work/charts"
touch blink.sfc cleanup.fsm board.iface notes.txt
complete_words() {
  PATH="$root/bin:$PATH" bash -c '
    shopt -s extglob
    source "$1"; shift
    COMP_WORDS=("$@"); COMP_CWORD=$(($# - 1))
    func=$(complete -p "$1" | sed "s/.*-F \([^ ]*\) .*/\1/")
    "$func"
    printf "%s\n" "${COMPREPLY[@]}" | sort' _ "$root/share/bash-completion/completions/gfec" "$@"
}
offers() { complete_words "$@" | tr '\n' ' '; }
# expect WORD... -- COMMAND-LINE...: completing the command line offers every WORD.
expect() {
  local words=()
  while [ "$1" != "--" ]; do words+=("$1"); shift; done
  shift
  local got=" $(offers "$@") "
  for w in "${words[@]}"; do [[ $got == *" $w "* ]] || fail "'$*' offers$got, not $w"; done
}
expect --check --chart -- gfec --ch
expect --context --context-type= -- gfec --cont
expect --names -- gfec --na
expect --emit=c --emit=cpp --emit=svg -- gfec --emit=
expect -Wunreachable-actor -Wunreachable-place -- gfec -Wunre
expect -Werror=dead-transition -- gfec -Werror=dead
expect -fdiagnostics-color=always -fdiagnostics-color=auto -- gfec -fdiagnostics-color=a
expect blink.sfc cleanup.fsm board.iface run -- gfec ""
[[ " $(offers gfec "") " == *" notes.txt "* ]] && fail "gfec <Tab> offers a text file"
expect blink.sfc -- gfec run b
expect --inputs -- gfec run blink.sfc --in
expect --world -- carbot-sim blink.sfc --wo
echo "installed manual pages and completion: all checks passed"
