#include "c_driver.h"

#include "interpreter/value.h"

#include <fmt/format.h>

namespace gfec::diff {

namespace {

std::string c_string(const std::string &s) {
  std::string out = "\"";
  for (char c : s) out += c == '"' || c == '\\' ? std::string("\\") + c : std::string(1, c);
  return out + "\"";
}

void function(std::string &s, const DriverCase &c, std::size_t index) {
  const GFunction &f = c.chart->functions[index];
  std::string params, format, args;
  for (std::size_t i = 0; i < f.params.size(); ++i) {
    params += fmt::format("{}{} a{}", i ? ", " : "", model::type_name(f.params[i]), i);
    auto [fmt_, arg] = interp::c_printf_of(f.params[i], fmt::format("a{}", i));
    format += (i ? ", " : "") + fmt_;
    args += ", " + arg;
  }
  if (params.empty()) params = "void";
  if (f.result == Type::Void) {
    s +=
        fmt::format("void {}({})\n{{\n    printf(\"call {}({})\\n\"{});\n}}\n\n", f.name, params, f.name, format, args);
    return;
  }
  auto list = [](const std::vector<std::string> &values) {
    std::string out;
    for (const auto &v : values) out += (out.empty() ? "" : ", ") + v;
    return out;
  };
  const bool team = c.chart->agents > 0;
  if (team) {  // [agent][tick]: an agent without values of its own has agent 0's
    std::string rows;
    for (int k = 0; k < c.chart->agents; ++k) {
      const auto &own = k == 0 ? c.trace->values[index] : c.trace->agents[static_cast<std::size_t>(k - 1)][index];
      rows += fmt::format("{}{{{}}}", k ? ", " : "", list(own.empty() ? c.trace->values[index] : own));
    }
    s += fmt::format("const {} d{}_{}[{}][{}] = {{{}}};\n", model::type_name(f.result), c.id, f.name, c.chart->agents,
                     c.trace->ticks, rows);
  } else {
    s += fmt::format("const {} d{}_{}[{}] = {{{}}};\n", model::type_name(f.result), c.id, f.name, c.trace->ticks,
                     list(c.trace->values[index]));
  }
  auto [rfmt, rarg] = interp::c_printf_of(f.result, "v");
  s += fmt::format(
      "{} {}({})\n{{\n    {} v = d{}_{}{}[d_tick];\n    printf(\"call {}({}) = {}\\n\"{}, {});\n    return v;\n}}\n\n",
      model::type_name(f.result), f.name, params, model::type_name(f.result), c.id, f.name, team ? "[d_agent]" : "",
      f.name, format, rfmt, args, rarg);
}

void names(std::string &s, const std::string &array, const std::vector<std::string> &list) {
  std::string items;
  for (const auto &n : list) items += (items.empty() ? "" : ", ") + c_string(n);
  if (items.empty()) items = "\"\"";
  s += fmt::format("const char *const {}[] = {{{}}};\n", array, items);
}

/// One tick of engine `e` (a C expression of type X *) and its observable lines: `av ...`, and
/// for an fsm `state S status`; `indent` spaces before each line of C.
void tick_and_log(std::string &s, const DriverCase &c, const std::string &e, int indent) {
  const std::string &t = c.chart->name;
  const std::string in(static_cast<std::size_t>(indent), ' ');
  s += fmt::format("{0}{1}_run({2});\n{0}printf(\"av\");\n{0}for (p = 0; p < {1}_PLACE_COUNT; ++p) {{\n"
                   "{0}    printf(\" %u\", {1}_activation({2}, p));\n{0}}}\n{0}printf(\"\\n\");\n",
                   in, t, e);
  if (c.chart->fsm)
    s += fmt::format("{0}printf(\"state %s %s\\n\", d{1}_places[{2}_state({3})], {2}_status({3}) == 0 ? \"running\" : "
                     "{2}_status({3}) > 0 ? \"succeeded\" : \"failed\");\n",
                     in, c.id, t, e);
}

/// A team machine: one engine per agent in lockstep; each tick every agent ticks in agent order,
/// then every agent's state is reported to every other (the reference exchange, docs/language.md
/// "Teams"); the log as the interpreter's team run writes it.
void team_run(std::string &s, const DriverCase &c) {
  const std::string &t = c.chart->name;
  s += fmt::format("static void d{0}_run(void)\n{{\n    {1} e[{2}];\n    int p, k, j;\n"
                   "    for (k = 0; k < {2}; ++k) {{\n        {1}_init(&e[k]);\n        {1}_set_agent(&e[k], k);\n"
                   "    }}\n    printf(\"case {0}\\n\");\n",
                   c.id, t, c.chart->agents);
  s += fmt::format(
      "    for (d_tick = 0; d_tick < {}; ++d_tick) {{\n        printf(\"tick %d\\n\", d_tick + 1);\n"
      "        for (k = 0; k < {}; ++k) {{\n            d_agent = k;\n            printf(\"agent %d\\n\", k);\n",
      c.trace->ticks, c.chart->agents);
  tick_and_log(s, c, "&e[k]", 12);
  s +=
      fmt::format("        }}\n        for (j = 0; j < {0}; ++j) {{\n            for (k = 0; k < {0}; ++k) {{\n"
                  "                {1}_report(&e[k], j, {1}_state(&e[j]));\n            }}\n        }}\n    }}\n}}\n\n",
                  c.chart->agents, t);
}

void one_case(std::string &s, const DriverCase &c) {
  const std::string &t = c.chart->name;
  s += fmt::format("/* ---- case {}: {} {} */\n\n", c.id, c.chart->fsm ? "fsm" : "sfc", t);
  for (std::size_t f = 0; f < c.chart->functions.size(); ++f) function(s, c, f);
  names(s, fmt::format("d{}_places", c.id), c.places);
  names(s, fmt::format("d{}_transitions", c.id), c.transitions);
  s += fmt::format("\n#ifdef {0}_HOOKS\n"
                   "void {0}_activated(const {0} *m, {0}_place place, bool active)\n{{\n"
                   "    (void)m;\n    printf(\"%s %s\\n\", active ? \"gained\" : \"lost\", d{1}_places[place]);\n}}\n\n"
                   "void {0}_enabled(const {0} *m, {0}_transition transition)\n{{\n"
                   "    (void)m;\n    printf(\"enabled %s\\n\", d{1}_transitions[transition]);\n}}\n"
                   "#endif\n\n",
                   t, c.id);
  if (c.chart->agents > 0) {
    team_run(s, c);
    return;
  }
  s += fmt::format(
      "static void d{}_run(void)\n{{\n    {} e;\n    int p;\n    {}_init(&e);\n    printf(\"case {}\\n\");\n", c.id, t,
      t, c.id);
  s += fmt::format("    for (d_tick = 0; d_tick < {}; ++d_tick) {{\n", c.trace->ticks);
  s += "        printf(\"tick %d\\n\", d_tick + 1);\n";
  tick_and_log(s, c, "&e", 8);
  s += "    }\n}\n\n";
}

}  // namespace

std::string driver_source(const std::vector<DriverCase> &cases) {
  std::string s = "/* Generated by gfec's differential harness (tests/differential): the interface functions\n"
                  "   of each case from its trace, and a loop that runs its engine and logs every tick. */\n"
                  "#include <stdbool.h>\n#include <stdio.h>\n\n";
  for (const auto &c : cases) s += fmt::format("#include \"{}\"\n", c.header);
  s += "\nstatic int d_tick; /* the current tick, from 0 */\n";
  for (const auto &c : cases)
    if (c.chart->agents > 0) {
      s += "static int d_agent; /* a team run: whose engine runs */\n";
      break;
    }
  s += "\n";
  for (const auto &c : cases) one_case(s, c);
  s += "int main(void)\n{\n";
  for (const auto &c : cases) s += fmt::format("    d{}_run();\n", c.id);
  s += "    return 0;\n}\n";
  return s;
}

}  // namespace gfec::diff
