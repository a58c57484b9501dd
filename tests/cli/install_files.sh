#!/usr/bin/env bash
# `cmake --install` into a DESTDIR puts the manual page, the guides and the bash completion where
# man and bash-completion look; the page renders without a warning and names what --help names;
# --help has one usage block and cites a guide that is installed; the completion offers gfec's
# commands, options, warning names (read from gfec --help), back ends and chart and test files.
# Usage: install_files.sh BUILD_DIR
set -euo pipefail
build_dir=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
# The man page checks need man (man-db); CI installs it (scripts/install-deps.sh).
if ! command -v man >/dev/null; then
  [ "${CI:-}" = true ] && fail "man is not installed (Debian package man-db)"
  echo "note: no man (man-db): the man page is not rendered"
fi

DESTDIR="$work/dest" cmake --install "$build_dir" --prefix /usr/local >/dev/null || fail "cmake --install"
root="$work/dest/usr/local"
[ -x "$root/bin/gfec" ] || fail "no bin/gfec"
[ -f "$root/share/man/man1/gfec.1" ] || fail "no share/man/man1/gfec.1"
[ -f "$root/share/bash-completion/completions/gfec" ] || fail "no bash completion for gfec"
# A page or a completion only for a command that is installed.
for page in "$root"/share/man/man1/*.1; do
  name=$(basename "$page" .1)
  [ -x "$root/bin/$name" ] || fail "share/man/man1/$name.1 installed without bin/$name"
done
for file in "$root"/share/bash-completion/completions/*; do
  [ -x "$root/bin/$(basename "$file")" ] || fail "a completion for $(basename "$file"), not installed"
done
[ -f "$root/share/doc/gfec/cli.md" ] || fail "no share/doc/gfec/cli.md"
[ -f "$root/share/doc/gfec/tutorial.md" ] || fail "no share/doc/gfec/tutorial.md"

# --help: one usage block, and every guide a help cites is installed (found beside bin/).
help=$("$root/bin/gfec" --help)
[ "$(grep -c 'Usage:' <<<"$help")" = 1 ] || fail "gfec --help has $(grep -c 'Usage:' <<<"$help") usage blocks"
for words in "gfec test FILE" "-x LANG" "chart text"; do
  grep -qF -- "$words" <<<"$help" || fail "gfec --help does not mention '$words'"
done
for command in "" run test lsp monitor; do
  cited=$("$root/bin/gfec" $command --help | sed -n 's/^Documentation: man gfec; \([^ ]*\)$/\1/p')
  [ -n "$cited" ] || fail "gfec $command --help cites no installed guide: $("$root/bin/gfec" $command --help | tail -1)"
  [ -f "$cited" ] || fail "gfec $command --help cites $cited, not installed"
done

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
    grep -q -- "$opt" <<<"$man_text" || fail "gfec.1 does not mention $opt"
  done
  for words in "gfec test" "GFEC TEST" "-x alica|gfec" "toolbox-skeleton or chart" \
               'fix-it:"FILE":{L:C-L:C}:"TEXT"' /usr/share/bash-completion/completions/gfec /usr/share/doc/gfec/; do
    grep -qF -- "$words" <<<"$man_text" || fail "gfec.1 does not say '$words'"
  done
  # Every page SEE ALSO names is installed (or a well-known system one).
  for ref in $(echo "$man_text" | sed -n '/^SEE ALSO/,$p' | grep -o '[a-z][a-z-]*([0-9])' | sed 's/(.*//'); do
    case $ref in gcc|make|cmake) ;; *) [ -x "$root/bin/$ref" ] || fail "gfec.1 refers to $ref(1), not installed" ;; esac
  done
fi

# bash-completion itself loads the file from the prefix once the prefix's share/ is on
# XDG_DATA_DIRS (the way docs/build-integration.md gives for a prefix it does not search).
loader=/usr/share/bash-completion/bash_completion
if [ -f "$loader" ]; then
  loaded=$(XDG_DATA_DIRS="$root/share:/usr/share" BASH_COMPLETION_USER_DIR="$work/none" bash -c \
    'source "$1"; __load_completion gfec && complete -p gfec' _ "$loader" 2>&1) ||
    fail "bash-completion did not load gfec's completion from $root/share: $loaded"
  [ "$loaded" = "complete -F _gfec gfec" ] || fail "bash-completion loaded: $loaded"
else
  [ "${CI:-}" = true ] && fail "bash-completion is not installed (Debian package bash-completion)"
  echo "note: no bash-completion: its loading of the file is not checked"
fi

# The completion, driven as bash does: COMP_WORDS/COMP_CWORD in, COMPREPLY out.
mkdir "$work/charts" && cd "$work/charts"
touch blink.sfc mixer.st cleanup.fsm board.iface notes.txt blink.test plan.pml report.xml
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
expect --trace --trace= --trace-full-every -- gfec --tra
expect --trace=calls -- gfec --trace=c
expect --log --serial --tcp --silence -- gfec monitor blink.sfc --
expect 115200 -- gfec monitor blink.sfc --baud 11
expect --emit=c --emit=cpp --emit=svg --emit=chart -- gfec --emit=
expect -Wunreachable-actor -Wunreachable-place -- gfec -Wunre
expect -Werror=dead-transition -- gfec -Werror=dead
expect -fdiagnostics-color=always -fdiagnostics-color=auto -- gfec -fdiagnostics-color=a
expect blink.sfc cleanup.fsm board.iface plan.pml run test monitor -- gfec ""
[[ " $(offers gfec "") " == *" notes.txt "* ]] && fail "gfec <Tab> offers a text file"
expect -x -- gfec -
expect alica gfec plcopen -- gfec -x ""
expect blink.sfc -- gfec run b
expect plan.pml -- gfec run p
expect --inputs -- gfec run blink.sfc --in
expect --html -- gfec run blink.sfc --ht
expect --agents -- gfec run blink.sfc --ag
expect alica -- gfec run -x a
expect --period -- gfec run mixer.st --per
expect T#10ms -- gfec --period T
expect mixer.st -- gfec run m
expect -Wall -- gfec run blink.sfc -Wal
expect blink.test -- gfec test ""
expect blink.sfc blink.test board.iface -- gfec fmt ""
[[ " $(offers gfec fmt "") " == *" plan.pml "* ]] && fail "gfec fmt <Tab> offers an ALICA plan, which it does not format"
expect --check -- gfec fmt --ch
expect fmt -- gfec f
[[ " $(offers gfec test "") " == *" blink.sfc "* ]] && fail "gfec test <Tab> offers a chart, not a test file"
expect --reference-only --junit -x -- gfec test -
expect report.xml -- gfec test --junit r
expect -Wconflict -- gfec test blink.test -Wconf
echo "installed manual pages and completion: all checks passed"
