#!/usr/bin/env bash
# Installs every Debian package gfec needs to build, test and run the simulator.
set -euo pipefail
packages=(
  cmake ninja-build gcc g++ clang lld llvm pkg-config make
  libfmt-dev nlohmann-json3-dev libcli11-dev catch2 libode-dev libpugixml-dev
  graphviz valgrind cppcheck time
  diffutils  # diff: gfec fmt --diff (essential in Debian; named because gfec runs it)
  procps  # pgrep: tests/cli/reliability.sh signals gfec, not the timeout(1) around it
  man-db  # man -l: tests/cli/install_files.sh renders docs/man/gfec.1 as `man gfec` shows it
  bash-completion  # tests/cli/install_files.sh: bash-completion loads the installed completion
  dpkg-dev  # dpkg-shlibdeps: the .deb's Depends (cmake/GfecPackage.cmake, tests/cli/deb_package.sh)
  unzip  # the VS Code extension's .vsix contents (tests/editors/vscode_test.sh)
  clang-format  # scripts/format.sh --check, a ctest test
  gcc-arm-none-eabi  # the cross build and freestanding engine tests (Cortex-M4)
  gcc-avr avr-libc libsimavr-dev  # AVR programs and tools/avr-run (docs/targets.md)
  # The engines on emulated targets (tests/targets, docs/targets.md): Cortex-M3/M4F under qemu
  # with picolibc's semihosting, RV32 under qemu-system-riscv32 (in qemu-system-misc).
  picolibc-arm-none-eabi qemu-system-arm
  gcc-riscv64-unknown-elf picolibc-riscv64-unknown-elf qemu-system-misc
  arduino-mk  # the Arduino sketch's make build (examples/arduino-line-follower); brings arduino-core-avr
  chromium   # the run viewer's browser test (tests/viewer)
  neovim     # the language server driven by a real client (tests/lsp/neovim)
  python3    # scripts/bench.sh lsp (tests/bench/bench_lsp.py)
  libcpp-httplib-dev  # gfec monitor --http: the live page's server (monitor/live, docs/live.md)
)
# Node (for the SARIF schema and TextMate grammar tests) may come from another repo already.
command -v npm >/dev/null 2>&1 || packages+=(nodejs npm)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  sudo_cmd=""
  [ "$(id -u)" -eq 0 ] || sudo_cmd="sudo"
  $sudo_cmd apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
