// The CSV input trace of `gfec run`: columns name functions, rows are ticks.
#include "interpreter/input_trace.h"
#include "interpreter_support.h"

using namespace gfec;
using test::compile;

namespace {

const char *kIface = "interface Bot { bool Black(); int Count(); float Dist(); double Exact(); void Go(); }";
const char *kChart = "sfc S { initial place A { Go(); } }";

struct Trace {
  std::unique_ptr<test::Compiled> c = compile(kChart, kIface);
  SourceManager sources;
  Diagnostics diag;
  std::unique_ptr<interp::InputTrace> trace;

  explicit Trace(const std::string &csv) {
    FileId id = sources.add("trace.csv", csv);
    trace = std::make_unique<interp::InputTrace>(c->model, sources, id, diag);
  }
  std::string errors() const {
    std::string out;
    for (const auto &d : diag.all()) out += render_text(d, sources);
    return out;
  }
  std::string at(const std::string &fn, std::uint64_t tick) const {
    return interp::format_value(trace->value(c->function(fn), tick));
  }
};

}  // namespace

TEST_CASE("input trace: a column per function, a row per tick") {
  Trace t("# a comment\n\ntick, Black, Dist ,Exact, Count\n1, 1, 0.25, 0.1, -3\n2,false,1e-1,2,4\n");
  CHECK(t.errors() == "");
  CHECK(t.trace->rows() == 2);
  CHECK(t.at("Black", 1) == "true");
  CHECK(t.at("Black", 2) == "false");
  CHECK(t.at("Dist", 1) == "0.25");
  CHECK(t.at("Dist", 2) == "0.100000001");  // read as a float
  CHECK(t.at("Exact", 1) == "0.10000000000000001");
  CHECK(t.at("Count", 1) == "-3");
  // Past the last row the last row holds; a function without a column returns 0.
  CHECK(t.at("Count", 9) == "4");
  Trace none("Black\n");
  CHECK(none.at("Black", 1) == "false");
  CHECK(none.at("Count", 1) == "0");
}

TEST_CASE("input trace: errors are located in the CSV file") {
  Trace t("Black, Nope, Go\n1, 2, 3\nyes, 1, 1\n1, 2\n");
  CHECK(t.errors() == "trace.csv:1:8: error: no interface function 'Nope' for this column [trace]\n"
                      " Black, Nope, Go\n"
                      "        ^~~~\n"
                      "trace.csv:1:14: error: 'Go' returns nothing, so it takes no input [trace]\n"
                      " Black, Nope, Go\n"
                      "              ^~\n"
                      "trace.csv:3:1: error: 'yes' is not a value of type 'bool' for 'Black' [trace]\n"
                      " yes, 1, 1\n"
                      " ^~~\n"
                      "trace.csv:4:1: error: 2 values where the header names 3 columns [trace]\n"
                      " 1, 2\n"
                      " ^~~~\n");
}

TEST_CASE("input trace: a tick column makes a sparse trace, a row holding until the next row's tick") {
  Trace t("tick, Black, Count\n3, 1, 7\n250, 0, 8\n251, 1, 9\n");
  CHECK(t.errors() == "");
  CHECK(t.trace->rows() == 3);
  CHECK(t.trace->last_tick() == 251);
  CHECK(t.at("Black", 1) == "false");  // before the first row's tick: 0
  CHECK(t.at("Count", 2) == "0");
  CHECK(t.at("Count", 3) == "7");
  CHECK(t.at("Count", 249) == "7");
  CHECK(t.at("Count", 250) == "8");
  CHECK(t.at("Black", 250) == "false");
  CHECK(t.at("Count", 251) == "9");
  CHECK(t.at("Count", 9000) == "9");  // past the last row it holds
  Trace plain("Count\n5\n6\n");
  CHECK(plain.trace->last_tick() == 2);
}

TEST_CASE("input trace: ticks that do not go up from 1 are located errors, a misspelt column gets a suggestion") {
  Trace t("tick, Black\n2, 1\n2, 0\n1, 0\n0, 1\n");
  CHECK(t.errors() ==
        "trace.csv:3:1: error: tick 2 is not after the previous row's tick 2: the rows go up in tick order [trace]\n"
        " 2, 0\n"
        " ^\n"
        "trace.csv:3:1: note: a row holds from its tick until the next row's; a tick without a row keeps the row "
        "before\n"
        "trace.csv:4:1: error: tick 1 is not after the previous row's tick 2: the rows go up in tick order [trace]\n"
        " 1, 0\n"
        " ^\n"
        "trace.csv:4:1: note: a row holds from its tick until the next row's; a tick without a row keeps the row "
        "before\n"
        "trace.csv:5:1: error: tick 0 in the tick column: ticks count from 1 [trace]\n"
        " 0, 1\n"
        " ^\n");
  Trace misspelt("tick, black, Cuont, Tick\n");
  CHECK(misspelt.errors() == "trace.csv:1:7: error: no interface function 'black' for this column [trace]\n"
                             " tick, black, Cuont, Tick\n"
                             "       ^~~~~\n"
                             "trace.csv:1:7: note: did you mean 'Black'?\n"
                             "trace.csv:1:14: error: no interface function 'Cuont' for this column [trace]\n"
                             " tick, black, Cuont, Tick\n"
                             "              ^~~~~\n"
                             "trace.csv:1:14: note: did you mean 'Count'?\n"
                             "trace.csv:1:21: error: no interface function 'Tick' for this column [trace]\n"
                             " tick, black, Cuont, Tick\n"
                             "                     ^~~~\n"
                             "trace.csv:1:21: note: did you mean 'tick'?\n");
}

TEST_CASE("input trace: a column per input variable of the chart (docs/language.md §14)", "[iec]") {
  auto c = compile("sfc S { in int Level = 7; in bool Start; out bool On; initial place A { On = Start; } }", kIface);
  REQUIRE(!c->diag.has_errors());
  SourceManager sources;
  Diagnostics diag;
  FileId id = sources.add("trace.csv", "tick, Level, Black\n2, 40, 1\n5, x, 0\n");
  interp::InputTrace trace(c->model, sources, id, diag);
  std::string errors;
  for (const auto &d : diag.all()) errors += render_text(d, sources);
  CHECK(errors == "trace.csv:3:4: error: 'x' is not a value of type 'int' for 'Level' [trace]\n"
                  " 5, x, 0\n"
                  "    ^\n");
  const model::Chart &chart = c->model.charts[model::ChartId(0)];
  const model::Var &level = chart.vars[model::VarId(0)];
  // Before the first row's tick the input keeps its value (none given); then the row's holds.
  CHECK(!trace.input(level, 1));
  REQUIRE(trace.input(level, 2));
  CHECK(interp::format_value(*trace.input(level, 4)) == "40");
  // An input without a column is never set.
  CHECK(!trace.input(chart.vars[model::VarId(1)], 3));
}
