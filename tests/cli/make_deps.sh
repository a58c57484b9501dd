#!/usr/bin/env bash
# gfec -MD -MP driven by a real make: samples/Makefile builds the sample engines; touching an
# imported interface rebuilds exactly the engines made from it, touching nothing rebuilds
# nothing, imports of imports count, and a deleted import does not break the build.
# Usage: make_deps.sh GFEC SOURCE_DIR
set -euo pipefail
gfec=$1 source_dir=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

# A copy of the samples, so the test can touch and edit them.
mkdir -p "$work/src" "$work/out"
cp "$source_dir"/samples/{Makefile,line_follower.sfc,linebot.iface,cleanup.fsm,cleanbot.iface} "$work/src/"
build() { make -C "$work/out" -f "$work/src/Makefile" GFEC="$gfec" "$@" 2>&1; }
stamp() { stat -c %Y.%y "$work/out/$1"; }
# Timestamps must differ for make to see a change; file systems here have fine-grained ones,
# but a second also covers those that do not.
tick() { sleep 1; }

build >/dev/null || fail "first build"
for f in line_follower.c line_follower.h line_follower.d cleanup.c cleanup.h cleanup.d libcharts.a; do
  [ -f "$work/out/$f" ] || fail "first build did not make $f"
done
grep -q 'line_follower.c line_follower.h:' "$work/out/line_follower.d" || fail "targets: $(cat "$work/out/line_follower.d")"
grep -q 'linebot.iface' "$work/out/line_follower.d" || fail "the import is not listed"
grep -q '^[^ ]*linebot.iface:$' "$work/out/line_follower.d" || fail "-MP: no empty rule for the import"
if grep -q cleanbot "$work/out/line_follower.d"; then fail "line_follower.d lists an unrelated file"; fi

# Touching nothing rebuilds nothing.
before_lf=$(stamp line_follower.c) before_cu=$(stamp cleanup.c)
out=$(build)
echo "$out" | grep -q "Nothing to be done" || fail "a second build did work: $out"
[ "$(stamp line_follower.c)" = "$before_lf" ] || fail "line_follower.c rewritten by a no-op build"

# Touching linebot.iface rebuilds line_follower only.
tick
touch "$work/src/linebot.iface"
out=$(build)
echo "$out" | grep -q "line_follower.sfc" || fail "touching linebot.iface did not recompile line_follower: $out"
if echo "$out" | grep -q "cleanup.fsm"; then fail "touching linebot.iface recompiled cleanup: $out"; fi
[ "$(stamp line_follower.c)" != "$before_lf" ] || fail "line_follower.c not rewritten"
[ "$(stamp cleanup.c)" = "$before_cu" ] || fail "cleanup.c rewritten"
echo "$out" | grep -q "libcharts.a" || fail "the library was not relinked: $out"

# Touching cleanbot.iface rebuilds cleanup only.
tick
touch "$work/src/cleanbot.iface"
out=$(build)
echo "$out" | grep -q "cleanup.fsm" || fail "touching cleanbot.iface did not recompile cleanup: $out"
if echo "$out" | grep -q "line_follower.sfc"; then fail "touching cleanbot.iface recompiled line_follower: $out"; fi

# Imports of imports: line_follower.sfc -> linebot.iface -> extra.iface.
tick
printf 'const int SPEED = 3;\n' > "$work/src/extra.iface"
printf 'import "extra.iface";\n' | cat - "$work/src/linebot.iface" > "$work/src/linebot.new"
mv "$work/src/linebot.new" "$work/src/linebot.iface"
build >/dev/null || fail "build with a nested import"
grep -q 'extra.iface' "$work/out/line_follower.d" || fail "the nested import is not listed: $(cat "$work/out/line_follower.d")"
tick
before_lf=$(stamp line_follower.c)
touch "$work/src/extra.iface"
out=$(build)
echo "$out" | grep -q "line_follower.sfc" || fail "touching a nested import did not recompile: $out"
[ "$(stamp line_follower.c)" != "$before_lf" ] || fail "line_follower.c not rewritten after a nested import changed"

