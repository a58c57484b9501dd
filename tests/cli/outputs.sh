#!/usr/bin/env bash
# gfec's outputs as a careless CI script or a hostile pull request would aim them
# (docs/security.md): never over an input or an import, never over a special file, never one
# file twice, nothing written when refused (exit 2), no temporary left behind.
# Special files are a FIFO and a symlink to it in a scratch folder, never the real /dev/null:
# CI runs as root, and a regression must not damage the machine.
# Usage: outputs.sh GFEC SOURCE_DIR
set -euo pipefail
gfec=$1 source_dir=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
mkdir "$work/c"
cd "$work/c"
err="$work/err"
cp "$source_dir"/samples/{line_follower.sfc,linebot.iface,square.plan,square_side.plan,carbot.toolbox} .
cp line_follower.sfc lf.sfc
sum() { sha256sum "$@" | cut -c1-64; }
before_inputs=$(sum line_follower.sfc linebot.iface lf.sfc)

# expect_refused "what" ARGS...: exit 2, a "refusing" message, no file changed or added.
expect_refused() {
  local what=$1; shift
  local listing_before; listing_before=$(ls -lA --time-style=full-iso)
  set +e
  "$gfec" "$@" 2>"$err" >/dev/null; local code=$?
  set -e
  [ $code -eq 2 ] || fail "$what: exit $code, not 2 ($(cat "$err"))"
  grep -q "refusing to write" "$err" || fail "$what: message: $(cat "$err")"
  [ "$(ls -lA --time-style=full-iso)" = "$listing_before" ] || fail "$what: the folder changed: $(ls -lA)"
  [ "$(sum line_follower.sfc linebot.iface lf.sfc)" = "$before_inputs" ] || fail "$what: an input changed"
}

# 5. The source, an import, the -MF file, an input named like the default output.
expect_refused "-o the input" lf.sfc -o lf.sfc
expect_refused "-o an import" lf.sfc -o linebot.iface
expect_refused "-MF the input" lf.sfc -o x.c -MD -MF lf.sfc
expect_refused "-MF an import" lf.sfc -o x.c -MD -MF linebot.iface
cp lf.sfc x.c
cp lf.sfc x.sfc
expect_refused "an input named like its default output" x.c
rm x.c x.sfc
# The same through a symlink, a hard link and another spelling of the path.
ln -s lf.sfc link.c
ln lf.sfc hard.c
mkdir sub
expect_refused "-o a symlink to the input" lf.sfc -o link.c
expect_refused "-o a hard link to the input" lf.sfc -o hard.c
expect_refused "-o the input by another path" lf.sfc -o sub/../lf.sfc
expect_refused "-o the input by its absolute path" lf.sfc -o "$work/c/lf.sfc"
# The header is an output too: -MF may not name it.
expect_refused "-MF named like the header" lf.sfc -o lf.c -MD -MF lf.h
rm link.c hard.c
# sarif-file writes INPUT.sarif beside the input: never over a file the input imports.
sed 's/linebot.iface/k.sfc.sarif/' lf.sfc > k.sfc
cp linebot.iface k.sfc.sarif
before_sarif=$(sum k.sfc.sarif)
expect_refused "a SARIF log over an import" --check -fdiagnostics-format=sarif-file k.sfc
[ "$(sum k.sfc.sarif)" = "$before_sarif" ] || fail "the SARIF log replaced an import"
rm k.sfc k.sfc.sarif

# 1. Special files: a FIFO, a symlink to it (what /dev/null is to a symlinked /dev), a folder.
mkfifo fifo
ln -s fifo null
expect_refused "-o a FIFO" lf.sfc -o fifo
expect_refused "-o a symlink to a FIFO" lf.sfc -o null
expect_refused "-MF a FIFO" lf.sfc -o y.c -MD -MF fifo
expect_refused "-o a folder" lf.sfc -o sub
[ -p fifo ] || fail "the FIFO was replaced"
[ -L null ] && [ -p null ] || fail "the symlink to the FIFO was replaced"
[ ! -e fifo.h ] && [ ! -e null.h ] || fail "a header was written beside the FIFO"

