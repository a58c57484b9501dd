#!/usr/bin/env bash
# Formats the hand-written C and C++ of the repository with clang-format (the .clang-format files:
# the root one for the compiler, its support, back ends, driver, language server, viewer, tools and tests; Google's style in sim/, runtime/ and
# tests/runtime/). Generated files (tests/golden/) are left as gfec wrote them.
#
#   scripts/format.sh            rewrite the files in place
#   scripts/format.sh --check    list the files that are not formatted; exit 1 if there are any
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
mapfile -t files < <(git ls-files -- support compiler backends viewer monitor driver lsp runtime sim tests tools |
  grep -E '\.(cc|cpp|h|hpp|c)$' | grep -v '^tests/golden/')
if [[ ${1:-} == --check ]]; then
  bad=0
  for f in "${files[@]}"; do
    if ! clang-format --dry-run --Werror "$f" > /dev/null 2>&1; then
      echo "not formatted: $f"
      bad=1
    fi
  done
  exit $bad
fi
clang-format -i "${files[@]}"
