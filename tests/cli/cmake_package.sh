#!/usr/bin/env bash
# `cmake --install` of this build into a temporary prefix, then a throwaway project that uses
# find_package(gfec), gfec_add_chart() and gfec::runtime: it must configure, build and run,
# rebuild the engine when an import (even an import of an import) changes, and do nothing
# when nothing changed. Each CMake generator at hand is tried (Ninja, Unix Makefiles).
# Usage: cmake_package.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build_dir=$1 source_dir=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

prefix="$work/prefix"
cmake --install "$build_dir" --prefix "$prefix" >/dev/null || fail "cmake --install"
[ -x "$prefix/bin/gfec" ] || fail "no bin/gfec installed"
[ -f "$prefix/include/afp/afp.h" ] || fail "no runtime headers installed"
config=$(find "$prefix" -name gfecConfig.cmake)
[ -n "$config" ] || fail "no gfecConfig.cmake installed"
ls "$(dirname "$config")"/GfecChart.cmake "$(dirname "$config")"/gfecTargets.cmake >/dev/null || fail "package files"

generators=()
command -v ninja >/dev/null && generators+=("Ninja")
command -v make >/dev/null && generators+=("Unix Makefiles")
[ ${#generators[@]} -gt 0 ] || fail "neither ninja nor make"

for generator in "${generators[@]}"; do
  echo "== $generator"
  project="$work/project-${generator// /-}"
  out="$project-build"
  cp -r "$source_dir/tests/cli/package_project" "$project"
  # The installed gfec is the only one: no source tree, no build tree of gfec on the paths.
  # A sanitizer build of gfec installs a sanitized runtime: link the project the same way.
  flags=()
  if [ -n "${GFEC_SANITIZE:-}" ]; then
    flags=(-DCMAKE_C_FLAGS="-fsanitize=$GFEC_SANITIZE" -DCMAKE_CXX_FLAGS="-fsanitize=$GFEC_SANITIZE"
           -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=$GFEC_SANITIZE")
  fi
  cmake -S "$project" -B "$out" -G "$generator" -DCMAKE_PREFIX_PATH="$prefix" "${flags[@]}" >/dev/null ||
    fail "configure ($generator)"
  cmake --build "$out" >/dev/null || fail "build ($generator)"
  blink=$("$out/firmware")
  # LANGUAGE.md 5.1 by hand: ticks counts the actions run; On -> Off once ticks >= 3 (tick 4),
  # Off -> On once ticks >= 5 (tick 6); from then on each transition fires on the next tick.
  [ "$blink" = "###..#.#.#" ] || fail "firmware printed '$blink'"
  [ "$("$out/runtime_user")" = "walldist=42" ] || fail "runtime_user: $("$out/runtime_user")"
  [ -f "$out/blink.json" ] && [ -f "$out/blink.dot" ] || fail "json/dot side products missing"
  grep -q '"kind": "sfc"' "$out/blink.json" || fail "blink.json"
  grep -q 'board.iface' "$out/blink.c.d" || fail "the dependency file lists no import"
  # gfec_add_chart_tests() registered charts/blink.test as one CTest test, and it passes.
  listed=$(ctest --test-dir "$out" -N)
  grep -q "gfec_test.blink" <<<"$listed" || fail "gfec_add_chart_tests registered no test: $listed"
  ctest --test-dir "$out" --output-on-failure >/dev/null || fail "the chart's scenario tests failed"

  # Nothing changed: nothing is regenerated.
  before=$(stat -c %y "$out/blink.c")
  log=$(cmake --build "$out" 2>&1)
  if echo "$log" | grep -q "gfec: compiling"; then fail "a no-op build ran gfec: $log"; fi
  [ "$(stat -c %y "$out/blink.c")" = "$before" ] || fail "blink.c rewritten by a no-op build"

  # An edited import of an import (tuning.iface, through board.iface) rebuilds the engine.
  sleep 1
  sed -i 's/ON_TICKS = 3/ON_TICKS = 1/' "$project/charts/tuning.iface"
  log=$(cmake --build "$out" 2>&1)
  echo "$log" | grep -q "gfec: compiling charts/blink.sfc (c)" || fail "editing tuning.iface did not recompile: $log"
  [ "$(stat -c %y "$out/blink.c")" != "$before" ] || fail "blink.c not regenerated"
  # With ON_TICKS = 1: On -> Off at tick 2, Off -> On once ticks >= 3 (tick 4), then alternating.
  after=$("$out/firmware")
  [ "$after" = "#..#.#.#.#" ] || fail "after ON_TICKS = 1 the firmware printed '$after'"

  # Touching the direct import rebuilds too.
  sleep 1
  before=$(stat -c %y "$out/blink.c")
  touch "$project/charts/board.iface"
  cmake --build "$out" >/dev/null || fail "rebuild"
  [ "$(stat -c %y "$out/blink.c")" != "$before" ] || fail "touching board.iface did not regenerate blink.c"
done
echo "cmake package: all checks passed"
