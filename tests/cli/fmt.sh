#!/usr/bin/env bash
# gfec fmt as an editor and CI use it (docs/formatting.md): in place, only when something
# changes; '-' as a filter; --check lists and fails; broken text, a symlink and a missing file
# are errors that leave everything as it was. Then `gfec fmt --check` over samples/ and the
# golden 'after' files: what the project ships is canonical.
# Usage: fmt.sh GFEC SOURCE_DIR
set -euo pipefail
gfec=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

printf 'interface I { void Go(); }\nsfc S{\ninitial place A{Go();}   // go\n}\n' > "$work/ugly.sfc"
printf 'interface I { void Go(); }\nsfc S {\n  initial place A { Go(); }  // go\n}\n' > "$work/want.sfc"
cp "$work/want.sfc" "$work/canonical.sfc"
touch -d '2000-01-01' "$work/canonical.sfc"

# --check: lists what would change, exit 1, writes nothing.
set +e
listed=$("$gfec" fmt --check "$work/ugly.sfc" "$work/canonical.sfc" 2>&1)
rc=$?
set -e
[[ $rc -eq 1 ]] || fail "--check with a file to change exited $rc"
[[ $listed == "$work/ugly.sfc" ]] || fail "--check listed: $listed"
cmp -s "$work/ugly.sfc" "$work/want.sfc" && fail "--check rewrote the file"
"$gfec" fmt --check "$work/canonical.sfc" || fail "--check on a canonical file failed"

# --diff: what would change as a unified diff, exit 1, nothing written.
set +e
shown=$("$gfec" fmt --diff "$work/ugly.sfc" "$work/canonical.sfc")
rc=$?
set -e
[[ $rc -eq 1 ]] || fail "--diff with a file to change exited $rc"
grep -qx -- "--- $work/ugly.sfc" <<<"$shown" || fail "--diff printed no header: $shown"
grep -qx -- "-initial place A{Go();}   // go" <<<"$shown" || fail "--diff lacks the old line: $shown"
grep -qx -- "+  initial place A { Go(); }  // go" <<<"$shown" || fail "--diff lacks the new line: $shown"
grep -q canonical <<<"$shown" && fail "--diff showed a canonical file"
cmp -s "$work/ugly.sfc" "$work/want.sfc" && fail "--diff rewrote the file"

# '-': stdin to stdout.
"$gfec" fmt - < "$work/ugly.sfc" > "$work/out.sfc"
cmp "$work/out.sfc" "$work/want.sfc" || fail "gfec fmt - printed other text"

# In place: the ugly file rewritten (its mode kept), the canonical one not touched (its time stays).
chmod 640 "$work/ugly.sfc"
"$gfec" fmt "$work/ugly.sfc" "$work/canonical.sfc"
cmp "$work/ugly.sfc" "$work/want.sfc" || fail "gfec fmt FILE did not rewrite it"
[[ $(stat -c %a "$work/ugly.sfc") == 640 ]] || fail "the file's mode became $(stat -c %a "$work/ugly.sfc")"
[[ $(stat -c %Y "$work/canonical.sfc") == $(date -d '2000-01-01' +%s) ]] || fail "an unchanged file was rewritten"

# Broken text: a located error, exit 1, the file as it was, the other files still formatted.
printf 'sfc S { place A { Go( } }\n' > "$work/broken.sfc"
cp "$work/broken.sfc" "$work/broken.orig"
printf 'sfc T{initial place B;}\n' > "$work/later.sfc"
set +e
msg=$("$gfec" fmt "$work/broken.sfc" "$work/later.sfc" 2>&1)
rc=$?
set -e
[[ $rc -eq 1 ]] || fail "broken input exited $rc"
grep -q "broken.sfc:1:[0-9]*: error:" <<<"$msg" || fail "no located error: $msg"
cmp -s "$work/broken.sfc" "$work/broken.orig" || fail "a broken file was rewritten"
[[ $(cat "$work/later.sfc") == $'sfc T { initial place B; }' ]] || fail "the file after a broken one was not formatted"

# A symlink is not replaced, and a missing file is an I/O error (exit 2).
printf 'sfc U{initial place C;}\n' > "$work/target.sfc"
ln -s target.sfc "$work/link.sfc"
set +e
"$gfec" fmt "$work/link.sfc" 2> "$work/err"
rc=$?
set -e
[[ $rc -eq 2 ]] || fail "a symlink exited $rc"
[[ -L $work/link.sfc ]] || fail "the symlink was replaced"
grep -q "symbolic link" "$work/err" || fail "no word of the symlink: $(cat "$work/err")"
set +e
"$gfec" fmt "$work/missing.sfc" 2> "$work/err"
rc=$?
set -e
[[ $rc -eq 2 ]] || fail "a missing file exited $rc"

# A folder: the chart text below it, nothing else.
mkdir -p "$work/tree/sub"
printf 'sfc V{initial place D;}\n' > "$work/tree/sub/deep.sfc"
printf 'not chart text{\n' > "$work/tree/notes.txt"
"$gfec" fmt "$work/tree"
[[ $(cat "$work/tree/sub/deep.sfc") == 'sfc V { initial place D; }' ]] || fail "a file below a folder was not formatted"
[[ $(cat "$work/tree/notes.txt") == 'not chart text{' ]] || fail "a file of another kind was touched"

# What the project ships is canonical.
"$gfec" fmt --check "$src/samples" "$src"/tests/golden/fmt/*.after.* ||
  fail "not canonical (run gfec fmt on the files listed)"
echo "fmt: ok"