# 6. Two outputs to one path: nothing is written, not even the first.
printf 'old\n' > e.c
expect_refused "-o and -MF the same file" lf.sfc -o e.c -MD -MF e.c
[ "$(cat e.c)" = old ] || fail "e.c was replaced"
expect_refused "-o and -MF the same file by two spellings" lf.sfc -o e.c -MD -MF ./sub/../e.c
rm e.c
expect_refused "gfec run --html over an import" run lf.sfc --html linebot.iface
expect_refused "gfec run --html over the chart" run lf.sfc --html lf.sfc
expect_refused "a plan's header named as its -o" square.plan -o X.hpp
[ ! -e X.hpp ] || fail "X.hpp written"

# 4. A symlink or a file planted under a temporary's old, predictable name is never used.
# The old name was OUT.gfec-tmp-PID: plant it for gfec's own PID (exec keeps the shell's).
printf 'victim\n' > victim
bash -c 'ln -s victim "good.c.gfec-tmp-$$" && exec "$0" lf.sfc -o good.c' "$gfec" || fail "a normal compile failed"
[ "$(cat victim)" = victim ] || fail "a planted symlink was followed"
[ -f good.c ] && [ -f good.h ] || fail "outputs missing"
grep -q "LineFollower" good.c || fail "good.c is not the engine"
rm -f good.c.gfec-tmp-*

# Writing over an existing regular output is normal; no temporary is left behind.
"$gfec" lf.sfc -o good.c -MD
"$gfec" lf.sfc -o good.c -MD
ls -A | grep -q 'gfec-tmp' && fail "temporaries left: $(ls -A)"
# A symlinked output (not to an input) is replaced by the file, the target is untouched.
ln -s victim out.c
"$gfec" lf.sfc -o out.c
[ "$(cat victim)" = victim ] && [ -f out.c ] && [ ! -L out.c ] || fail "symlinked output"

# An output folder that does not exist: an I/O error, exit 2.
set +e
"$gfec" lf.sfc -o nowhere/x.c 2>"$err"; code=$?
set -e
[ $code -eq 2 ] && grep -q "cannot write 'nowhere/x.c'" "$err" || fail "missing folder: $code $(cat "$err")"

# 11. SIGTERM, SIGHUP or SIGINT while the outputs are being written: no temporary, no output.
# The chart is big enough that writing takes a while (larger on each attempt, for a fast
# machine); the signal is sent as soon as a temporary appears. A check that never ran would
# prove nothing: it fails.
big_chart() {  # big_chart N: a sequence of N places
  echo 'import "linebot.iface";'
  echo 'sfc Big {'
  echo '  initial place P0 { Left_FW(); }'
  for i in $(seq 1 "$1"); do echo "  place P$i { Left_FW(); Right_FW(); Left_Stop(); }"; done
  for i in $(seq 0 $(($1 - 1))); do echo "  P$i -> P$((i + 1)) when Left_IR_Black();"; done
  echo '}'
}
# A shell without job control starts background commands with SIGINT ignored, and gfec keeps
# an ignored signal ignored (docs/security.md): job control gives the compile SIGINT's default.
set -m
interrupted_while_writing() {  # SIGNAL EXIT-CODE
  local sig=$1 expected=$2 killed=0 places code
  rm -rf sig && mkdir sig
  for places in 4000 4000 20000 20000 60000; do
    big_chart $places > big.sfc
    "$gfec" big.sfc -o sig/big.c -MD &
    local pid=$!
    for _ in $(seq 1 200000); do
      if compgen -G 'sig/*gfec-tmp*' >/dev/null; then kill -"$sig" $pid 2>/dev/null || true; killed=1; break; fi
      kill -0 $pid 2>/dev/null || break
    done
    set +e; wait $pid; code=$?; set -e
    if [ $killed -eq 1 ] && [ $code -eq "$expected" ]; then break; fi
    killed=0
    rm -f sig/*
  done
  [ $killed -eq 1 ] || fail "the compile was never interrupted while writing: the SIG$sig check did not run"
  echo "SIG$sig sent while writing a chart of $places places"
  ls -A sig | grep -q 'gfec-tmp' && fail "SIG$sig left temporaries: $(ls -A sig)"
  # Either nothing (killed while writing) or the whole set (killed during the renames, which
  # hold the signal back until they are done): never a part.
  local n
  n=$(ls -A sig | wc -l)
  [ "$n" -eq 0 ] || [ "$n" -eq 3 ] || fail "SIG$sig left part of the set: $(ls -A sig)"
}
interrupted_while_writing TERM 143
interrupted_while_writing HUP 129
interrupted_while_writing INT 130
set +m
echo "gfec outputs: all checks passed"
