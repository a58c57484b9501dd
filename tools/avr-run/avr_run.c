// avr-run: runs an AVR program under simavr the way a test needs it (docs/targets.md "AVR / Arduino").
//
//   avr-run --mcu atmega328p [--freq 16000000] [--max-cycles N] [--cycles]
//           [--pins SCRIPT] [--pin-log FILE] [--real-time] PROGRAM.elf
//
// simavr's own command line decorates the UART's lines and rewrites newlines, and sleeps in real
// time; this runner gives a test the program's bytes and a plain exit status instead:
//   stdout   every byte the program writes to UART0, as it is, and nothing else
//   exit 0   the program halted: interrupts off and sleep (avr-libc: cli(); sleep_mode();),
//            or main returned with tests/targets/avr/avr_support.c linked in
//   exit 1   the program halted after writing a non-zero status to GPIOR1 (avr_support.c
//            writes main's return value there); stderr says `exit status N`
//   exit 2   bad usage, an unreadable program or pin script, or the program crashed
//   exit 3   timeout: more than --max-cycles cycles (default 2e9, 125 s of a 16 MHz part)
//
// Cycle markers (--cycles): writing 1 to GPIOR0 starts a stretch, writing 2 ends it; avr-run adds
// up the cycles of every stretch and prints `marked-cycles N (K stretches)` on stderr at exit,
// after `cycles N` (every cycle from reset). A stretch is counted from its start write to its end
// write, so the count holds the start marker's own `out` and not the end marker's. Interrupts
// taken inside a stretch are counted in it. The marker registers are the megaAVR's (GPIOR0 at
// data address 0x3E, GPIOR1 at 0x4A), as on the ATmega48/88/168/328, 644, 1284 and 2560.
//
// Real time (--real-time): the program runs no faster than the part would (it is slower when the
// host cannot keep up), and its UART bytes leave each emulated millisecond instead of when
// stdout's buffer fills: what a live monitor reading the UART through a pipe needs
// (scripts/live-avr.sh, docs/live.md).
//
// Pins: --pins SCRIPT drives input pins at given times; --pin-log FILE records every change of an
// output pin (a pin whose DDR bit is set; its level is its PORT bit). Both use one line format:
//   TIME PIN=VALUE [PIN=VALUE ...]      # a comment
// TIME is cycles from reset (`160000`), or `10ms` / `250us` at --freq; PIN is the port letter
// and bit as the datasheet names them (`PD2`; an Uno's digital pin 2 is PD2, 8 is PB0, A0 is
// PC0); VALUE is 0 or 1. Script times never decrease; a line takes effect before the first
// instruction at or after its time (a sleeping CPU sees it when it wakes). The log writes times
// in cycles, one change a line, in the order they happened; an output that changes back within one
// instruction is not seen.
#include <sim_avr.h>
#include <sim_elf.h>
#include <sim_io.h>
#include <sim_irq.h>
#include <avr_ioport.h>
#include <avr_uart.h>

#include <ctype.h>
#include <errno.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

enum { kExitOk = 0, kExitStatus = 1, kExitError = 2, kExitTimeout = 3 };
enum { kGpior0 = 0x3E, kGpior1 = 0x4A, kMarkStart = 1, kMarkStop = 2, kMaxPorts = 12 };

typedef struct Options {
  const char *mcu;
  uint32_t freq;
  uint64_t max_cycles;
  int cycles;
  const char *pins;
  const char *pin_log;
  const char *program;
  int real_time;
} Options;

/// One pin set by the script at a time.
typedef struct PinEvent {
  uint64_t cycle;
  char port;
  int bit;
  int value;
} PinEvent;

typedef struct Script {
  PinEvent *events;
  size_t count, capacity, next;
} Script;

/// An I/O port of the MCU and the output levels last logged.
typedef struct Port {
  char name;
  avr_io_addr_t r_port, r_ddr;
  uint8_t outputs;
} Port;

typedef struct Run {
  avr_t *avr;
  uint64_t mark_start, marked;
  unsigned long stretches;
  int marking;
  uint8_t status;
  Port ports[kMaxPorts];
  int port_count;
  FILE *pin_log;
} Run;

static const char *program_name = "avr-run";

static void fail_usage(const char *format, ...) {
  va_list args;
  va_start(args, format);
  fprintf(stderr, "%s: ", program_name);
  vfprintf(stderr, format, args);
  va_end(args);
  fprintf(stderr, "\nusage: avr-run --mcu MCU [--freq HZ] [--max-cycles N] [--cycles] [--pins SCRIPT] "
                  "[--pin-log FILE] [--real-time] PROGRAM.elf\n");
  exit(kExitError);
}

