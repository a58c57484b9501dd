#!/usr/bin/env bash
# What gfec reads and what it prints, against hostile files and names (docs/security.md,
# "Special files and sizes", "Messages"): a file of /proc (as the main input, an import, a
# symlinked import, an --inputs trace, a gfec test file, an ALICA behaviour), a FIFO with no
# writer, a file past the size limit, and a newline in an import path or a test name.
# /proc/self/pagemap and /proc/self/status stand in for /proc/kmsg, which a regression would
# block on and drain as root: every gfec runs under `timeout` and a memory limit, so a regression
# fails here instead of taking the machine down.
# Usage: special_files.sh GFEC SOURCE_DIR
set -euo pipefail
# The memory bound on every run; none under AddressSanitizer (tests/sanitize.sh), which reserves
# terabytes of address space for its shadow memory and aborts under any such limit.
vmem=2000000
[ -z "${ASAN_OPTIONS:-}" ] || vmem=unlimited
gfec=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
cd "$work"
cp "$src/samples/line_follower.sfc" "$src/samples/linebot.iface" .

# gfec ARGS... with at most 20 s and 2 GB of address space; stdout in out, stderr in err.
code=0
run() {
  set +e
  (ulimit -v "$vmem" && exec timeout 20 "$gfec" "$@") >out 2>err
  code=$?
  set -e
  [ $code -ne 124 ] || fail "gfec $* did not end within 20 s"
  [ $code -lt 128 ] || fail "gfec $* died of a signal (exit $code): $(head -c 2000 err)"
}
expect_error() {  # EXIT-CODE PATTERN: what the last run must have done
  [ $code -eq "$1" ] || fail "expected exit $1, got $code: $(head -c 2000 err)"
  grep -q -- "$2" err || fail "no '$2' in: $(head -c 2000 err)"
}
kernel="a file of /proc, /sys or another of the kernel's pseudo file systems; gfec reads none"
not_regular="not a regular file (a FIFO); gfec reads no devices, pipes or sockets"

# Imports: the file /proc/self/pagemap (gigabytes that say 0 bytes), a symlink to a /proc file,
# a FIFO no one writes. Each is a located error, exit 1, and nothing is read.
mkfifo pipe.iface
ln -s /proc/self/status status.iface
for import in /proc/self/pagemap status.iface pipe.iface; do
  printf 'import "%s";\nsfc A { initial place P; }\n' "$import" >imports.sfc
  run --check imports.sfc
  reason=$kernel
  [ "$import" != pipe.iface ] || reason=$not_regular
  expect_error 1 "^imports.sfc:1:8: error: cannot read imported file '$import': $reason \[import\]"
done

# The main input, of each command.
run --check /proc/self/pagemap
expect_error 2 "^gfec: error: cannot read '/proc/self/pagemap': $kernel"
run --check pipe.iface
expect_error 2 "^gfec: error: cannot read 'pipe.iface': $not_regular"
run run /proc/self/status
expect_error 2 "cannot read '/proc/self/status': $kernel"
run test /proc/self/status
expect_error 2 "cannot read '/proc/self/status': $kernel"
run test pipe.iface
expect_error 2 "cannot read 'pipe.iface': $not_regular"
# An --inputs trace.
run run line_follower.sfc --inputs /proc/self/pagemap
expect_error 2 "cannot read '/proc/self/pagemap': $kernel"
run run line_follower.sfc --inputs pipe.iface
expect_error 2 "cannot read 'pipe.iface': $not_regular"

# A file past the limit of one file (128 MiB) is refused by its size, before a byte is read: a
# sparse file costs no disk.
truncate -s 200M huge.iface
printf 'import "huge.iface";\nsfc A { initial place P; }\n' >imports.sfc
run --check imports.sfc
expect_error 1 "^imports.sfc:1:8: error: cannot read imported file 'huge.iface': larger than 128 MiB, the most gfec reads of one file"

