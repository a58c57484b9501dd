/* The firmware's main loop, reduced to what the test needs: run the engine and print the LED. */
#include "blink.h"

#include <stdio.h>

int main(void) {
  Blink m;
  Blink_init(&m);
  for (int i = 0; i < 10; ++i) {
    Blink_run(&m);
    printf("%c", Blink_activation(&m, Blink_On) ? '#' : '.');
  }
  printf("\n");
  return 0;
}