/// simavr's default logger writes its warnings to stdout, which belongs to the program's UART.
static void log_to_stderr(avr_t *avr, const int level, const char *format, va_list args) {
  (void)avr;
  if (level <= LOG_WARNING) vfprintf(stderr, format, args);
}

static int parse_u64(const char *text, uint64_t *out) {
  char *end;
  if (!isdigit((unsigned char)text[0])) return 0;
  errno = 0;
  unsigned long long v = strtoull(text, &end, 10);
  if (errno != 0 || *end != '\0') return 0;
  *out = v;
  return 1;
}

static Options parse_options(int argc, char **argv) {
  Options o = {NULL, 16000000u, 2000000000ull, 0, NULL, NULL, NULL, 0};
  for (int i = 1; i < argc; ++i) {
    const char *a = argv[i];
    int has_value = i + 1 < argc;
    uint64_t n;
    if (strcmp(a, "--cycles") == 0) {
      o.cycles = 1;
    } else if (strcmp(a, "--real-time") == 0) {
      o.real_time = 1;
    } else if (strcmp(a, "--mcu") == 0 && has_value) {
      o.mcu = argv[++i];
    } else if (strcmp(a, "--freq") == 0 && has_value) {
      if (!parse_u64(argv[++i], &n) || n == 0 || n > UINT32_MAX) fail_usage("bad --freq '%s'", argv[i]);
      o.freq = (uint32_t)n;
    } else if (strcmp(a, "--max-cycles") == 0 && has_value) {
      if (!parse_u64(argv[++i], &o.max_cycles)) fail_usage("bad --max-cycles '%s'", argv[i]);
    } else if (strcmp(a, "--pins") == 0 && has_value) {
      o.pins = argv[++i];
    } else if (strcmp(a, "--pin-log") == 0 && has_value) {
      o.pin_log = argv[++i];
    } else if (a[0] == '-' && a[1] != '\0') {
      fail_usage("unknown option or missing value: '%s'", a);
    } else if (o.program) {
      fail_usage("one program only ('%s' and '%s')", o.program, a);
    } else {
      o.program = a;
    }
  }
  if (!o.mcu) fail_usage("--mcu is required (e.g. --mcu atmega328p)");
  if (!o.program) fail_usage("no program given");
  return o;
}

/// `160000`, `10ms` or `250us` in cycles at `freq`.
static int parse_time(const char *text, uint32_t freq, uint64_t *cycle) {
  char digits[32];
  size_t n = strspn(text, "0123456789");
  if (n == 0 || n >= sizeof digits) return 0;
  memcpy(digits, text, n);
  digits[n] = '\0';
  uint64_t v;
  if (!parse_u64(digits, &v)) return 0;
  const char *unit = text + n;
  if (*unit == '\0') {
    *cycle = v;
  } else if (strcmp(unit, "ms") == 0) {
    *cycle = v * freq / 1000u;
  } else if (strcmp(unit, "us") == 0) {
    *cycle = v * freq / 1000000u;
  } else {
    return 0;
  }
  return 1;
}

/// `PD2=1`.
static int parse_pin(const char *text, PinEvent *e) {
  if (text[0] != 'P' || text[1] < 'A' || text[1] > 'L' || text[2] < '0' || text[2] > '7' || text[3] != '=' ||
      (text[4] != '0' && text[4] != '1') || text[5] != '\0')
    return 0;
  e->port = text[1];
  e->bit = text[2] - '0';
  e->value = text[4] - '0';
  return 1;
}

static void add_event(Script *s, PinEvent e) {
  if (s->count == s->capacity) {
    s->capacity = s->capacity ? 2 * s->capacity : 64;
    s->events = realloc(s->events, s->capacity * sizeof *s->events);
    if (!s->events) fail_usage("out of memory");
  }
  s->events[s->count++] = e;
}

