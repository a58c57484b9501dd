/* The loop of the target benchmarks (bench_target.sh): CHART_init once, then TICKS ticks of
   CHART_run, each between two markers, after as many empty stretches (the markers' own cost,
   which the script subtracts on the qemu targets). On the AVR a marker is a write to GPIOR0,
   which tools/avr-run times in cycles; elsewhere a call of bench_mark (semihost_support.c) whose
   address the script finds in qemu's instruction trace. The state is a buffer of the size the
   script measured, so a hand-written machine with its own layout fits the same loop. */
#ifdef __AVR__
#include <avr/io.h>
#define MARK(x) (GPIOR0 = (x))
#else
void bench_mark(int what);
#define MARK(x) bench_mark(x)
#endif

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

extern volatile unsigned long bench_tick;
extern volatile unsigned long bench_sum;

static union {
  long l;
  void *p;
  float f;
  unsigned char bytes[STATE_BYTES];
} state;

int main(void) {
  int i;
  CHART *m = (CHART *)(void *)&state;
  NAME(CHART, _init)(m);
#ifndef __AVR__
  for (i = 0; i < TICKS; ++i) {
    MARK(1);
    MARK(2);
  }
#endif
  for (i = 0; i < TICKS; ++i) {
    ++bench_tick;
    MARK(1);
    NAME(CHART, _run)(m);
    MARK(2);
  }
  return (int)(bench_sum & 0u);
}
