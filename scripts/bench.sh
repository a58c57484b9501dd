#!/usr/bin/env bash
# Runs every benchmark of docs/performance.md and prints its tables. Measures; never fails on time.
#
#   scripts/bench.sh [--quick] [SECTION...]     sections: compiler cc engine size target trace sim plan lsp iec (default: all)
#
# Builds a Release tree in build-bench/ (or $GFEC_BENCH_BUILD_DIR) with the targets the
# benchmarks need: gfec, gfec_bench_gen, afp_step_bench, sim_rtf. --quick uses smaller sizes
# (compiler up to 100000 places, fewer ticks) for a run of about a minute. Section iec measures
# MatIEC's engine beside gfec's when MATIEC names a MatIEC tree built by hand
# (tests/iec/matiec/README.md); without it that side is skipped, saying so.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${GFEC_BENCH_BUILD_DIR:-$root/build-bench}
quick=0
sections=()
for arg in "$@"; do
  case $arg in
    --quick) quick=1 ;;
    compiler | cc | engine | size | target | trace | sim | plan | lsp | iec) sections+=("$arg") ;;
    *) echo "usage: scripts/bench.sh [--quick] [compiler|cc|engine|size|target|trace|sim|plan|lsp|iec]..." >&2; exit 2 ;;
  esac
done
[[ ${#sections[@]} -gt 0 ]] || sections=(compiler cc engine size target trace sim plan lsp iec)

if [[ ! -f $build/build.ninja ]]; then
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release > /dev/null
fi
cmake --build "$build" -j 2 --target bench_tools > /dev/null
gfec=$build/gfec
gen=$build/tests/bench/gfec_bench_gen

echo "== machine: $(uname -srm); $(nproc) cores; $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
echo "== gfec $(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo '?'), $(date -u +%Y-%m-%d)"
for section in "${sections[@]}"; do
  echo
  case $section in
    compiler)
      echo "== (a) compiler: time, lines per second, peak memory"
      if ((quick)); then
        "$root/tests/bench/bench_compiler.sh" "$gfec" "$gen" 1000 10000 100000
      else
        "$root/tests/bench/bench_compiler.sh" "$gfec" "$gen"
      fi ;;
    cc)
      echo "== (a') the C compiler on large engines"
      "$root/tests/bench/bench_cc.sh" "$gfec" "$gen" ;;
    engine)
      echo "== (b) engine: instructions and nanoseconds per tick"
      if ((quick)); then export BENCH_TICKS=200000; fi
      "$root/tests/bench/bench_engine.sh" "$gfec" "$gen"
      echo
      echo "== (b') engine: what a sub-chart instance costs per tick"
      "$root/tests/bench/bench_subchart.sh" "$gfec" ;;
    size)
      echo "== (c) engine size"
      "$root/tests/bench/bench_size.sh" "$gfec" "$gen" ;;
    target)
      echo "== (c') cost on the emulated targets: flash, RAM, cycles or instructions per tick"
      cmake --build "$build" -j 2 --target avr-run > /dev/null 2>&1 || echo "(avr-run not built: no libsimavr; the AVR rows are skipped)"
      GFEC_TARGET_BIN=$build "$root/tests/bench/bench_target.sh" "$gfec" ;;
    trace)
      echo "== (c'') the live trace (--trace, docs/live.md): bytes and cycles per tick on the emulated AVR"
      if cmake --build "$build" -j 2 --target avr-run > /dev/null 2>&1 && command -v avr-gcc > /dev/null; then
        "$root/tests/targets/avr/trace_test.sh" "$gfec" "$build/tools/avr-run/avr-run" "$root" --bench
      else
        echo "(avr-run or avr-gcc missing: no trace row)"
      fi ;;
    sim)
      echo "== (d) simulator real-time factor"
      if [[ -x $build/sim_rtf ]]; then
        "$build/sim_rtf" --seconds $((quick ? 10 : 60))
      else
        echo "sim_rtf not built (GFEC_BUILD_SIM=OFF?)"
      fi ;;
    plan)
      echo "== (e) plan runtime: overhead per executor step"
      "$build/tests/bench/afp_step_bench" $((quick ? 200000 : 2000000)) ;;
    lsp)
      echo "== (f) language server: latency on a 5000-place chart"
      python3 "$root/tests/bench/bench_lsp.py" "$gfec" "$gen" 5000 $((quick ? 10 : 30)) ;;
    iec)
      echo "== (g) PLCopen XML: read + check, and read + check + compile, of a generated project;"
      echo "==     the 500-step program's engine, and MatIEC's beside it with MATIEC=DIR"
      if ((quick)); then "$root/tests/bench/bench_plcopen.sh" "$gfec" "$root" 500; else "$root/tests/bench/bench_plcopen.sh" "$gfec" "$root"; fi ;;
  esac
done
