/* The robot library of the engine benchmarks: every interface function the benchmark charts
   call, as cheap as a real one could be, and the same for a generated engine and for the
   hand-written machine it is compared with. Sensing functions answer from the tick number, so
   tokens move every few ticks; actions add to a checksum, so two machines that make different
   calls print different sums. */
#include <stdbool.h>

unsigned long bench_tick; /* the tick being run, from 1 */
unsigned long bench_sum;  /* what the actions did */

/* tests/bench/gen_chart.cc: rings and branches */
bool Go(int i) { return ((bench_tick + (unsigned long)i) & 3u) == 0; }
void Act(int i) { bench_sum += (unsigned long)i; }

/* samples/linebot.iface: the line follower */
bool Left_IR_Black(void) { return bench_tick % 4 == 0; }
bool Left_IR_White(void) { return bench_tick % 4 == 2; }
bool Right_IR_Black(void) { return bench_tick % 5 == 0; }
bool Right_IR_White(void) { return bench_tick % 5 == 3; }
void Left_FW(void) { bench_sum += 1; }
void Left_Stop(void) { bench_sum += 2; }
void Right_FW(void) { bench_sum += 3; }
void Right_Stop(void) { bench_sum += 4; }
