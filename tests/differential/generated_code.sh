#!/usr/bin/env bash
# The generated-code gate (docs/verification.md): every sample's engine compiles warning-free
# with gcc and clang at -Wall -Wextra -Wpedantic -Werror as C99 and C11 (plain, with the hooks,
# with the checks), every plan's C++ wiring and toolbox skeleton at -std=c++17, and cppcheck
# reports nothing on any of it. Random charts' engines go through the same compilers and
# cppcheck in gfec_differential.
#
#   tests/differential/generated_code.sh GFEC SOURCE_DIR WORK_DIR
set -euo pipefail
gfec=$1
src=$2
work=$3
rm -rf "$work"
mkdir -p "$work"
cd "$work"

strict=(-Wall -Wextra -Wpedantic -Werror)
ccs=()
for cc in gcc clang; do command -v "$cc" > /dev/null && ccs+=("$cc"); done
cxxs=()
for cxx in g++ clang++; do command -v "$cxx" > /dev/null && cxxs+=("$cxx"); done
failed=0
fail() { echo "FAIL: $*"; failed=1; }
run() { "$@" 2> err.txt || { fail "$*"; cat err.txt; }; }

c_files=()
for chart in "$src"/samples/*.sfc "$src"/samples/*.fsm; do
  base=$(basename "$chart")
  out="${base%.*}_${base##*.}.c"
  run "$gfec" -I "$src/samples" "$chart" -o "$out"
  [ -f "$out" ] || continue
  c_files+=("$out")
  prefix=$(grep -o '[A-Za-z_][A-Za-z0-9_]*_HOOKS' "$out" | head -n 1 | sed 's/_HOOKS$//')
  for cc in "${ccs[@]}"; do
    for std in c99 c11; do
      for variant in "" "-D${prefix}_HOOKS" "-D${prefix}_CHECKS"; do
        run "$cc" "-std=$std" "${strict[@]}" $variant -c "$out" -o /dev/null
      done
    done
  done
done

# The stricter sets firmware teams build with (docs/c-engine.md, "Warnings"): clang's
# -Weverything less the short documented list, and gcc's conversion and hygiene warnings at -O2
# (where gcc decides conditions), for every sample and golden chart in both engine forms, with
# the hooks and the checks compiled in.
everything=(-std=c99 -Weverything -Wno-padded -Wno-bad-function-cast -Werror)
gcc_strict=(-std=c99 -O2 -Wall -Wextra -Wpedantic -Wconversion -Wshadow -Wcast-qual -Wstrict-prototypes -Wundef
  -Wdouble-promotion -Werror)
strict_count=0
for chart in "$src"/samples/*.sfc "$src"/samples/*.fsm "$src"/tests/golden/c/*.sfc "$src"/tests/golden/c/*.fsm; do
  base=$(basename "$chart")
  forms=(auto)
  [[ $chart == *.sfc ]] && forms=(readable scalable)
  for form in "${forms[@]}"; do
    out="strict_${base%.*}_${form}.c"
    run "$gfec" --engine="$form" -I "$src/samples" -I "$(dirname "$chart")" "$chart" -o "$out"
    [ -f "$out" ] || continue
    prefix=$(sed -n 's/^void \([A-Za-z0-9_]*\)_init(.*/\1/p' "${out%.c}.h" | head -n 1)
    defines=(-D"${prefix}_HOOKS" -D"${prefix}_CHECKS")
    command -v clang > /dev/null && run clang "${everything[@]}" "${defines[@]}" -c "$out" -o /dev/null
    command -v gcc > /dev/null && run gcc "${gcc_strict[@]}" "${defines[@]}" -c "$out" -o /dev/null
    strict_count=$((strict_count + 1))
  done
done

cpp_files=()
for toolbox in "$src"/samples/*.toolbox; do
  name=$(grep -o '^toolbox [A-Za-z_][A-Za-z0-9_]*' "$toolbox" | head -n 1 | cut -d' ' -f2 | tr '[:upper:]' '[:lower:]')
  run "$gfec" --emit=toolbox-skeleton "$toolbox" -o "${name}_toolbox.h"
  [ -f "${name}_toolbox.cpp" ] && cpp_files+=("${name}_toolbox.cpp")
done
for plan in "$src"/samples/*.plan; do
  base=$(basename "$plan" .plan)
  run "$gfec" -I "$src/samples" "$plan" -o "$base.cpp"
  [ -f "$base.cpp" ] && cpp_files+=("$base.cpp")
done
for f in "${cpp_files[@]}"; do
  for cxx in "${cxxs[@]}"; do
    run "$cxx" -std=c++17 "${strict[@]}" -I "$src/runtime/include" -I . -c "$f" -o /dev/null
  done
done

if command -v cppcheck > /dev/null; then
  checks=(--enable=warning,style,performance,portability --error-exitcode=1 --quiet --inline-suppr)
  run cppcheck "${checks[@]}" --std=c99 "${c_files[@]}"
  # The runtime's own headers are not generated code: read them, report nothing of theirs.
  [ ${#cpp_files[@]} -gt 0 ] &&
    run cppcheck "${checks[@]}" --language=c++ --std=c++17 -I "$src/runtime/include" -I . \
      --suppress="*:$src/runtime/*" "${cpp_files[@]}"
else
  echo "cppcheck not installed: skipped"
fi

echo "generated code: ${#c_files[@]} C engines with ${ccs[*]} (C99, C11; plain, hooks, checks), $strict_count under clang -Weverything and gcc's strict set, ${#cpp_files[@]} C++ files with ${cxxs[*]}, cppcheck"
exit $failed