static Script read_script(const char *path, uint32_t freq) {
  Script s = {NULL, 0, 0, 0};
  FILE *f = fopen(path, "r");
  if (!f) fail_usage("%s: %s", path, strerror(errno));
  char line[4096];
  uint64_t last = 0;
  for (int number = 1; fgets(line, sizeof line, f); ++number) {
    char *hash = strchr(line, '#');
    if (hash) *hash = '\0';
    char *word = strtok(line, " \t\r\n");
    if (!word) continue;
    uint64_t cycle;
    if (!parse_time(word, freq, &cycle))
      fail_usage("%s:%d: bad time '%s' (cycles, or e.g. 10ms, 250us)", path, number, word);
    if (cycle < last) fail_usage("%s:%d: time '%s' is before the line above", path, number, word);
    last = cycle;
    int pins = 0;
    while ((word = strtok(NULL, " \t\r\n")) != NULL) {
      PinEvent e;
      if (!parse_pin(word, &e)) fail_usage("%s:%d: bad pin '%s' (e.g. PD2=1)", path, number, word);
      e.cycle = cycle;
      add_event(&s, e);
      ++pins;
    }
    if (pins == 0) fail_usage("%s:%d: a time without pins", path, number);
  }
  fclose(f);
  return s;
}

static void uart_output(struct avr_irq_t *irq, uint32_t value, void *param) {
  (void)irq;
  (void)param;
  putchar((int)(value & 0xffu));
}

static void marker_write(avr_t *avr, avr_io_addr_t addr, uint8_t v, void *param) {
  Run *run = param;
  avr->data[addr] = v;
  if (v == kMarkStart && !run->marking) {
    run->marking = 1;
    run->mark_start = avr->cycle;
  } else if (v == kMarkStop && run->marking) {
    run->marking = 0;
    run->marked += avr->cycle - run->mark_start;
    ++run->stretches;
  }
}

static void status_write(avr_t *avr, avr_io_addr_t addr, uint8_t v, void *param) {
  Run *run = param;
  avr->data[addr] = v;
  run->status = v;
}

/// The MCU's I/O ports, from simavr's list of I/O modules.
static void find_ports(Run *run) {
  for (avr_io_t *io = run->avr->io_port; io; io = io->next) {
    if (strcmp(io->kind, "port") != 0 || run->port_count == kMaxPorts) continue;
    avr_ioport_t *p = (avr_ioport_t *)io;
    Port *port = &run->ports[run->port_count++];
    port->name = p->name;
    port->r_port = p->r_port;
    port->r_ddr = p->r_ddr;
    port->outputs = 0;
  }
}

static void log_outputs(Run *run) {
  const uint8_t *data = run->avr->data;
  for (int i = 0; i < run->port_count; ++i) {
    Port *p = &run->ports[i];
    uint8_t now = data[p->r_port] & data[p->r_ddr];
    uint8_t changed = now ^ p->outputs;
    if (changed == 0) continue;
    for (int bit = 0; bit < 8; ++bit)
      if (changed & (1u << bit))
        fprintf(run->pin_log, "%llu P%c%d=%d\n", (unsigned long long)run->avr->cycle, p->name, bit, (now >> bit) & 1);
    p->outputs = now;
  }
}

static void apply_pins(Run *run, Script *s) {
  while (s->next < s->count && s->events[s->next].cycle <= run->avr->cycle) {
    const PinEvent *e = &s->events[s->next++];
    avr_irq_t *irq = avr_io_getirq(run->avr, AVR_IOCTL_IOPORT_GETIRQ(e->port), IOPORT_IRQ_PIN0 + e->bit);
    if (!irq) {
      fprintf(stderr, "%s: the %s has no port %c\n", program_name, run->avr->mmcu, e->port);
      exit(kExitError);
    }
    // Only a change: simavr checks a low INT0/INT1 pin (PD2, PD3) every cycle once told of it,
    // which would make a run that drives one low from the start several times slower.
    if (irq->value != (uint32_t)e->value) avr_raise_irq(irq, (uint32_t)e->value);
  }
}

/// simavr sleeps in real time while the program sleeps; a test wants it over at once.
static void no_sleep(avr_t *avr, avr_cycle_count_t how_long) {
  (void)avr;
  (void)how_long;
}

static void print_cycles(const Options *o, const Run *run) {
  if (!o->cycles) return;
  fprintf(stderr, "cycles %llu\n", (unsigned long long)run->avr->cycle);
  fprintf(stderr, "marked-cycles %llu (%lu stretches)\n", (unsigned long long)run->marked, run->stretches);
}

// Under LeakSanitizer (tests/sanitize.sh): libsimavr never frees its core and IRQ tables, on any
// exit path (avr_terminate leaves them), so their allocations are suppressed by module; a leak of
// avr-run's own is still reported. Without a sanitizer nothing calls this.
const char *__lsan_default_suppressions(void);
const char *__lsan_default_suppressions(void) { return "leak:libsimavr\n"; }

