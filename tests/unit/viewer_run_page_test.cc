// `gfec run --html`: the run viewer's page of an interpreter run (docs/viewer.md). The browser
// test (tests/viewer) drives the page; this checks what the page is given.
#include "support.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <filesystem>

using namespace gfec::test;

namespace {

const std::string gfec_exe = std::string(GFEC_BINARY_DIR) + "/gfec";
const std::string samples = std::string(GFEC_SOURCE_DIR) + "/samples";

/// The recording embedded in a page.
nlohmann::json page_data(const std::string &page) {
  const std::string open = "<script type=\"application/json\" id=\"gfec-data\">";
  const std::size_t from = page.find(open);
  REQUIRE(from != std::string::npos);
  const std::size_t to = page.find("</script>", from);
  return nlohmann::json::parse(page.substr(from + open.size(), to - from - open.size()));
}

}  // namespace

TEST_CASE("gfec run --html: the page holds each tick's activation and what the tick did", "[viewer]") {
  std::string dir = scratch_dir("gfec_run_html");
  write_file(dir + "/lf.csv", "tick, Left_IR_Black, Left_IR_White\n1, 0, 1\n2, 1, 0\n3, 1, 0\n");
  const std::string run = gfec_exe + " run " + samples + "/line_follower.sfc --inputs " + dir + "/lf.csv";
  auto plain = run_command(run);
  auto with_page = run_command(run + " --html " + dir + "/run.html");
  REQUIRE(with_page.exit_code == 0);
  CHECK(with_page.out == plain.out);  // the log is the same with or without the page

  const std::string page = read_file(dir + "/run.html");
  CHECK(page.rfind("<!DOCTYPE html>", 0) == 0);
  const nlohmann::json d = page_data(page);
  CHECK(d["tool"] == "gfec run");
  CHECK(d["frames"] == 3);
  CHECK(d["world"].is_null());
  CHECK(d["rows"] == nlohmann::json::parse(R"([
    {"name": "LeftFw", "node": "p0", "terminal": false}, {"name": "LeftStop", "node": "p1", "terminal": false},
    {"name": "RightFw", "node": "p2", "terminal": false}, {"name": "RightStop", "node": "p3", "terminal": false}])"));
  // Tick 1 (frame 0): both sides run; tick 2 the left sensor sees the line, T0 fires; tick 3
  // nothing changes, so the change list has two entries.
  CHECK(d["active"] == nlohmann::json::parse("[[0, [0, 2]], [1, [1, 2]]]"));
  CHECK(d["events"] == nlohmann::json::parse(R"([[1, "fire", "fire T0: LeftFw -> LeftStop"]])"));
  const auto &texts = d["calls"]["texts"];
  const auto &ticks = d["calls"]["ticks"];
  REQUIRE(ticks.size() == 3);
  std::vector<std::string> tick2;
  for (const auto &i : ticks[1][1]) tick2.push_back(texts[i.get<std::size_t>()]);
  CHECK(tick2 ==
        std::vector<std::string>{"cond T0 = true", "  call Left_IR_Black() = true", "fire T0: LeftFw -> LeftStop",
                                 "cond T2 = false", "  call Right_IR_Black() = false", "exit LeftFw", "entry LeftStop",
                                 "action LeftStop", "  call Left_Stop()", "action RightFw", "  call Right_FW()"});
  // With Graphviz the chart's picture, whose nodes the page lights by their dot names.
  if (d["svg"] != "") {
    CHECK(d["svg"].get<std::string>().find("<title>p1</title>") != std::string::npos);
  } else {
    CHECK(d["svg_note"].get<std::string>().rfind("no diagram", 0) == 0);
  }
}

