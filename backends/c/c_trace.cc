// --trace (docs/live.md): after each tick the engine hands one frame to X_trace_write, the user's
// function. The values come through the engine's own accessors (X_activation,
// X_instance_activation), so every form of the engine writes the same frames; the layout of the
// values and the fingerprint come from the one description of the format (compiler/trace_format.h)
// that the monitor reads too.
#include "c_trace.h"

#include "c_emit.h"
#include "trace_format.h"

#include <fmt/format.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace gfec::c_backend {

namespace {

trace::Layout layout(const EngineContext &c) {
  trace::Layout l = trace::layout_of(c.model, c.options.chart);
  // The frame's length and its positions are 16-bit numbers (an AVR's unsigned).
  if (l.max_frame() > 65535)
    throw std::runtime_error(fmt::format("--trace: {} {} has {} values a frame (places, instances' places, status), "
                                         "more than a frame of at most 65535 bytes can hold",
                                         l.fsm ? "fsm" : "sfc", c.type, l.values));
  return l;
}

}  // namespace

void trace_prototype(CodeWriter &w, const EngineContext &c) {
  w.line("/* --trace (docs/live.md in gfec's documentation): after each tick {}_run hands one frame of", c.type);
  w.line("   `len` bytes to this function, which the caller defines (a UART, a socket, a file). */");
  w.line("void {}(const unsigned char *data, unsigned len);", c.trace_write_fn);
}

void trace_fields(const EngineContext &c, FieldRows &rows) {
  const trace::Layout l = layout(c);
  rows.emplace_back(fmt::format("uint32_t {};", c.trace_tick), "--trace: the ticks run since _init");
  rows.emplace_back(fmt::format("uint16_t {};", c.trace_left), "--trace: frames of changes before a full one");
  rows.emplace_back(fmt::format("uint32_t {}[{}];", c.trace_prev, l.values), "--trace: the values of the last frame");
}

void trace_init(CodeWriter &w, const EngineContext &c) {
  const trace::Layout l = layout(c);
  w.line("{} = 0u;", c.field(c.trace_tick));
  w.line("{} = 0u;", c.field(c.trace_left));
  // A block of its own: each form declares the function's index with a type of its own.
  auto scope = w.block("{");
  w.line("uint16_t {};", c.i);
  auto each = w.block(fmt::format("for ({0} = 0u; {0} < {1}u; ++{0}) {{", c.i, l.values));
  w.line("{}[{}] = 0u;", c.field(c.trace_prev), c.i);
}

