# Checks of `gfec test` runs for the tests/cli scripts, sourced: they need $gfec and fail().
# Every test runs on the interpreter and on the C engine (docs/testing-charts.md).

# tests_pass FILE N: all N tests of FILE pass.
tests_pass() {
  local name
  name=$(basename "$1")
  "$gfec" test "$1" > test.txt 2> test.err || fail "$name: $(cat test.err)"
  grep -qx "$2 passed, 0 failed" test.txt || fail "$name: $(cat test.txt)"
}

# tests_fail_with FILE MESSAGE...: FILE exits 1 with exactly these errors (grep patterns, one
# error each), and none fails on one run only (a run that ignored what the other did).
tests_fail_with() {
  local file=$1 name status=0 message
  name=$(basename "$file")
  shift
  "$gfec" test "$file" > wrong.txt 2> wrong.err || status=$?
  [[ $status == 1 ]] || fail "$name: exit $status, not 1"
  for message in "$@"; do
    grep -q "$message" wrong.err || fail "$name: no '$message': $(cat wrong.err)"
  done
  [[ $(grep -c 'error:' wrong.err) == $# ]] || fail "$name: not just the $# wrong expectations: $(cat wrong.err)"
  if grep -q ' only; it holds on ' wrong.err; then fail "$name: one run ignored a step: $(cat wrong.err)"; fi
}
