/* The line follower engine on an ATmega328P as a sketch would run it, for the live trace's test
   and cost (docs/live.md): the IR sensors from a table (rows.h, made by trace_test.sh from a CSV
   trace), and with -DTRACED each tick's frame copied into a buffer by LineFollower_trace_write, as
   a serial library's ring buffer takes it, then sent on UART0 between ticks. The tick itself,
   frame included, is marked for avr-run --cycles (GPIOR0 = 1 ... 2). */
#include "lf.h"
#include "rows.h"

#include <avr/io.h>
#include <stdint.h>

int harness_putc(int c);

static uint8_t sensors[4];

bool Left_IR_Black(void) { return sensors[0] != 0u; }
bool Left_IR_White(void) { return sensors[1] != 0u; }
bool Right_IR_Black(void) { return sensors[2] != 0u; }
bool Right_IR_White(void) { return sensors[3] != 0u; }
void Left_FW(void) {}
void Left_Stop(void) {}
void Right_FW(void) {}
void Right_Stop(void) {}

#ifdef TRACED
static unsigned char pending[64];
static unsigned pending_n;

void LineFollower_trace_write(const unsigned char *data, unsigned len)
{
    unsigned i;
    for (i = 0u; (i < len) && (pending_n < sizeof pending); ++i) {
        pending[pending_n] = data[i];
        ++pending_n;
    }
}
#endif

int main(void)
{
    static LineFollower m;
    uint16_t k;
    uint8_t j;
    LineFollower_init(&m);
    for (k = 0u; k < ROWS; ++k) {
        for (j = 0u; j < 4u; ++j) sensors[j] = rows[k][j];
        GPIOR0 = 1;
        LineFollower_run(&m);
        GPIOR0 = 2;
#ifdef TRACED
        for (j = 0u; j < pending_n; ++j) (void)harness_putc(pending[j]);
        pending_n = 0u;
#endif
    }
    return 0;
}