TEST_CASE("gfec run --html: a sub-chart instance gets rows of its own, lit while it runs", "[viewer]") {
  std::string dir = scratch_dir("gfec_run_html_nested");
  write_file(dir + "/nest.fsm", R"(interface R { bool Go(); }
sfc Leaf { initial place L1; place L2; L1 -> L2 when Go(); }
fsm Top { initial state A runs Leaf; state B; A -> B when active(A.L2); B -> A when Go(); }
)");
  write_file(dir + "/go.csv", "tick, Go\n1, 0\n2, 1\n3, 0\n4, 1\n");
  auto r = run_command(gfec_exe + " run " + dir + "/nest.fsm --inputs " + dir + "/go.csv --html " + dir + "/run.html");
  REQUIRE(r.exit_code == 0);
  const nlohmann::json d = page_data(read_file(dir + "/run.html"));
  // The chart's states, then the instance that state A runs, named by its path, drawn in the
  // frame whose nodes the DOT back end prefixes with s0_.
  CHECK(d["rows"] == nlohmann::json::parse(R"([
    {"name": "A", "node": "p0", "terminal": false}, {"name": "B", "node": "p1", "terminal": false},
    {"name": "A/L1", "node": "s0_p0", "terminal": false, "group": "A"},
    {"name": "A/L2", "node": "s0_p1", "terminal": false, "group": "A"}])"));
  CHECK(d["instances"] == nlohmann::json::parse(R"([{"path": "A", "chart": "Leaf", "first": 2, "count": 2}])"));
  // Tick 1: A, its instance's first tick leaves L1 active. Tick 2: Go() moves the instance to L2.
  // Tick 3: active(A.L2) takes Top to B; the stopped instance is not lit. Tick 4: back to A, a
  // fresh instance starts in L1 and, Go() holding, moves to L2 in its first tick.
  CHECK(d["active"] == nlohmann::json::parse("[[0, [0, 2]], [1, [0, 3]], [2, [1]], [3, [0, 3]]]"));
  CHECK(d["title"] == "Top (fsm): running after 4 ticks");  // an instance's state is not the run's
}

TEST_CASE("gfec run --html: the chart's vars with their values per tick, not a sub-chart's", "[viewer]") {
  std::string dir = scratch_dir("gfec_run_html_vars");
  // Leaf has a var of the same name as Top's: its `set n` lines are the instance's, not Top's.
  write_file(dir + "/vars.sfc", R"(interface R { bool Go(); }
const int START = 4;
sfc Leaf { var int n = 100; initial place L { n += 1; } }
sfc Top {
  var int n = START;
  var bool done;
  initial place A runs Leaf { n += 2; }
  place B { entry { done = true; } }
  A -> B when Go();
}
)");
  write_file(dir + "/go.csv", "tick, Go\n1, 0\n2, 0\n3, 1\n4, 0\n");
  auto r = run_command(gfec_exe + " run " + dir + "/vars.sfc --chart Top --inputs " + dir + "/go.csv --html " + dir +
                       "/run.html");
  REQUIRE(r.exit_code == 0);
  const nlohmann::json d = page_data(read_file(dir + "/run.html"));
  // Ticks 1 and 2: A's action adds 2 to Top's n; tick 3: B is entered (done). Leaf's n (101,
  // 102) never shows.
  CHECK(d["vars"] == nlohmann::json::parse(R"([
    {"type": "int", "name": "n", "init": "4", "values": [[0, "6"], [1, "8"]]},
    {"type": "bool", "name": "done", "init": "false", "values": [[2, "true"]]}])"));
  CHECK(d["vars_note"] == "");
}

TEST_CASE("gfec run --html: an unwritable page is an I/O error and nothing is written", "[viewer]") {
  std::string dir = scratch_dir("gfec_run_html_bad");
  auto r = run_command(gfec_exe + " run " + samples + "/cleanup.fsm --ticks 2 --html " + dir + "/missing/run.html");
  CHECK(r.exit_code == 2);
  CHECK(r.out.find("run.html") != std::string::npos);
  CHECK(!std::filesystem::exists(dir + "/missing/run.html"));
}
