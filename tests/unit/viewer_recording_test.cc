// The run viewer's recording builder (viewer/recording.h) and the picture's node ids
// (support/chart_nodes.h) that its rows point at. `gfec run --html` and carbot-sim build their
// recordings with it; viewer_run_page_test.cc and tests/viewer check those pages.
#include "chart_nodes.h"
#include "recording.h"

#include <catch2/catch.hpp>

using nlohmann::json;

TEST_CASE("chart node ids: an instance's nodes carry its place's prefix, level by level", "[viewer]") {
  using namespace gfec::chart_nodes;
  CHECK(place("", 3) == "p3");
  CHECK(transition("", 2) == "t2");
  CHECK(join("", 1) == "join1");
  CHECK(fork("", 1) == "fork1");
  const std::string inner = instance_prefix(instance_prefix("", 0), 2);
  CHECK(inner == "s0_s2_");
  CHECK(place(inner, 1) == "s0_s2_p1");
  CHECK(transition(inner, 0) == "s0_s2_t0");
  CHECK(instance_frame("s0_", 2) == "cluster_s0_s2");
  CHECK(actor(1) == "a1");
  CHECK(supervisor(1, 0) == "s1_0");
  CHECK(global_supervisor(0) == "g0");
  CHECK(constraint(2) == "c2");
}

TEST_CASE("outline rows: the chart's places, then each instance's, depth first", "[viewer]") {
  // Main: A runs Sub, B, C runs Sub too; Sub: X runs Leaf, Y (terminal); Leaf: L.
  gfec::viewer::ChartOutline o;
  o.charts = {{"Main", {{"A", false, 1}, {"B", false, -1}, {"C", false, 1}}},
              {"Sub", {{"X", false, 2}, {"Y", true, -1}}},
              {"Leaf", {{"L", false, -1}}}};
  std::vector<gfec::viewer::Row> rows;
  std::vector<gfec::viewer::Instance> instances;
  gfec::viewer::outline_rows(o, rows, instances);
  std::vector<std::string> names, nodes, groups;
  for (const auto &r : rows) {
    names.push_back(r.name);
    nodes.push_back(r.node);
    groups.push_back(r.group);
  }
  CHECK(names == std::vector<std::string>{"A", "B", "C", "A/X", "A/Y", "A.X/L", "C/X", "C/Y", "C.X/L"});
  CHECK(nodes ==
        std::vector<std::string>{"p0", "p1", "p2", "s0_p0", "s0_p1", "s0_s0_p0", "s2_p0", "s2_p1", "s2_s0_p0"});
  CHECK(groups == std::vector<std::string>{"", "", "", "A", "A", "A.X", "C", "C", "C.X"});
  CHECK(rows[4].terminal);
  CHECK_FALSE(rows[3].terminal);
  REQUIRE(instances.size() == 4);
  CHECK(instances[0].path == "A");
  CHECK(instances[0].chart == "Sub");
  CHECK(instances[0].first == 3);
  CHECK(instances[0].count == 2);
  CHECK(instances[0].parent_row == 0);
  CHECK(instances[1].path == "A.X");
  CHECK(instances[1].parent_row == 3);
  CHECK(instances[3].path == "C.X");
  CHECK(instances[3].first == 8);
  CHECK(instances[3].parent_row == 6);
}

TEST_CASE("recording builder: ticks appended one at a time, the data readable at any tick", "[viewer]") {
  gfec::viewer::RecordingBuilder rec("test", "Main", "sfc", "main.sfc", 0.01);
  rec.add_row({"A", "p0", false, "", -1});
  rec.add_row({"B", "p1", true, "", -1});
  rec.set_picture("", "no diagram: none");
  rec.record_status(0, "running");
  rec.record_calls(0, {"call F() = true"});
  rec.add_tick({0});
  // A live monitor's page after one tick.
  json now = rec.data();
  CHECK(now["frames"] == 1);
  CHECK(now["active"] == json::parse("[[0, [0]]]"));
  CHECK(now["svg_note"] == "no diagram: none");

  rec.record_calls(1, {"call F() = true"});
  rec.add_tick({0});  // unchanged: no entry
  rec.record_calls(2, {"call G()", "call F() = true"});
  rec.add_tick({1});
  rec.record_status(2, "succeeded");
  rec.add_event(2, "status", "succeeded");
  rec.add_event(1, "fire", "fire T0");  // added late, listed in frame order
  rec.set_title("Main: succeeded", "test");
  const json d = rec.data();
  CHECK(d["format"] == 1);
  CHECK(d["tool"] == "test");
  CHECK(d["chart"] == json::parse(R"({"name": "Main", "kind": "sfc", "file": "main.sfc"})"));
  CHECK(d["frames"] == 3);
  CHECK(d["title"] == "Main: succeeded");
  CHECK(d["rows"] == json::parse(R"([{"name": "A", "node": "p0", "terminal": false},
                                     {"name": "B", "node": "p1", "terminal": true}])"));
  CHECK(d["active"] == json::parse("[[0, [0]], [2, [1]]]"));
  CHECK(d["calls"]["texts"] == json::parse(R"j(["call F() = true", "call G()"])j"));
  CHECK(d["calls"]["ticks"] == json::parse("[[0, [0]], [2, [1, 0]]]"));
  CHECK(d["status"] == json::parse(R"([[0, "running"], [2, "succeeded"]])"));
  CHECK(d["events"] == json::parse(R"([[1, "fire", "fire T0"], [2, "status", "succeeded"]])"));
  CHECK(d["world"].is_null());
  CHECK_FALSE(d.contains("robots"));
}

TEST_CASE("recording builder: several robots keep their own calls and status", "[viewer]") {
  gfec::viewer::RecordingBuilder rec("test", "Team", "fsm", "team.fsm", 0.05);
  for (int i = 0; i < 2; ++i) {
    const std::string name = "robot " + std::to_string(i);
    rec.add_row({name + "/Go", "p0", false, name, i});
    CHECK(rec.add_robot(name, i ? "#00f" : "#f00", static_cast<std::size_t>(i), 1) == static_cast<std::size_t>(i));
    rec.record_status(static_cast<std::size_t>(i), 0, "running");
  }
  rec.record_calls(1, 0, {"call Go()"});
  rec.set_robot(1, "pose", json::object({{"x", json::array()}}));
  rec.record_status(1, 0, "failed");
  rec.add_tick({0, 1});
  rec.set("world", json::object({{"name", "room"}}));
  const json d = rec.data();
  CHECK(d["calls"].is_null());  // each robot's, under robots
  REQUIRE(d["robots"].size() == 2);
  CHECK(d["robots"][1]["name"] == "robot 1");
  CHECK(d["robots"][1]["first"] == 1);
  CHECK(d["robots"][1]["calls"]["texts"] == json::parse(R"j(["call Go()"])j"));
  CHECK(d["robots"][1]["status"] == json::parse(R"([[0, "running"], [0, "failed"]])"));
  CHECK(d["robots"][1]["pose"].contains("x"));
  CHECK(d["robots"][0]["calls"]["ticks"].empty());
  CHECK(d["rows"][1] == json::parse(R"({"name": "robot 1/Go", "node": "p0", "terminal": false, "group": "robot 1",
                                        "robot": 1})"));
  CHECK(d["world"]["name"] == "room");
}