# An ALICA behaviour that is a symlink into /proc: the reader says so, located, and reads nothing.
cp -r "$src/tests/alica/plans" alica
ln -sf /proc/self/pagemap alica/Behaviours/Park.beh
run --check alica/Master.pml
expect_error 1 "^alica/Master.pml:[0-9]*:[0-9]*: error: cannot read 'alica/Behaviours/Park.beh': $kernel, referenced here"

# A newline in an import path or a test name is printed escaped, never as a line of its own: a
# chart must not write '::error file=...::' workflow commands (or a forged diagnostic) into a
# CI log.
injected='::error file=x.sfc,line=1::forged'
no_forged_lines() {
  if grep -q '^[[:space:]]*::' out err; then fail "a line of its own: $(grep -h '^[[:space:]]*::' out err)"; fi
}
printf 'import "a\\n%s";\nsfc A { initial place P; }\n' "$injected" >newline.sfc
run --check newline.sfc
expect_error 1 "^newline.sfc:1:8: error: cannot find imported file 'a<U+000A>$injected' \[import\]"
no_forged_lines
cat >newline.test <<TEST
import "line_follower.sfc";
test "fails\\n$injected" of LineFollower { tick; expect active(LeftStop); }
test "passes\\n$injected" of LineFollower { tick; expect active(LeftFw); }
TEST
run test -v --reference-only newline.test
expect_error 1 "newline.test:2:.*error: "
grep -q "^PASS newline.test: passes<U+000A>$injected$" out || fail "the PASS line: $(cat out)"
no_forged_lines
# The JSON and SARIF forms stay one valid document each, the newline escaped by JSON.
for format in json sarif-stderr; do
  run --check -fdiagnostics-format=$format newline.sfc
  [ $code -eq 1 ] || fail "$format: exit $code"
  no_forged_lines
  run test --reference-only -fdiagnostics-format=$format newline.test
  [ $code -eq 1 ] || fail "$format: exit $code"
  no_forged_lines
done
if command -v node >/dev/null 2>&1; then
  run --check -fdiagnostics-format=json newline.sfc
  node -e 'const d = JSON.parse(require("fs").readFileSync("err", "utf8"));
    if (!JSON.stringify(d).includes("a\\n::error")) process.exit(1);' || fail "json: $(cat err)"
  run --check -fdiagnostics-format=sarif-stderr newline.sfc
  node -e 'const d = JSON.parse(require("fs").readFileSync("err", "utf8"));
    if (!JSON.stringify(d).includes("a\\n::error")) process.exit(1);' || fail "sarif: $(cat err)"
elif [ "${CI:-}" = true ]; then
  fail "node is needed to parse the JSON and SARIF outputs (scripts/install-deps.sh installs it)"
else
  echo "skipping the JSON parse: node is not installed"
fi
# Output names. The engine includes its header by name, and #include "..." takes no escapes: a
# name it cannot hold is refused (exit 2, nothing written), never an engine that cannot find
# its header. A valid name of 240 to 255 bytes is written (its temporary's name is cut to fit).
for name in 'q"x.c' 'a\b.c' 'tri??-.c' "$(printf 'n\nl.c')"; do
  run line_follower.sfc -o "$name"
  expect_error 2 "cannot name the header '.*' in the engine's #include"
  no_forged_lines
done
[ -z "$(find . -name '*.h' ! -name '*.iface' -newer line_follower.sfc)" ] || fail "a refused name wrote a header"
for length in 240 253; do
  name=$(printf "%${length}s" "" | tr ' ' e)  # NAME.c: 242 and 255 bytes, NAME.h beside it
  run line_follower.sfc -o "$name.c"
  [ $code -eq 0 ] || fail "a $((length + 2))-byte output name: exit $code: $(cat err)"
  [ -f "$name.c" ] && [ -f "$name.h" ] || fail "a $((length + 2))-byte output name was not written"
  if command -v cc >/dev/null 2>&1; then
    cc -std=c99 -Wall -Wextra -Wpedantic -Werror -c "$name.c" -o long.o || fail "the engine of a long name does not compile"
  fi
  if ls | grep -q gfec-tmp; then fail "a temporary was left: $(ls | grep gfec-tmp)"; fi
done

echo "special files and names: ok"