# A deleted generated header (or engine) is regenerated, and only its chart is recompiled.
tick
before_cu=$(stamp cleanup.c)
rm "$work/out/line_follower.h"
out=$(build)
[ -f "$work/out/line_follower.h" ] || fail "rm line_follower.h; make did not regenerate it: $out"
echo "$out" | grep -q "line_follower.sfc" || fail "the header came back without gfec: $out"
if echo "$out" | grep -q "cleanup.fsm"; then fail "deleting line_follower.h recompiled cleanup: $out"; fi
[ "$(echo "$out" | grep -c 'line_follower.sfc')" -eq 1 ] || fail "gfec ran more than once for one chart: $out"
rm "$work/out/cleanup.c"
out=$(build)
[ -f "$work/out/cleanup.c" ] || fail "rm cleanup.c; make did not regenerate it: $out"
out=$(build)
echo "$out" | grep -q "Nothing to be done" || fail "after regenerating, a second build did work: $out"

# -MP: deleting an import (and the line importing it) must not stop make.
tick
tail -n +2 "$work/src/linebot.iface" > "$work/src/linebot.new"
mv "$work/src/linebot.new" "$work/src/linebot.iface"
rm "$work/src/extra.iface"
build >/dev/null || fail "the build failed after an import was deleted"
if grep -q 'extra.iface' "$work/out/line_follower.d"; then fail "the deleted import is still listed"; fi

# An input error leaves the engine and the dependency file as they were.
tick
before_d=$(cat "$work/out/line_follower.d")
before_lf=$(stamp line_follower.c)
printf 'sfc Broken {\n' >> "$work/src/line_follower.sfc"
if build >/dev/null; then fail "a broken chart built"; fi
[ "$(stamp line_follower.c)" = "$before_lf" ] || fail "a failed compile touched line_follower.c"
[ "$(cat "$work/out/line_follower.d")" = "$before_d" ] || fail "a failed compile changed line_follower.d"

# make injection: an import whose name holds a newline, ';' or '=' must not become a rule, a
# recipe or a variable of the next make. gfec refuses to write such a dependency file (exit 2).
for evil in $'e=1\nall:;touch${IFS}PWNED' 'x;touch PWNED' 'GFEC=touch PWNED'; do
  cp "$source_dir/samples/line_follower.sfc" "$work/src/line_follower.sfc"
  cp "$work/src/linebot.iface" "$work/src/$evil"
  printf 'import "%s";\n' "$(printf '%s' "$evil" | sed 's/\\/\\\\/g' | sed ':a;N;$!ba;s/\n/\\n/g')" \
    | cat - "$work/src/line_follower.sfc" | sed 's/^import "linebot.iface";$//' > "$work/src/lf.new"
  mv "$work/src/lf.new" "$work/src/line_follower.sfc"
  tick
  out=$(build) && fail "a dependency file naming '$evil' was written: $out"
  echo "$out" | grep -q "cannot write the dependency file" || fail "no message for '$evil': $out"
  build >/dev/null || true
  [ ! -e "$work/out/PWNED" ] && [ ! -e "$work/src/PWNED" ] || fail "make ran a command injected by '$evil'"
  grep -q "touch" "$work/out/line_follower.d" && fail "line_follower.d names '$evil': $(cat "$work/out/line_follower.d")"
  rm "$work/src/$evil"
done
# A ':' in a name is escaped and the rule still works.
cp "$source_dir/samples/line_follower.sfc" "$work/src/line_follower.sfc"
cp "$work/src/linebot.iface" "$work/src/a:b.iface"
sed -i 's/^import "linebot.iface";$/import "a:b.iface";/' "$work/src/line_follower.sfc"
tick
build >/dev/null || fail "a build importing a:b.iface"
grep -q 'a\\:b.iface' "$work/out/line_follower.d" || fail "':' not escaped: $(cat "$work/out/line_follower.d")"
tick
touch "$work/src/a:b.iface"
out=$(build)
echo "$out" | grep -q "line_follower.sfc" || fail "touching a:b.iface did not recompile: $out"

echo "make dependency files: all checks passed"
