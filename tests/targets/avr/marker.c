// avr-run's own test: three stretches of a known instruction count between the GPIOR0 markers,
// then main returns the status from the command line's -DSTATUS (0 unless given).
#include <avr/io.h>

#ifndef STATUS
#define STATUS 0
#endif

int harness_putc(int c);

// out GPIOR0 (1) + ldi (1) + 100 x dec (1) + 99 taken brne (2) + the last brne (1) + ldi (1):
// 302 cycles from the start marker's out to the stop marker's out.
static void stretch(void) {
  __asm__ __volatile__("ldi r25, 1\n\t"
                       "out %0, r25\n\t"
                       "ldi r24, 100\n"
                       "1:\tdec r24\n\t"
                       "brne 1b\n\t"
                       "ldi r25, 2\n\t"
                       "out %0, r25" ::"I"(_SFR_IO_ADDR(GPIOR0))
                       : "r24", "r25");
}

int main(void) {
  for (int i = 0; i < 3; ++i) stretch();
  harness_putc('.');
  return STATUS;
}
