// What a test program needs on an ATmega328P under tools/avr-run (docs/targets.md "AVR /
// Arduino"): UART0 set up before main, `int harness_putc(int)` for the engine harness's Putc
// output (backends/c/c_harness.h), and a halt avr-run recognises when main returns.
//
// Link it beside the program: avr-gcc -mmcu=atmega328p -DF_CPU=16000000UL ... avr_support.c
// Nothing here is needed on a board; on one, the output goes to the serial port at 1 Mbaud.
#include <avr/interrupt.h>
#include <avr/io.h>
#include <avr/sleep.h>

#include <stdint.h>

int harness_putc(int c);
void harness_exit(int status);

// avr-run takes each byte as UDR0 is written and does not care for the baud; 1 Mbaud (U2X,
// UBRR 1 at 16 MHz) keeps the UART's own wait per byte short (160 cycles).
__attribute__((naked, used, section(".init8"))) static void harness_uart_init(void) {
  UBRR0H = 0;
  UBRR0L = 1;
  UCSR0A = _BV(U2X0);
  UCSR0B = _BV(TXEN0);
  UCSR0C = _BV(UCSZ01) | _BV(UCSZ00);  // 8N1
}

int harness_putc(int c) {
  loop_until_bit_is_set(UCSR0A, UDRE0);
  UDR0 = (uint8_t)c;
  return c;
}

/// Halts with `status`: GPIOR1 tells avr-run (a non-zero status makes it exit 1), then the CPU
/// sleeps with interrupts off -- power-down for good on a board, the program's end for simavr.
void harness_exit(int status) {
  GPIOR1 = (uint8_t)status;
  cli();
  set_sleep_mode(SLEEP_MODE_PWR_DOWN);
  sleep_enable();
  sleep_cpu();
  for (;;) {}
}

// main's return: avr-libc's exit() runs the .fini sections with main's value still in r24 (C,
// no destructors in between), then would spin in .fini0; this halts first.
__attribute__((naked, used, section(".fini1"))) static void harness_halt(void) {
  __asm__ __volatile__("out %0, r24\n\tcli\n\tldi r24, %2\n\tout %1, r24\n\tsleep" ::"I"(_SFR_IO_ADDR(GPIOR1)),
                       "I"(_SFR_IO_ADDR(SMCR)), "M"(_BV(SM1) | _BV(SE)));
}
