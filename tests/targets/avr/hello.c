// avr-run's own test: these bytes reach stdout exactly (tests/targets/avr/avr_run_test.sh).
int harness_putc(int c);

static void say(const char *s) {
  while (*s) harness_putc((unsigned char)*s++);
}

int main(void) {
  say("hello, avr\n\n  two newlines above\r\n");
  for (int c = 0; c < 256; ++c) harness_putc(c);
  say("AAA\n");
  return 0;
}
