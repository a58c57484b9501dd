/* The timing loop of the engine benchmarks: CHART_init once, then CHART_run for N ticks.
     cc -O2 -DCHART=Ring engine_main.c stubs.c ring.c -o bench && ./bench 1000000
   prints `<ns per tick> <checksum>`. Under callgrind (--toggle-collect=Ring_run) the same
   program counts the instructions of the run function and everything it calls. The engine's
   struct is opaque here, so a hand-written machine with another layout fits the same loop. */
#define _POSIX_C_SOURCE 199309L /* clock_gettime under -std=c99 */
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#define GLUE(a, b) a##b
#define NAME(a, b) GLUE(a, b)

/* A generated engine's header (its functions' names carry the chart's fingerprint, which only
   the header knows); a hand-written machine has none. */
#ifdef ENGINE_HEADER
#include ENGINE_HEADER
#else
typedef struct CHART CHART;
void NAME(CHART, _init)(CHART *m);
void NAME(CHART, _run)(CHART *m);
#endif

extern unsigned long bench_tick, bench_sum;

/* Room for the engine's state, aligned for anything it holds. */
static union {
  long double d;
  void *p;
  unsigned long long u;
  unsigned char bytes[1 << 22];
} state;

int main(int argc, char **argv) {
  long ticks = argc > 1 ? atol(argv[1]) : 1000000;
  struct timespec start, end;
  double ns;
  long i;
  CHART *m = (CHART *)(void *)&state;
  NAME(CHART, _init)(m);
  clock_gettime(CLOCK_MONOTONIC, &start);
  for (i = 0; i < ticks; ++i) {
    ++bench_tick;
    NAME(CHART, _run)(m);
  }
  clock_gettime(CLOCK_MONOTONIC, &end);
  ns = (double)(end.tv_sec - start.tv_sec) * 1e9 + (double)(end.tv_nsec - start.tv_nsec);
  printf("%.2f %lu\n", ns / (double)ticks, bench_sum);
  return 0;
}
