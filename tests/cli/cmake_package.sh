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
pkgdir=$(dirname "$config")
ls "$pkgdir"/GfecChart.cmake "$pkgdir"/gfecTargets.cmake "$pkgdir"/gfecRuntimeTargets.cmake >/dev/null || fail "package files"
# A host tool's version file must not compare pointer sizes: a 32-bit (cross) consumer is fine.
cat > "$work/version32.cmake" <<CMAKE
cmake_minimum_required(VERSION 3.20)
set(CMAKE_SIZEOF_VOID_P 4)
set(PACKAGE_FIND_NAME gfec)
set(PACKAGE_FIND_VERSION 0.1)
set(PACKAGE_FIND_VERSION_MAJOR 0)
set(PACKAGE_FIND_VERSION_MINOR 1)
set(PACKAGE_FIND_VERSION_COUNT 2)
include("$pkgdir/gfecConfigVersion.cmake")
message("compatible=\${PACKAGE_VERSION_COMPATIBLE} unsuitable=\${PACKAGE_VERSION_UNSUITABLE}")
CMAKE
verdict=$(cmake -P "$work/version32.cmake" 2>&1)
[ "$verdict" = "compatible=TRUE unsuitable=" ] || fail "a 32-bit consumer of gfec 0.1: $verdict"
# The compiler's targets need no Threads; only the runtime's do.
grep -q "Threads" "$pkgdir/gfecTargets.cmake" && fail "gfecTargets.cmake needs Threads"

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
  # docs/language.md §5.1 by hand: ticks counts the actions run; On -> Off once ticks >= 3 (tick 4),
  # Off -> On once ticks >= 5 (tick 6); from then on each transition fires on the next tick.
  [ "$blink" = "###..#.#.#" ] || fail "firmware printed '$blink'"
  [ "$("$out/runtime_user")" = "walldist=42" ] || fail "runtime_user: $("$out/runtime_user")"
  [ -f "$out/blink.json" ] && [ -f "$out/blink.dot" ] || fail "json/dot side products missing"
  grep -q '"kind": "sfc"' "$out/blink.json" || fail "blink.json"
  grep -q 'board.iface' "$out/blink.c.d" || fail "the dependency file lists no import"
  # No absolute path in what gfec generated: the same files from any checkout and build folder.
  for f in blink.c blink.h blink.c.d; do
    grep -q -e "$project" -e "$out" -e "$work" "$out/$f" && fail "$f holds an absolute path: $(grep -e "$work" "$out/$f" | head -3)"
  done
  grep -q '#line [0-9]* "\.\./project-[^"]*/charts/blink.sfc"' "$out/blink.c" || fail "blink.c's #line is not relative"
  # A plan through CMake: CountTo counts one per step up to limit = 3, writes reached, DONE ends it.
  [ "$("$out/plan_user")" = "reached=3 succeeded=1" ] || fail "plan_user: $("$out/plan_user")"
  for f in count.cpp count.hpp count.cpp.d; do
    grep -q -e "$project" -e "$out" -e "$work" "$out/$f" && fail "$f holds an absolute path: $(grep -e "$work" "$out/$f" | head -3)"
  done
  grep -q '#line [0-9]* "\.\./project-[^"]*/charts/count.plan"' "$out/count.cpp" || fail "count.cpp's #line is not relative"
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
# A Cortex-M4 cross build (tests/cli/cross_project): the toolchain file hides host packages
# (CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY), the one documented line -Dgfec_DIR=... finds gfec,
# the 32-bit consumer passes the version check, Threads is never looked for, and the engine is
# compiled for ARM.
if command -v arm-none-eabi-gcc >/dev/null && command -v ninja >/dev/null; then
  echo "== cross build (arm-none-eabi)"
  cross="$work/cross"
  cp -r "$source_dir/tests/cli/cross_project" "$cross"
  cp -r "$source_dir/tests/cli/package_project/charts" "$cross/charts"
  toolchain="$cross/arm-none-eabi.cmake"
  cmake -S "$cross" -B "$work/cross-hidden" -G Ninja -DCMAKE_TOOLCHAIN_FILE="$toolchain" \
      -DCMAKE_PREFIX_PATH="$prefix" >/dev/null 2>&1 &&
    fail "the toolchain file was expected to hide the package without gfec_DIR"
  cmake -S "$cross" -B "$work/cross-build" -G Ninja -DCMAKE_TOOLCHAIN_FILE="$toolchain" \
      -Dgfec_DIR="$pkgdir" >"$work/cross.log" 2>&1 || fail "cross configure: $(cat "$work/cross.log")"
  grep -qi "threads" "$work/cross.log" && fail "a cross build looked for Threads"
  cmake --build "$work/cross-build" >"$work/cross.log" 2>&1 || fail "cross build: $(cat "$work/cross.log")"
  lib="$work/cross-build/libblink_engine.a"
  arm-none-eabi-readelf -h "$lib" | grep -q "Machine: *ARM" || fail "the engine is not ARM code"
  text=$(arm-none-eabi-size "$lib" | awk 'NR == 2 { print $1 }')
  [ "$text" -gt 0 ] || fail "empty engine"
  echo "Cortex-M4 engine: $text bytes of .text at -Os"
else
  echo "SKIP: cross build (no arm-none-eabi-gcc or ninja; Debian package gcc-arm-none-eabi)"
fi
echo "cmake package: all checks passed"