int main(int argc, char **argv) {
  Options o = parse_options(argc, argv);
  avr_global_logger_set(log_to_stderr);
  static elf_firmware_t firmware;
  if (elf_read_firmware(o.program, &firmware) != 0 || firmware.flashsize == 0)
    fail_usage("%s: not an AVR ELF program", o.program);
  Run run;
  memset(&run, 0, sizeof run);
  run.avr = avr_make_mcu_by_name(o.mcu);
  if (!run.avr) fail_usage("simavr does not know the MCU '%s'", o.mcu);
  avr_init(run.avr);
  run.avr->log = LOG_WARNING;
  firmware.frequency = o.freq;
  avr_load_firmware(run.avr, &firmware);
  run.avr->frequency = o.freq;
  run.avr->sleep = no_sleep;

  // UART0's bytes to stdout, each one even when it repeats the last, without simavr's line
  // printing and without its real-time wait while the program polls the UART.
  avr_irq_t *uart = avr_io_getirq(run.avr, AVR_IOCTL_UART_GETIRQ('0'), UART_IRQ_OUTPUT);
  if (uart) {
    uint32_t flags = 0;
    avr_ioctl(run.avr, AVR_IOCTL_UART_GET_FLAGS('0'), &flags);
    flags &= ~(uint32_t)(AVR_UART_FLAG_STDIO | AVR_UART_FLAG_POLL_SLEEP);
    avr_ioctl(run.avr, AVR_IOCTL_UART_SET_FLAGS('0'), &flags);
    avr_irq_set_flags(uart, avr_irq_get_flags(uart) & ~IRQ_FLAG_FILTERED);
    avr_irq_register_notify(uart, uart_output, NULL);
  }
  avr_register_io_write(run.avr, kGpior0, marker_write, &run);
  avr_register_io_write(run.avr, kGpior1, status_write, &run);

  Script script = {NULL, 0, 0, 0};
  if (o.pins) script = read_script(o.pins, o.freq);
  if (o.pin_log) {
    run.pin_log = fopen(o.pin_log, "w");
    if (!run.pin_log) fail_usage("%s: %s", o.pin_log, strerror(errno));
    find_ports(&run);
  }

  int code = kExitOk;
  // --real-time: each emulated millisecond, the UART's bytes go out and the run waits for the clock.
  struct timespec start;
  clock_gettime(CLOCK_MONOTONIC, &start);
  const uint64_t per_ms = o.freq / 1000u ? o.freq / 1000u : 1u;
  uint64_t next_ms = per_ms;
  for (;;) {
    if (o.real_time && run.avr->cycle >= next_ms) {
      next_ms += per_ms;
      fflush(stdout);
      struct timespec now;
      clock_gettime(CLOCK_MONOTONIC, &now);
      const double ahead = (double)run.avr->cycle / o.freq -
                           ((double)(now.tv_sec - start.tv_sec) + (double)(now.tv_nsec - start.tv_nsec) / 1e9);
      if (ahead > 0) {
        struct timespec wait = {(time_t)ahead, (long)((ahead - (double)(time_t)ahead) * 1e9)};
        nanosleep(&wait, NULL);
      }
    }
    if (script.next < script.count) apply_pins(&run, &script);
    int state = avr_run(run.avr);
    if (run.pin_log) log_outputs(&run);
    if (state == cpu_Done) break;
    if (state == cpu_Crashed) {
      fflush(stdout);
      fprintf(stderr, "%s: %s crashed after %llu cycles\n", program_name, o.program,
              (unsigned long long)run.avr->cycle);
      code = kExitError;
      break;
    }
    if (run.avr->cycle > o.max_cycles) {
      fflush(stdout);
      fprintf(stderr, "%s: timeout: %s ran past %llu cycles\n", program_name, o.program,
              (unsigned long long)o.max_cycles);
      code = kExitTimeout;
      break;
    }
  }
  fflush(stdout);
  if (code == kExitOk && run.status != 0) {
    fprintf(stderr, "%s: exit status %u\n", program_name, run.status);
    code = kExitStatus;
  }
  print_cycles(&o, &run);
  if (run.pin_log && fclose(run.pin_log) != 0) {
    fprintf(stderr, "%s: %s: %s\n", program_name, o.pin_log, strerror(errno));
    code = kExitError;
  }
  avr_terminate(run.avr);
  free(script.events);
  return code;
}
