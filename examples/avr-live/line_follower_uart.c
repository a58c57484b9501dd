/* The line follower of samples/line_follower.sfc on a bare ATmega328P (an Arduino Uno's chip,
   avr-gcc and avr-libc, no Arduino core), its engine built with `gfec --trace`: every tick's
   trace frame goes out of the UART at 115200 baud, where `gfec monitor` reads it (docs/live.md
   "The emulated AVR live"; scripts/live-avr.sh runs it under tools/avr-run).
   Wiring as the Arduino sketch's (examples/arduino-line-follower): IR sensors on D2 (PD2, left)
   and D3 (PD3, right), high over the black line; the motor driver's ENA IN1 IN2 on D5 D7 D8
   (PD5 PD7 PB0) and ENB IN3 IN4 on D6 D9 D10 (PD6 PB1 PB2). One tick every 10 ms (the chart's
   period) from Timer1, counted from the first, so a late tick does not shift the others. */
#include <avr/io.h>
#include <stdbool.h>

#include "line_follower.h"

static bool sees_black(uint8_t bit) { return (PIND & (1u << bit)) != 0; }

bool Left_IR_Black(void) { return sees_black(PD2); }
bool Left_IR_White(void) { return !sees_black(PD2); }
bool Right_IR_Black(void) { return sees_black(PD3); }
bool Right_IR_White(void) { return !sees_black(PD3); }

/* Forward: IN1 high, IN2 low, enabled; stopped: all low (the motor coasts). */
void Left_FW(void) {
  PORTD |= (1u << PD5) | (1u << PD7);
  PORTB &= (uint8_t) ~(1u << PB0);
}
void Left_Stop(void) {
  PORTD &= (uint8_t) ~((1u << PD5) | (1u << PD7));
  PORTB &= (uint8_t) ~(1u << PB0);
}
void Right_FW(void) {
  PORTD |= (1u << PD6);
  PORTB |= (1u << PB1);
  PORTB &= (uint8_t) ~(1u << PB2);
}
void Right_Stop(void) {
  PORTD &= (uint8_t) ~(1u << PD6);
  PORTB &= (uint8_t) ~((1u << PB1) | (1u << PB2));
}

/* The engine's trace, byte by byte out of UART0 (polled: a frame of ~20 bytes takes under 2 ms
   of the 10 ms tick at 115200 baud). */
void LineFollower_trace_write(const unsigned char *data, unsigned len) {
  for (unsigned i = 0; i < len; ++i) {
    while (!(UCSR0A & (1u << UDRE0))) {}
    UDR0 = data[i];
  }
}

static LineFollower engine;

int main(void) {
  DDRD |= (1u << PD5) | (1u << PD6) | (1u << PD7);
  DDRB |= (1u << PB0) | (1u << PB1) | (1u << PB2);
  /* UART0: 115200 8N1, double speed (UBRR 16 at 16 MHz: 2.1 % off, as the Arduino core has it). */
  UCSR0A = (1u << U2X0);
  UBRR0 = 16;
  UCSR0B = (1u << TXEN0);
  UCSR0C = (1u << UCSZ01) | (1u << UCSZ00);
  /* Timer1, CTC at 10 ms: 16 MHz / 64 = 250 kHz, 2500 counts. */
  TCCR1A = 0;
  TCCR1B = (1u << WGM12) | (1u << CS11) | (1u << CS10);
  OCR1A = 2499;
  LineFollower_init(&engine);
  for (;;) {
    LineFollower_run(&engine); /* the tick, then its trace frame */
    while (!(TIFR1 & (1u << OCF1A))) {}
    TIFR1 = (1u << OCF1A);
  }
}
