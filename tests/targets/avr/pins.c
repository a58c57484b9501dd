// avr-run's own test: PB0 and PB1 follow the inputs PD2 and PD3 until PD4 goes high.
#include <avr/io.h>

int main(void) {
  DDRB = _BV(DDB0) | _BV(DDB1);
  while (!(PIND & _BV(PIND4))) PORTB = (uint8_t)((PIND >> PIND2) & 3u);
  return 0;
}
