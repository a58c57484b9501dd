#!/usr/bin/env bash
# The C engines are freestanding C99: the sample charts, in every engine form, compiled for a
# Cortex-M4 with arm-none-eabi-gcc -ffreestanding -nostdlib (no C library at all: a hosted
# header such as <string.h> or <assert.h> would not even be found) in every mode -- plain,
# -DX_HOOKS, -DX_CHECKS with the firmware's own X_ASSERT, and both. Without the cross compiler,
# the host gcc with -ffreestanding -nostdinc and only gcc's own freestanding headers. Every
# engine is also made with --context-type and --names.
# Usage: freestanding.sh GFEC SOURCE_DIR
set -euo pipefail
gfec=$1 source_dir=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

strict=(-std=c99 -Wall -Wextra -Wpedantic -Werror -Os -c)
if command -v arm-none-eabi-gcc >/dev/null; then
  cc=(arm-none-eabi-gcc -mcpu=cortex-m4 -mthumb -ffreestanding -nostdlib)
  size=arm-none-eabi-size
else
  echo "no arm-none-eabi-gcc (Debian: gcc-arm-none-eabi): the host gcc with -nostdinc instead"
  # gcc's own folder holds the freestanding headers (stdint.h, stdbool.h, limits.h, ...); with
  # -ffreestanding they do not reach for the C library's.
  cc=(gcc -ffreestanding -nostdinc -isystem "$(gcc -print-file-name=include)" -isystem "$(gcc -print-file-name=include-fixed)")
  size=size
fi
# The firmware's own failure handler: no <assert.h> in sight.
user_assert='-D%s_ASSERT(cond)=do { if (!(cond)) { for (;;) { } } } while (0)'

count=0
for chart in "$source_dir"/samples/*.sfc "$source_dir"/samples/*.fsm; do
  base=$(basename "${chart%.*}")
  forms=(auto)
  [[ $chart == *.sfc ]] && forms=(readable scalable)
  # Each form also with the opt-in instance context and name table (docs/c-engine.md).
  for variant in "${forms[@]}" "${forms[@]/%/+context}"; do
    form=${variant%+context}
    options=()
    [[ $variant == *+context ]] && options=(--context-type='struct device *' --names)
    dir="$work/$base-$variant"
    mkdir -p "$dir"
    "$gfec" --engine="$form" "${options[@]}" -I "$source_dir/samples" -o "$dir/$base.c" "$chart" || fail "gfec $chart"
    name=$(sed -n 's/^void \([A-Za-z0-9_]*\)_init(.*/\1/p' "$dir/$base.h")
    [ -n "$name" ] || fail "no _init in $base.h"
    grep -n '#include <' "$dir/$base.c" "$dir/$base.h" | grep -v -e '<stdint.h>' -e '<stdbool.h>' -e '<limits.h>' -e '<float.h>' -e '<assert.h>' &&
      fail "$base ($variant) includes a hosted header"
    grep -q 'memcpy\|memset\|printf' "$dir/$base.c" && fail "$base ($variant) calls the C library"
    # shellcheck disable=SC2059
    assert_flag=$(printf -- "$user_assert" "$name")
    for mode in plain hooks checks both; do
      defines=()
      case $mode in
        hooks) defines=(-D"${name}_HOOKS") ;;
        checks) defines=(-D"${name}_CHECKS" "$assert_flag") ;;
        both) defines=(-D"${name}_HOOKS" -D"${name}_CHECKS" "$assert_flag") ;;
      esac
      "${cc[@]}" "${strict[@]}" "${defines[@]}" -o "$dir/$mode.o" "$dir/$base.c" 2>"$work/err" ||
        fail "$base ($variant, $mode): $(cat "$work/err")"
      count=$((count + 1))
    done
    # The user's X_ASSERT is the one used: its loop is in the checked object when there is a post.
    if grep -q "${name}_ASSERT(" "$dir/$base.c"; then
      "${cc[@]}" "${strict[@]}" -D"${name}_CHECKS" "$assert_flag" -E -o "$dir/checks.i" "$dir/$base.c"
      grep -q 'for (;;)' "$dir/checks.i" || fail "$base: the user's ${name}_ASSERT is not used"
      grep -q '__assert' "$dir/checks.i" && fail "$base: assert used despite the user's ${name}_ASSERT"
    fi
    echo "$base ($variant): $($size "$dir/plain.o" | awk 'NR == 2 { print $1 }') bytes of .text (plain, -Os)"
  done
done
[ "$count" -ge 32 ] || fail "only $count compiles"
echo "freestanding engines: $count compiles, all checks passed"
