#include "c_harness.h"

#include "c_context.h"
#include "c_expr.h"
#include "roots.h"
#include "scenario/snapshot.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <string_view>
#include <utility>

namespace gfec::c_backend {

namespace {

using model::Type;

/// The names the C back end chose for a chart's engine (c_context.h), by whatever name its type goes.
using Names = decltype(make_context(std::declval<const model::Model &>(), std::declval<const model::Chart &>(),
                                    std::declval<const EmitOptions &>()))::element_type;

std::string c_string(std::string_view s) {
  std::string out = "\"";
  for (char c : s) out += c == '"' || c == '\\' ? std::string("\\") + c : std::string(1, c);
  return out + "\"";
}

/// One line of the log as the C statements that print it: text and values, each through the
/// program's output functions (@H@s, @H@u, @H@d, @H@g), so that the output option only changes
/// how those are written.
class Line {
public:
  explicit Line(std::string indent) : indent_(std::move(indent)) {}
  Line &text(const std::string &t) {
    pending_ += t;
    return *this;
  }
  Line &string(const std::string &expr) { return call(fmt::format("@H@s({})", expr)); }
  Line &integer(const std::string &expr) { return call(fmt::format("@H@d((long)({}))", expr)); }
  Line &unsigned_(const std::string &expr) { return call(fmt::format("@H@u((unsigned long)({}))", expr)); }
  Line &real(const std::string &expr, int digits) { return call(fmt::format("@H@g((double)({}), {})", expr, digits)); }
  /// A value of model type `t` as format_value prints it (interp::c_printf_of's formats).
  Line &value(Type t, const std::string &expr) {
    switch (t) {
    case Type::Bool: return string(fmt::format("({}) ? \"true\" : \"false\"", expr));
    case Type::Int: return integer(expr);
    case Type::Float: return real(expr, 9);
    case Type::Double: return real(expr, 17);
    // The sized integers and times through `long` (the host's 64 bits; the run's values are
    // checked against gfec run's, which prints them whole).
    case Type::Time: return text("T#").integer(expr).text("ms");
    default:
      if (model::is_unsigned(t)) return unsigned_(expr);
      if (model::is_integer(t)) return integer(expr);
      return real(expr, 17);
    }
  }
  /// The compact log's `%d` (an int or bool) or `%g` (a float or double).
  Line &compact(Type t, const std::string &expr) {
    return t == Type::Float || t == Type::Double ? real(expr, 6) : integer(expr);
  }
  std::string end(bool newline = true) {
    if (newline) pending_ += "\\n";
    flush();
    return out_;
  }

private:
  Line &call(const std::string &c) {
    flush();
    out_ += indent_ + c + ";\n";
    return *this;
  }
  void flush() {
    if (!pending_.empty()) out_ += indent_ + "@H@s(\"" + pending_ + "\");\n";
    pending_.clear();
  }
  std::string indent_, pending_, out_;
};

/// The engine's state, as glue.c names it.
constexpr std::string_view kEngines = "@H@m";

/// What glue.c calls of harness.c (or, for Putc output, defines itself), declared on top of it.
constexpr std::string_view kOutputCalls = "void @H@s(const char *text);\n"
                                          "void @H@u(unsigned long value);\n"
                                          "void @H@d(long value);\n"
                                          "void @H@g(double value, int digits);\n"
                                          "void @H@flush(void);\n"
                                          "void @H@exit(int status);\n";

/// Output through stdio: one variadic printf over vprintf, which is all harness.c prints with.
constexpr std::string_view kStdioOutput =
    "int @H@printf(const char *format, ...)\n{\n    int n;\n    va_list args;\n"
    "    va_start(args, format);\n    n = vprintf(format, args);\n    va_end(args);\n    return n;\n}\n\n"
    "void @H@s(const char *text)\n{\n    (void)@H@printf(\"%s\", text);\n}\n\n"
    "void @H@u(unsigned long value)\n{\n    (void)@H@printf(\"%lu\", value);\n}\n\n"
    "void @H@d(long value)\n{\n    (void)@H@printf(\"%ld\", value);\n}\n\n"
    "void @H@g(double value, int digits)\n{\n    (void)@H@printf(\"%.*g\", digits, value);\n}\n\n"
    "void @H@flush(void)\n{\n    (void)fflush(stdout);\n}\n\n";

/// With a context: a wrong one ends the program.
constexpr std::string_view kStdioExit = "void @H@exit(int status)\n{\n    exit(status);\n}\n\n";

/// Output through one character function, with printf's formats written out: %g is the exact
/// decimal value rounded half to even to `digits` significant digits (as glibc's printf and
/// format_value print it), so that a target's log equals the interpreter's.
constexpr std::string_view kPutcOutput =
    "void @H@s(const char *text)\n{\n"
    "    while (*text != '\\0') {\n        (void)@P@((unsigned char)*text);\n        ++text;\n    }\n}\n\n"
    "void @H@u(unsigned long value)\n{\n    char digit[24];\n    int n = 0;\n"
    "    do {\n        digit[n++] = (char)('0' + (int)(value % 10u));\n        value /= 10u;\n"
    "    } while (value != 0u);\n"
    "    while (n > 0) {\n        (void)@P@(digit[--n]);\n    }\n}\n\n"
    "void @H@d(long value)\n{\n"
    "    if (value < 0) {\n        (void)@P@('-');\n        @H@u(0ul - (unsigned long)value);\n"
    "    } else {\n        @H@u((unsigned long)value);\n    }\n}\n\n"
    "/* The decimal digits of an integer, least significant first, times `factor` (below 2^28). */\n"
    "static int @H@times(unsigned char *digit, int len, unsigned long factor)\n{\n"
    "    unsigned long carry = 0;\n    int i;\n"
    "    for (i = 0; i < len; ++i) {\n        unsigned long t = digit[i] * factor + carry;\n"
    "        digit[i] = (unsigned char)(t % 10u);\n        carry = t / 10u;\n    }\n"
    "    while (carry != 0u) {\n        digit[len++] = (unsigned char)(carry % 10u);\n        carry /= 10u;\n"
    "    }\n    return len;\n}\n\n"
    "void @H@g(double value, int digits)\n{\n"
    "    /* value = N / 10^k exactly, N's digits least significant first: a binary64 N has at most 800, a\n"
    "       binary32 one (avr-gcc's double) 160, which a part with 2 KB of RAM can spare. */\n"
    "    static unsigned char digit[sizeof value > 4u ? 830 : 160];\n"
    "    const unsigned one = 1u;\n"
    "    const unsigned char *byte = (const unsigned char *)&value;\n"
    "    int len = 0, k = 0, e = 0, cut = 0, x, j;\n"
    "    unsigned long long m;\n"
    "    if ((*(const unsigned char *)&one == 1u ? byte[sizeof value - 1] : byte[0]) & 0x80u) {\n"
    "        (void)@P@('-');\n        value = -value;\n    }\n"
    "    if (value != value) {\n        @H@s(\"nan\");\n        return;\n    }\n"
    "    if (value - value != 0.0) { /* infinite (no constant of DBL_MAX: a double may be binary32) */\n"
    "        @H@s(\"inf\");\n        return;\n    }\n"
    "    if (value == 0.0) {\n        (void)@P@('0');\n        return;\n    }\n"
    "    if (digits < 1) {\n        digits = 1;\n    }\n"
    "    /* value = m * 2^e, m an integer of 53 bits: scaling by 2 is exact. */\n"
    "    while (value >= 9007199254740992.0) {\n        value /= 2.0;\n        ++e;\n    }\n"
    "    while (value < 4503599627370496.0) {\n        value *= 2.0;\n        --e;\n    }\n"
    "    m = (unsigned long long)value;\n"
    "    while (m != 0u) {\n        digit[len++] = (unsigned char)(m % 10u);\n        m /= 10u;\n    }\n"
    "    for (; e > 0; e -= e > 27 ? 27 : e) {\n"
    "        len = @H@times(digit, len, 1ul << (e > 27 ? 27 : e));\n    }\n"
    "    for (; e < 0; e += e < -12 ? 12 : -e) {\n"
    "        int n = e < -12 ? 12 : -e;\n        unsigned long five = 1;\n"
    "        k += n;\n        while (n-- > 0) {\n            five *= 5u;\n        }\n"
    "        len = @H@times(digit, len, five);\n    }\n"
    "    /* Rounded to `digits` significant digits, half to even: digit[cut] is the last one kept. */\n"
    "    if (len > digits) {\n"
    "        int i, up, rest = 0;\n        cut = len - digits;\n"
    "        for (i = 0; i < cut - 1; ++i) {\n            rest = rest || digit[i] != 0;\n        }\n"
    "        up = digit[cut - 1] > 5 || (digit[cut - 1] == 5 && (rest || digit[cut] % 2 != 0));\n"
    "        for (i = cut; up && i < len; ++i) {\n"
    "            digit[i] = (unsigned char)((digit[i] + 1) % 10);\n            up = digit[i] == 0;\n        }\n"
    "        if (up) {\n            digit[len++] = 1;\n            ++cut;\n        }\n    }\n"
    "    while (cut < len - 1 && digit[cut] == 0) {\n        ++cut;\n    }\n"
    "    x = len - 1 - k; /* the exponent of the first digit */\n"
    "    if (x < -4 || x >= digits) {\n"
    "        (void)@P@((char)('0' + digit[len - 1]));\n"
    "        if (cut < len - 1) {\n            (void)@P@('.');\n        }\n"
    "        for (j = len - 2; j >= cut; --j) {\n            (void)@P@((char)('0' + digit[j]));\n        }\n"
    "        (void)@P@('e');\n        (void)@P@(x < 0 ? '-' : '+');\n"
    "        if (x < 0) {\n            x = -x;\n        }\n"
    "        if (x < 10) {\n            (void)@P@('0');\n        }\n"
    "        @H@u((unsigned long)x);\n        return;\n    }\n"
    "    for (j = x > 0 ? x : 0; j >= (cut - k < 0 ? cut - k : 0); --j) {\n"
    "        int i = j + k;\n"
    "        if (j == -1) {\n            (void)@P@('.');\n        }\n"
    "        (void)@P@((char)('0' + (i >= cut && i < len ? digit[i] : 0)));\n    }\n}\n\n"
    "void @H@flush(void)\n{\n}\n\n";

/// Where a sensing function's value comes from, as a C expression of its result type.
std::string input_of(const HarnessOptions &o, const model::Function &f, model::FunctionId id) {
  const std::string t = c_type(f.result);
  switch (o.inputs) {
  case HarnessInputs::Steps:
    switch (f.result) {
    case Type::Bool: return fmt::format("@H@bool(@H@agent, {}) != 0", id.index());
    case Type::Int: return fmt::format("@H@int(@H@agent, {})", id.index());
    case Type::Float: return fmt::format("@H@float(@H@agent, {})", id.index());
    default: return fmt::format("@H@double(@H@agent, {})", id.index());
    }
  case HarnessInputs::Script: return fmt::format("({})@H@value({})", t, c_string(f.name));
  case HarnessInputs::Table: return fmt::format("@H@in{}[@H@agent][@H@tick_count - 1]", id.index());
  }
  return "0";
}

/// A value of the table as a C constant of its type, exactly (float and double round-trip).
std::string c_constant(const interp::Value &v, Type t) {
  char buffer[64];
  switch (t) {
  case Type::Bool: return v.b ? "1" : "0";
  case Type::Int: return v.i == INT32_MIN ? "(-2147483647 - 1)" : std::to_string(v.i);
  case Type::Float: std::snprintf(buffer, sizeof buffer, "%.9g", v.f); break;
  case Type::Double: std::snprintf(buffer, sizeof buffer, "%.17g", v.f); break;
  default:
    if (model::is_integer(t) || t == Type::Time) {
      if (t == Type::UInt64) return fmt::format("UINT64_C({})", static_cast<std::uint64_t>(v.i));
      if (v.i == INT64_MIN) return "(-INT64_C(9223372036854775807) - 1)";
      return v.i < -2147483647 || v.i > 2147483647 ? fmt::format("INT64_C({})", v.i) : std::to_string(v.i);
    }
    std::snprintf(buffer, sizeof buffer, "%.17g", v.f);
    break;
  }
  // A floating constant, whatever its value: `-0` would be the int 0, `7f` no constant at all.
  std::string text = buffer;
  if (text.find_first_of(".e") == std::string::npos) text += ".0";
  return t == Type::Float ? text + "f" : text;
}

/// The table of every sensing function, `[agent][tick - 1]`.
std::string input_tables(const model::Model &m, const std::vector<model::FunctionId> &functions,
                         const HarnessOptions &o) {
  std::string s = "/* What each sensing function returns, by agent and tick. */\n";
  const std::uint64_t ticks = std::max<std::uint64_t>(o.table.ticks, 1);
  for (model::FunctionId id : functions) {
    const model::Function &f = m.functions[id];
    if (f.result == Type::Void) continue;
    std::string rows;
    for (int a = 0; a < o.agents; ++a) {
      std::string row;
      for (std::uint64_t t = 1; t <= ticks; ++t) {
        const bool given = t <= o.table.ticks && o.table.value;
        row +=
            (t > 1 ? ", " : "") + c_constant(given ? o.table.value(id, t, a) : interp::Value::zero(f.result), f.result);
      }
      rows += fmt::format("{}{{{}}}", a ? ", " : "", row);
    }
    s +=
        fmt::format("static const {} @H@in{}[{}][{}] = {{{}}};\n", c_type(f.result), id.index(), o.agents, ticks, rows);
  }
  return s + "\n";
}

/// One interface function: it logs its call and returns its input.
void interface_function(std::string &s, const model::Model &m, model::FunctionId id, const HarnessOptions &o) {
  const model::Function &f = m.functions[id];
  const bool compact = o.log == HarnessLog::Compact;
  std::string params;
  for (std::size_t i = 0; i < f.params.size(); ++i)
    params += fmt::format("{}{} a{}", i ? ", " : "", c_type(f.params[i].type), i);
  if (o.context) params = "void *ctx" + (params.empty() ? "" : ", " + params);
  s += fmt::format("{} {}({})\n{{\n", c_type(f.result), f.name, params.empty() ? "void" : params);
  if (o.context)
    s += "    if (ctx != (const void *)&@H@device[@H@agent]) {\n        @H@s(\"wrong context\\n\");\n"
         "        @H@exit(3);\n    }\n";
  const bool senses = f.result != Type::Void;
  if (senses) s += fmt::format("    const {} v = {};\n", c_type(f.result), input_of(o, f, id));
  // `call F(args)`: every call in the records and the observable log; the compact log's
  // `act F(args)` for an action, `call F(args)` for a sensing function with arguments.
  if (!compact || !senses || !f.params.empty()) {
    Line line("    ");
    line.text(fmt::format("{} {}", compact && !senses ? "act" : "call", f.name));
    if (!compact || !f.params.empty()) line.text("(");
    for (std::size_t i = 0; i < f.params.size(); ++i) {
      if (i) line.text(", ");
      if (compact) line.compact(f.params[i].type, fmt::format("a{}", i));
      else line.value(f.params[i].type, fmt::format("a{}", i));
    }
    if (!compact || !f.params.empty()) line.text(")");
    if (o.log == HarnessLog::Observable && senses) line.text(" = ").value(f.result, "v");
    s += line.end();
  }
  if (compact && senses) s += Line("    ").text(fmt::format("cond {} -> ", f.name)).compact(f.result, "v").end();
  if (senses) s += "    return v;\n";
  s += "}\n\n";
}

/// The name of each of a chart's places, by number.
std::string place_names(const std::string &array, const model::Chart &c) {
  std::string s = fmt::format("static const char *const {}[] = {{", array);
  for (const auto &p : c.places) s += c_string(p.name) + ", ";
  return s + "\"\"};\n";
}

/// The observation hooks (-DX_HOOKS), logged as the interpreter's hooks layer or the compact log.
std::string hooks(const model::Chart &c, const std::string &t, const HarnessOptions &o) {
  const std::string lead = o.log == HarnessLog::Compact ? "hook " : "";
  std::string s = fmt::format("#ifdef {}_HOOKS\nstatic const char *const @H@transition_names[] = {{", t);
  for (const auto &tr : c.transitions) s += c_string(tr.name) + ", ";
  s += "\"\"};\n\n";
  s += fmt::format("void {0}_activated(const {0} *m, {0}_place place, bool active)\n{{\n    (void)m;\n", t);
  s += Line("    ").text(lead).string("active ? \"gained\" : \"lost\"").text(" ").string("@H@place_names[place]").end();
  s += fmt::format("}}\n\nvoid {0}_enabled(const {0} *m, {0}_transition transition)\n{{\n    (void)m;\n", t);
  s += Line("    ").text(lead + "enabled ").string("@H@transition_names[transition]").end();
  return s + "}\n#endif\n\n";
}

/// The start of `@H@dump` for the records and the observable log: `av` and every place's
/// activation count, one line.
std::string dump_with_counts(const std::string &t) {
  std::string s = fmt::format("static void @H@dump(const {} *m)\n{{\n    int p;\n    @H@s(\"av\");\n", t);
  s += fmt::format("    for (p = 0; p < {}_PLACE_COUNT; ++p) {{\n", t);
  return s + Line("        ").text(" ").unsigned_(t + "_activation(m, p)").end(false) + "    }\n    @H@s(\"\\n\");\n";
}

/// The records of one agent's engine `m` (HarnessLog::Records).
std::string records(const model::Model &model, model::ChartId chart, const Names &fields,
                    const std::vector<scenario::Instance> &instances) {
  const model::Chart &c = model.charts[chart];
  const std::string &t = c.name;
  std::string s = dump_with_counts(t);
  // Each sub-chart instance's activation, numbered as X_instance numbers them.
  for (std::size_t k = 0; k < instances.size(); ++k)
    s +=
        fmt::format("    @H@s(\"inst {}\");\n    for (p = 0; p < {}; ++p) {{\n", k,
                    model.charts[instances[k].chart].places.size()) +
        Line("        ").text(" ").unsigned_(fmt::format("{}(m, {}, p)", fields.instance_activation_fn, k)).end(false) +
        "    }\n    @H@s(\"\\n\");\n";
  if (c.kind == model::Chart::Kind::Fsm)
    s += Line("    ").text("state ").integer(t + "_state(m)").text(" ").integer(t + "_status(m)").end();
  for (model::VarId i : c.vars.ids())
    s += Line("    ").text(fmt::format("var {} ", i.index())).value(c.vars[i].type, "m->" + fields.var_field[i]).end();
  for (model::PlaceId p : c.places.ids())
    if (c.places[p].timed)
      s += Line("    ").text(fmt::format("timer {} ", p.index())).unsigned_("m->" + fields.timer_field[p]).end();
  return s + "}\n\n";
}

/// The observable lines after one agent's tick: `av`, an fsm's `state S running`, and every
/// output variable's `out NAME = VALUE` (docs/iec.md).
std::string observable(const model::Chart &c, const Names &fields) {
  const std::string &t = c.name;
  std::string s = dump_with_counts(t);
  if (c.kind != model::Chart::Kind::Fsm) s += "    (void)@H@place_names; /* the hooks' */\n";
  if (c.kind == model::Chart::Kind::Fsm)
    s +=
        Line("    ")
            .text("state ")
            .string(fmt::format("@H@place_names[{}_state(m)]", t))
            .text(" ")
            .string(fmt::format("{0}_status(m) == 0 ? \"running\" : {0}_status(m) > 0 ? \"succeeded\" : \"failed\"", t))
            .end();
  for (model::VarId i : c.vars.ids())
    if (model::read_by_caller(c.vars[i].role))
      s += Line("    ")
               .text(fmt::format("out {} = ", c.vars[i].name))
               .value(c.vars[i].type, "m->" + fields.var_field[i])
               .end();
  return s + "}\n\n";
}

/// Table inputs of the chart's `in` variables, `[tick - 1]`, with whether the tick sets it.
std::string input_var_tables(const model::Chart &c, const HarnessOptions &o) {
  std::string s;
  const std::uint64_t ticks = std::max<std::uint64_t>(o.table.ticks, 1);
  for (model::VarId id : c.vars.ids()) {
    const model::Var &v = c.vars[id];
    if (!model::set_by_caller(v.role)) continue;
    std::string values, given;
    for (std::uint64_t t = 1; t <= ticks; ++t) {
      std::optional<interp::Value> x;
      if (t <= o.table.ticks && o.table.input) x = o.table.input(v, t);
      values += (t > 1 ? ", " : "") + c_constant(x ? *x : interp::Value::zero(v.type), v.type);
      given += (t > 1 ? ", " : "") + std::string(x ? "1" : "0");
    }
    s += fmt::format("static const {} @H@var{}[{}] = {{{}}};\n", c_type(v.type), id.index(), ticks, values);
    s += fmt::format("static const unsigned char @H@var{}_set[{}] = {{{}}};\n", id.index(), ticks, given);
  }
  return s.empty() ? s
                   : std::string("/* What the caller sets each input variable to, by tick (1: set). */\n") + s + "\n";
}

/// Steps inputs: a `set` input's value in harness.c (steps_main), as a C expression of its type.
std::string step_input(Type t, model::VarId id) {
  const std::size_t i = id.index();
  switch (t) {
  case Type::Bool: return fmt::format("@H@input_ll(a, {}) != 0", i);
  case Type::Float: return fmt::format("@H@input_f(a, {})", i);
  case Type::Double: return fmt::format("@H@input_d(a, {})", i);
  default:
    if (model::is_unsigned(t)) return fmt::format("({})@H@input_ull(a, {})", c_type(t), i);
    return fmt::format("({})@H@input_ll(a, {})", c_type(t), i);
  }
}

/// Before a tick: the caller sets the chart's `in` variables (docs/iec.md "The scan"); with Steps
/// inputs those a test's `set` gave a value, from then on.
std::string set_input_vars(const model::Chart &c, const Names &fields, const HarnessOptions &o) {
  std::string s;
  if (o.inputs == HarnessInputs::Script) return s;
  for (model::VarId id : c.vars.ids()) {
    if (!model::set_by_caller(c.vars[id].role)) continue;
    if (o.inputs == HarnessInputs::Table)
      s += fmt::format("        if (@H@var{0}_set[@H@tick_count - 1] != 0u) {{\n"
                       "            {1}[a].{2} = @H@var{0}[@H@tick_count - 1];\n        }}\n",
                       id.index(), kEngines, fields.var_field[id]);
    else
      s += fmt::format("        if (@H@input_set(a, {0}) != 0) {{\n            {1}[a].{2} = {3};\n        }}\n",
                       id.index(), kEngines, fields.var_field[id], step_input(c.vars[id].type, id));
  }
  return s;
}

/// One past the number of the chart's last `in` variable (at least 1): the size of harness.c's
/// table of the values `set` gave them.
std::size_t inputs_end(const model::Chart &c) {
  std::size_t end = 1;
  for (model::VarId id : c.vars.ids())
    if (model::set_by_caller(c.vars[id].role)) end = std::max(end, id.index() + 1);
  return end;
}

/// The compact log's lines after a tick: the active places by name (an fsm's state and status),
/// and with -DHARNESS_INSTANCES every instance's active places, `in A.M1: L2`.
std::string compact(const model::Model &model, model::ChartId chart, const Names &fields,
                    const std::vector<scenario::Instance> &instances) {
  const model::Chart &c = model.charts[chart];
  const std::string &t = c.name;
  std::string s = fmt::format("static void @H@dump(const {} *m)\n{{\n", t);
  if (c.kind == model::Chart::Kind::Fsm) {
    s += Line("    ")
             .text("state ")
             .string(fmt::format("@H@place_names[{}_state(m)]", t))
             .text(" status ")
             .integer(t + "_status(m)")
             .end();
  } else {
    s += fmt::format("    int p;\n    @H@s(\"av\");\n    for (p = 0; p < {0}_PLACE_COUNT; ++p) {{\n"
                     "        unsigned n = {0}_activation(m, p);\n        if (n == 1) {{\n",
                     t);
    s += Line("            ").text(" ").string("@H@place_names[p]").end(false);
    s += "        }\n        if (n > 1) {\n";
    s += Line("            ").text(" ").string("@H@place_names[p]").text(":").unsigned_("n").end(false);
    s += "        }\n    }\n    @H@s(\"\\n\");\n";
  }
  // Instances by their path from the chart: `Search.Grab`.
  std::vector<std::string> paths;
  for (const scenario::Instance &in : instances) {
    const model::ChartId holder = in.parent < 0 ? chart : instances[static_cast<std::size_t>(in.parent)].chart;
    const std::string name(model.charts[holder].places[in.place].name.view());
    paths.push_back(in.parent < 0 ? name : paths[static_cast<std::size_t>(in.parent)] + "." + name);
  }
  s += "#ifdef HARNESS_INSTANCES\n    {\n        int q;\n";
  for (std::size_t k = 0; k < instances.size(); ++k) {
    s += "        " + place_names(fmt::format("names{}", k), model.charts[instances[k].chart]);
    s += fmt::format("        @H@s(\"in {}:\");\n        for (q = 0; q < {}; ++q) {{\n", paths[k],
                     model.charts[instances[k].chart].places.size());
    s += fmt::format("            if ({}(m, {}, q) != 0u) {{\n", fields.instance_activation_fn, k);
    s += Line("                ").text(" ").string(fmt::format("names{}[q]", k)).end(false);
    s += "            }\n        }\n        @H@s(\"\\n\");\n";
  }
  // Numbers out of range read 0.
  s += fmt::format("        if ({0}(m, -1, 0) + {0}(m, {1}, 0) + {0}(m, 0, -1) + {0}(m, 0, 1000) != 0u) {{\n"
                   "            @H@s(\"out of range: not 0\\n\");\n        }}\n",
                   fields.instance_activation_fn, instances.size());
  s += "        (void)q;\n    }\n#endif\n";
  return s + "}\n\n";
}

/// What harness.c holds for Steps inputs: the values `set` stored, and main reading the steps.
std::string steps_main(int agents, std::size_t functions, std::size_t inputs) {
  // Each record is flushed as it is complete: an engine that dies of a signal in tick n leaves
  // the records before it, so that a message can name the tick.
  return fmt::format(
      "/* By agent and function (its index in the model): what `set` gave it; \"\" is false/0. */\n"
      "static char @H@value[{0}][{1}][64];\n\n"
      "/* By agent and input variable (its number in the chart): what `set` gave it, as a number (a bool\n"
      "   0 or 1, a time in milliseconds); \"\" until set, when the input keeps its value. */\n"
      "static char @H@input[{0}][{2}][64];\n\n"
      "int @H@input_set(int agent, int var)\n{{\n    return @H@input[agent][var][0] != '\\0';\n}}\n\n"
      "long long @H@input_ll(int agent, int var)\n{{\n"
      "    return strtoll(@H@input[agent][var], NULL, 10);\n}}\n\n"
      "unsigned long long @H@input_ull(int agent, int var)\n{{\n"
      "    return strtoull(@H@input[agent][var], NULL, 10);\n}}\n\n"
      "float @H@input_f(int agent, int var)\n{{\n    return strtof(@H@input[agent][var], NULL);\n}}\n\n"
      "double @H@input_d(int agent, int var)\n{{\n    return strtod(@H@input[agent][var], NULL);\n}}\n\n"
      "int @H@bool(int agent, int function)\n{{\n"
      "    return strcmp(@H@value[agent][function], \"true\") == 0;\n}}\n\n"
      "int @H@int(int agent, int function)\n{{\n"
      "    return (int)strtol(@H@value[agent][function], NULL, 10);\n}}\n\n"
      "float @H@float(int agent, int function)\n{{\n"
      "    return strtof(@H@value[agent][function], NULL);\n}}\n\n"
      "double @H@double(int agent, int function)\n{{\n"
      "    return strtod(@H@value[agent][function], NULL);\n}}\n\n"
      "int main(void)\n{{\n    char word[16];\n    @H@init();\n    @H@flush();\n"
      "    while (scanf(\"%15s\", word) == 1) {{\n"
      "        if (strcmp(word, \"tick\") == 0) {{\n            @H@tick();\n            @H@flush();\n"
      "        }} else if (strcmp(word, \"set\") == 0) {{\n"
      "            int who;\n            int f;\n            int a;\n            char v[64];\n"
      "            if (scanf(\"%d %d %63s\", &who, &f, v) != 3 || who < -1 || who >= {0} || f < 0 || f >= {1}) {{\n"
      "                return 2;\n            }}\n"
      "            for (a = 0; a < {0}; ++a) {{\n"
      "                if (who < 0 || who == a) {{\n"
      "                    strcpy(@H@value[a][f], v);\n                }}\n            }}\n"
      "        }} else if (strcmp(word, \"input\") == 0) {{\n"
      "            int who;\n            int i;\n            int a;\n            char v[64];\n"
      "            if (scanf(\"%d %d %63s\", &who, &i, v) != 3 || who < -1 || who >= {0} || i < 0 || i >= {2}) {{\n"
      "                return 2;\n            }}\n"
      "            for (a = 0; a < {0}; ++a) {{\n"
      "                if (who < 0 || who == a) {{\n"
      "                    strcpy(@H@input[a][i], v);\n                }}\n            }}\n"
      "        }}\n    }}\n    return 0;\n}}\n",
      agents, functions, inputs);
}

/// What harness.c holds for Script inputs: this tick's line, and main reading one a tick.
constexpr std::string_view kScriptMain =
    "static char @H@script[1024]; /* this tick's line */\n\n"
    "double @H@value(const char *name)\n{\n"
    "    size_t n = strlen(name);\n"
    "    const char *p = @H@script;\n"
    "    while ((p = strstr(p, name)) != NULL) {\n"
    "        int starts = p == @H@script || p[-1] == ' ';\n"
    "        if (starts && (p[n] == '=')) return atof(p + n + 1);\n"
    "        if (starts && (p[n] == ' ' || p[n] == '\\n' || p[n] == '\\0')) return 1;\n"
    "        p += n;\n"
    "    }\n"
    "    return 0;\n}\n\n"
    "int main(void)\n{\n"
    "    setvbuf(stdout, NULL, _IONBF, 0); /* the log survives a failed assert */\n"
    "    @H@init();\n"
    "    while (fgets(@H@script, sizeof @H@script, stdin) != NULL) {\n        @H@tick();\n    }\n"
    "    return 0;\n}\n";

/// Replaces @H@ (the harness's prefix) and @P@ (the character function) everywhere.
void substitute(std::string &text, const std::string &marker, const std::string &by) {
  for (std::size_t at = text.find(marker); at != std::string::npos; at = text.find(marker, at + by.size()))
    text.replace(at, marker.size(), by);
}

}  // namespace

std::vector<model::FunctionId> engine_functions(const model::Model &model, model::ChartId root) {
  const IdMap<model::ChartId, bool> tree = charts_in_tree(model, root);
  IdMap<model::FunctionId, bool> used(model.functions.size());
  for (model::ChartId c : tree.ids())
    if (tree[c])
      for (model::FunctionId f : model.charts[c].functions) used[f] = true;
  std::vector<model::FunctionId> out;
  for (model::FunctionId f : used.ids())
    if (used[f]) out.push_back(f);
  return out;
}

std::vector<std::string> harness_library_names(const HarnessOptions &o) {
  if (o.output == HarnessOutput::Putc) return {"main", o.putc};
  std::vector<std::string> names = {"main", "vprintf", "fflush"};
  if (o.context) names.push_back("exit");
  if (o.inputs == HarnessInputs::Steps)
    for (const char *n : {"scanf", "strcmp", "strcpy", "strtol", "strtoll", "strtoull", "strtof", "strtod"})
      names.push_back(n);
  if (o.inputs == HarnessInputs::Script)
    for (const char *n : {"setvbuf", "fgets", "strlen", "strstr", "atof"}) names.push_back(n);
  return names;
}

HarnessSources write_harness(const model::Model &model, model::ChartId chart, const EmitOptions &emit,
                             const HarnessOptions &o) {
  const model::Chart &c = model.charts.at(chart);
  const int n = std::max(o.agents, 1);
  if (o.output == HarnessOutput::Putc && (o.inputs != HarnessInputs::Table || o.context))
    throw std::invalid_argument("a harness without the C library takes its inputs from a table and has no context");
  if (o.inputs == HarnessInputs::Script && n > 1) throw std::invalid_argument("a script answers one agent");
  // A team machine's engines get their agent numbers and exchange states; the compact log's
  // single engine is driven as any chart's (its tests set the reports themselves, if at all).
  const bool team = c.team > 0 && o.log != HarnessLog::Compact;
  if (n > 1 && !team) throw std::invalid_argument("several agents run a team machine only");
  // The engine's field and function names as the C back end chose them for this chart.
  const auto fields = make_context(model, c, emit);
  const std::string &t = c.name;
  const std::vector<model::FunctionId> functions = engine_functions(model, chart);
  const std::vector<scenario::Instance> instances = scenario::instances_of(model, chart);
  const bool putc = o.output == HarnessOutput::Putc;

  std::string g = fmt::format("/* Generated by gfec: the interface of {} as a test sets it, and its engines, run tick\n"
                              "   by tick with a log of what they do (backends/c/c_harness.h). */\n"
                              "#include \"{}\"\n\n",
                              t, o.header);
  g += "/* The log's output. */\n" + std::string(kOutputCalls);
  if (putc) g += fmt::format("int {}(int c);\n", o.putc);
  if (o.inputs == HarnessInputs::Steps)
    g += "/* harness.c: the values `set` gave each agent's sensing functions. */\n"
         "int @H@bool(int agent, int function);\nint @H@int(int agent, int function);\n"
         "float @H@float(int agent, int function);\ndouble @H@double(int agent, int function);\n"
         "/* harness.c: whether `set` gave an agent's input variable a value, and the value. */\n"
         "int @H@input_set(int agent, int var);\nlong long @H@input_ll(int agent, int var);\n"
         "unsigned long long @H@input_ull(int agent, int var);\nfloat @H@input_f(int agent, int var);\n"
         "double @H@input_d(int agent, int var);\n";
  if (o.inputs == HarnessInputs::Script)
    g += "/* harness.c: the value this tick's line gives a name. */\n"
         "double @H@value(const char *name);\n";
  if (o.inputs != HarnessInputs::Table) g += "void @H@init(void);\nvoid @H@tick(void);\n";
  g += fmt::format("\n/* The engines, one per agent, and the agent whose engine runs: its calls read its values. */\n"
                   "static {} {}[{}];\nstatic int @H@agent;\nstatic unsigned long @H@tick_count;\n",
                   t, kEngines, n);
  if (o.context) g += fmt::format("static int @H@device[{}]; /* the engines' contexts */\n", n);
  g += "\n";
  if (o.inputs == HarnessInputs::Table) g += input_tables(model, functions, o) + input_var_tables(c, o);
  // The unused-warnings of the places' names (not every log prints them) are kept quiet by the
  // hooks and the dumps that do.
  const bool names = o.log != HarnessLog::Records;
  if (names) g += place_names("@H@place_names", c) + "\n";
  for (model::FunctionId f : functions) interface_function(g, model, f, o);
  if (o.log != HarnessLog::Records) g += hooks(c, t, o);
  switch (o.log) {
  case HarnessLog::Records: g += records(model, chart, *fields, instances); break;
  case HarnessLog::Observable: g += observable(c, *fields); break;
  case HarnessLog::Compact: g += compact(model, chart, *fields, instances); break;
  }
  const bool after_init = o.log == HarnessLog::Records;
  // Records: every agent's state, then the end of the record; else each agent's after its tick.
  if (after_init) {
    g += fmt::format("static void @H@dump_all(void)\n{{\n    int a;\n    for (a = 0; a < {}; ++a) {{\n", n);
    if (team) g += Line("        ").text("agent ").integer("a").end();
    g += fmt::format("        @H@dump(&{}[a]);\n    }}\n    @H@s(\"end\\n\");\n}}\n\n", kEngines);
  }
  g += fmt::format("{}void @H@init(void)\n{{\n    int a;\n    for (a = 0; a < {}; ++a) {{\n        {}(&{}[a]);\n",
                   o.inputs == HarnessInputs::Table ? "static " : "", n, fields->init_fn, kEngines);
  if (team) g += fmt::format("        {}(&{}[a], a);\n", fields->set_agent_fn, kEngines);
  if (o.context) g += fmt::format("        {}(&{}[a], &@H@device[a]);\n", fields->set_context_fn, kEngines);
  g += "    }\n";
  if (after_init) g += "    @H@dump_all();\n";
  g += "}\n\n";
  g += fmt::format("{}void @H@tick(void)\n{{\n    int a;\n    ++@H@tick_count;\n",
                   o.inputs == HarnessInputs::Table ? "static " : "");
  g += o.log == HarnessLog::Records ? "    @H@s(\"tick\\n\");\n"
                                    : Line("    ").text("tick ").unsigned_("@H@tick_count").end();
  g += fmt::format("    for (a = 0; a < {}; ++a) {{\n", n);
  if (team) g += Line("        ").text("agent ").integer("a").end();
  g += set_input_vars(c, *fields, o);
  g += fmt::format("        @H@agent = a;\n        {}(&{}[a]);\n", fields->run_fn, kEngines);
  if (!after_init) g += fmt::format("        @H@dump(&{}[a]);\n", kEngines);
  g += "    }\n";
  if (team)
    g += fmt::format("    /* The reference exchange (docs/language.md \"Teams\"): every agent's state to every "
                     "other. */\n"
                     "    for (a = 0; a < {0}; ++a) {{\n        int b;\n"
                     "        for (b = 0; b < {0}; ++b) {{\n"
                     "            {1}(&{3}[b], a, (int){2}_state(&{3}[a]));\n        }}\n    }}\n",
                     n, fields->report_fn, t, kEngines);
  if (after_init) g += "    @H@dump_all();\n";
  g += "}\n";
  if (o.inputs == HarnessInputs::Table)
    g += fmt::format("\nint main(void)\n{{\n    @H@init();\n    @H@flush();\n"
                     "    while (@H@tick_count < {}ul) {{\n        @H@tick();\n        @H@flush();\n    }}\n"
                     "    return 0;\n}}\n",
                     o.table.ticks);
  if (putc) g += "\n/* The log's output, through " + o.putc + ". */\n" + std::string(kPutcOutput);

  // harness.c: the C library's side, which never sees the engine's header.
  std::string h;
  if (!putc) {
    h = "/* Generated by gfec: the C library's side of the harness in glue.c (backends/c/c_harness.h):\n"
        "   output, and the inputs. */\n"
        "#include <stdarg.h>\n#include <stdio.h>\n#include <stdlib.h>\n#include <string.h>\n\n" +
        std::string(kOutputCalls) + "void @H@init(void);\nvoid @H@tick(void);\n\n" + std::string(kStdioOutput);
    if (o.context) h += kStdioExit;
    if (o.inputs == HarnessInputs::Steps) h += steps_main(n, model.functions.size() + 1, inputs_end(c));
    if (o.inputs == HarnessInputs::Script) h += kScriptMain;
  }
  // The harness's own names: a prefix that begins no name of the interface.
  std::string prefix = "gfec_h_";
  for (bool clash = true; clash;) {
    clash = false;
    for (model::FunctionId f : functions) clash = clash || model.functions[f].name.rfind(prefix, 0) == 0;
    if (clash) prefix.insert(prefix.size() - 1, "_");
  }
  for (std::string *text : {&g, &h}) {
    substitute(*text, "@H@", prefix);
    substitute(*text, "@P@", o.putc);
  }
  return {std::move(g), std::move(h)};
}

}  // namespace gfec::c_backend