void emit_trace(CodeWriter &w, const EngineContext &c) {
  const trace::Layout l = layout(c);
  const std::string &t = c.type, &m = c.self;
  const std::size_t size = l.max_frame();
  w.line("/* --trace: `value` at frame[at], 7 bits a byte, low first, the top bit set on all but the");
  w.line("   last byte (docs/live.md); returns where the next number goes. */");
  w.line("static uint16_t {}(unsigned char *frame, uint16_t at, uint32_t value)", c.trace_put_fn);
  {
    auto body = w.block("{");
    w.line("uint32_t rest = value;");
    w.line("uint16_t n = at;");
    {
      auto more = w.block("while (rest >= 0x80u) {");
      w.line("frame[n] = (unsigned char)((rest & 0x7Fu) | 0x80u);");
      w.line("n = (uint16_t)(n + 1u);");
      w.line("rest = rest >> 7;");
    }
    w.line("frame[n] = (unsigned char)rest;");
    w.line("return (uint16_t)(n + 1u);");
  }
  w.blank();
  w.line("/* --trace: the frame of the tick just run (docs/live.md): a full one on the first tick and");
  w.line("   every {} ticks, else the values that changed as (index, value) pairs; then its CRC-32. */",
         c.engine_options.trace_full_every);
  w.line("static void {}({} *{})", c.trace_frame_fn, t, m);
  auto body = w.block("{");
  w.line("unsigned char frame[{}];", size);
  w.line("uint32_t now[{}];", l.values);
  w.line("uint32_t crc = 0xFFFFFFFFu;");
  w.line("uint16_t n = {}u;", trace::kHeaderBytes);
  w.line("uint16_t i;");
  w.line("uint8_t bit;");
  w.line("int place;");
  w.line("bool full;");
  w.line("/* The values: the {}' activation{}, read as {}_activation reads them. */", l.fsm ? "states" : "places",
         l.instances.empty() ? "" : ", then each sub-chart instance's", t);
  w.line("i = 0u;");
  // Read in place rather than through X_activation: the engine calls none of its own API.
  auto read_all = [&](const EngineContext &of, const std::string &obj, std::size_t places, const std::string &what) {
    auto each = w.block(fmt::format("for (place = 0; place < {}; ++place) {{{}", places, what));
    const ActivationRead read = of.form().activation(of, obj);
    {
      auto active = w.block(fmt::format("if ({}) {{", read.test), "} else {");
      w.line("now[i] = {};", read.value);
    }
    {
      auto inactive = w.indented();
      w.line("now[i] = 0u;");
    }
    w.line("}");
    w.line("i = (uint16_t)(i + 1u);");
  };
  read_all(c, "", l.places, "");
  std::size_t k = 0;
  c.each_instance(m + "->", [&](const EngineContext &s, const std::string &member) {
    read_all(s, member, l.instances.at(k).places, fmt::format(" /* {} */", l.instances.at(k).path));
    ++k;
  });
  if (l.fsm) {
    w.line("/* The status: 0 running, 1 succeeded, 2 failed. */");
    w.line("now[{}] = 0u;", l.status);
    {
      auto won = w.block(fmt::format("if ({} > 0) {{", c.field(c.status)));
      w.line("now[{}] = 1u;", l.status);
    }
    auto lost = w.block(fmt::format("if ({} < 0) {{", c.field(c.status)));
    w.line("now[{}] = 2u;", l.status);
  }
  if (l.agent >= 0) {
    w.line("/* The agent number, then by agent the state last reported plus 1 (0: none). */");
    w.line("now[{}] = (uint32_t){};", l.agent, c.field(c.agent));
    auto each = w.block(fmt::format("for (i = 0u; i < {}u; ++i) {{", l.team));
    {
      auto some = w.block(fmt::format("if ({}[i] >= 0) {{", c.field(c.reports)), "} else {");
      w.line("now[{}u + i] = (uint32_t){}[i] + 1u;", l.agent + 1, c.field(c.reports));
    }
    {
      auto none = w.indented();
      w.line("now[{}u + i] = 0u;", l.agent + 1);
    }
    w.line("}");
  }
  w.line("{0} = {0} + 1u;", c.field(c.trace_tick));
  w.line("full = {} == 0u;", c.field(c.trace_left));
  {
    auto reset = w.block("if (full) {", "} else {");
    w.line("{} = {}u;", c.field(c.trace_left), c.engine_options.trace_full_every - 1);
  }
  {
    auto count = w.indented();
    w.line("{0} = (uint16_t)({0} - 1u);", c.field(c.trace_left));
  }
  w.line("}");
  {
    auto each = w.block(fmt::format("for (i = 0u; i < {}u; ++i) {{", l.values));
    {
      auto all = w.block("if (full) {", fmt::format("}} else if (now[i] != {}[i]) {{", c.field(c.trace_prev)));
      w.line("n = {}(frame, n, now[i]);", c.trace_put_fn);
    }
    {
      auto changed = w.indented();
      w.line("n = {}(frame, n, (uint32_t)i);", c.trace_put_fn);
      w.line("n = {}(frame, n, now[i]);", c.trace_put_fn);
    }
    w.line("} else {");
    {
      auto same = w.indented();
      w.line("/* unchanged: not sent */");
    }
    w.line("}");
    w.line("{}[i] = now[i];", c.field(c.trace_prev));
  }
  w.line("/* The header: sync, version, kind, payload length, fingerprint {:08x}, tick. */", l.fingerprint);
  w.line("frame[0] = 0x{:02X}u;", trace::kSync0);
  w.line("frame[1] = 0x{:02X}u;", trace::kSync1);
  w.line("frame[2] = {}u;", trace::kVersion);
  w.line("frame[3] = full ? 1u : 0u;");
  w.line("frame[4] = (unsigned char)((uint16_t)(n - {}u) & 0xFFu);", trace::kHeaderBytes);
  w.line("frame[5] = (unsigned char)((uint16_t)(n - {}u) >> 8);", trace::kHeaderBytes);
  for (int b = 0; b < 4; ++b) w.line("frame[{}] = 0x{:02X}u;", 6 + b, (l.fingerprint >> (8 * b)) & 0xFFu);
  for (int b = 0; b < 4; ++b)
    w.line("frame[{}] = (unsigned char)(({} >> {}) & 0xFFu);", 10 + b, c.field(c.trace_tick), 8 * b);
  w.line("/* CRC-32 (zlib's) of all of it, bit by bit: no table in the engine's memory. */");
  {
    auto each = w.block("for (i = 0u; i < n; ++i) {");
    w.line("crc = crc ^ (uint32_t)frame[i];");
    auto bits = w.block("for (bit = 0u; bit < 8u; ++bit) {");
    {
      auto odd = w.block("if ((crc & 1u) != 0u) {", "} else {");
      w.line("crc = (crc >> 1) ^ 0xEDB88320u;");
    }
    {
      auto even = w.indented();
      w.line("crc = crc >> 1;");
    }
    w.line("}");
  }
  w.line("crc = ~crc;");
  w.line("frame[n] = (unsigned char)(crc & 0xFFu);");
  w.line("frame[n + 1u] = (unsigned char)((crc >> 8) & 0xFFu);");
  w.line("frame[n + 2u] = (unsigned char)((crc >> 16) & 0xFFu);");
  w.line("frame[n + 3u] = (unsigned char)((crc >> 24) & 0xFFu);");
  w.line("n = (uint16_t)(n + 4u);");
  w.line("{}(frame, (unsigned)n);", c.trace_write_fn);
  body.end();
  w.blank();
  w.line("/* One tick (the chart's), then its frame (--trace). */");
  w.line("void {0}({1} *{2})", c.run_fn, t, m);
  auto run = w.block("{");
  w.line("{}({});", c.step_fn, m);
  w.line("{}({});", c.trace_frame_fn, m);
}

}  // namespace gfec::c_backend
