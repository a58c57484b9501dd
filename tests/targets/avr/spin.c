// avr-run's own test: a program that never halts, for --max-cycles.
int harness_putc(int c);

int main(void) {
  harness_putc('x');
  for (;;) { __asm__ __volatile__(""); }
}
