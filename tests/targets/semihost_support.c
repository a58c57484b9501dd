/* The target's side of a test or benchmark program on the qemu targets (tests/targets/targets.txt):
   the log goes to the host's stdout through picolibc's semihosting stdio, and returning from main
   ends the emulator with main's status (crt0-semihost calls exit, which qemu turns into its own). */
#include <stdio.h>

int harness_putc(int c);
void bench_mark(int what);

int harness_putc(int c) { return putchar(c); }

/* Benchmarks (tests/bench/bench_target.sh) count the instructions between two calls: 1 starts a
   measured stretch, 2 ends it. The asm keeps the call and its argument from being optimised out. */
__attribute__((noinline)) void bench_mark(int what) { __asm__ volatile("" : : "r"(what) : "memory"); }
