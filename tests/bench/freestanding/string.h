/* The one function of <string.h> that a gfec engine may call, for a bare-metal target without
   a C library's headers (the Cortex-M4 size benchmark, bench_size.sh). */
#ifndef GFEC_BENCH_STRING_H
#define GFEC_BENCH_STRING_H
#include <stddef.h>
void *memcpy(void *dest, const void *src, size_t n);
#endif
