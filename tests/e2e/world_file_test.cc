// World files: every shipped world loads; a bad one is refused with a message that names
// the file and the field, and carbot-sim exits 1 (bad input) or 2 (no such file).
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "core/world.h"
#include "support.h"

namespace {

std::string error_of(const std::string &text) {
  try {
    carbot::parse_world(text, "w.json");
  } catch (const carbot::WorldError &e) { return e.what(); }
  return "(accepted)";
}

const char *kStart = R"("start": {"pose": [0, 0, 0]})";

}  // namespace

TEST_CASE("world files: every shipped world loads", "[e2e][world]") {
  int count = 0;
  for (const auto &entry : std::filesystem::directory_iterator(e2e::source("sim/worlds"))) {
    if (entry.path().extension() != ".json") continue;
    INFO(entry.path());
    CHECK_NOTHROW(carbot::load_world(entry.path().string()));
    ++count;
  }
  CHECK(count >= 6);
}

TEST_CASE("world files: a shipped world reads as written", "[e2e][world]") {
  const carbot::World w = e2e::world("sim/worlds/cleanup_drop.json");
  CHECK(w.name == "cleanup_drop");
  CHECK(w.walls.size() == 4);
  REQUIRE(w.items.size() == 1);
  CHECK(w.items[0].name == "cup");
  CHECK(w.items[0].destination.x == Approx(-1.3));
  REQUIRE(w.events.size() == 1);
  CHECK(w.events[0].kind == carbot::Event::Kind::DropItem);
  CHECK(w.events[0].has_to);
}

TEST_CASE("world files: errors name the field", "[e2e][world]") {
  CHECK(error_of(std::string(R"({"size": [2, 2], "line": {"points": [[0,0], [1,0], [1,1], [2]]}, )") + kStart + "}") ==
        "w.json: line.points[3]: expected [x, y]");
  CHECK(error_of(R"({"size": [2, 2]})") == "w.json: start: missing");
  CHECK(error_of(std::string(R"({"size": [2, -1], )") + kStart + "}") == "w.json: size: expected positive [w, h]");
  CHECK(error_of(std::string(R"({"size": [2, 2], "wals": [], )") + kStart + "}") ==
        "w.json: wals: unknown field (expected one of: description, size, line, walls, boxes, items, start, events)");
  CHECK(error_of(std::string(R"({"size": [2, 2], "walls": [{"from": [0, 0], "to": "east"}], )") + kStart + "}") ==
        "w.json: walls[0].to: expected [x, y]");
  CHECK(error_of(std::string(R"({"size": [2, 2], "boxes": [{"center": [0, 0], "size": [0.5, 0]}], )") + kStart + "}") ==
        "w.json: boxes[0].size: expected positive [w, d]");
  CHECK(error_of(std::string(R"({"size": [2, 2], "events": [{"at": 3, "drop": "mug"}], )") + kStart + "}") ==
        "w.json: events[0].drop: no item named 'mug' in \"items\"");
  CHECK(error_of(std::string(R"({"size": [2, 2], "events": [{"at": 3, "press": "reset"}], )") + kStart + "}") ==
        "w.json: events[0].press: expected \"escape\" (the only button)");
  CHECK(error_of(R"({"size": [2, 2], "start": {"pose": [0, 0]}})") ==
        "w.json: start.pose: expected [x, y, heading_deg]");
  CHECK(error_of("{\n  \"size\": [2, 2],\n  oops\n}").rfind("w.json:3:3: not valid JSON: syntax error", 0) == 0);
}

TEST_CASE("world files: carbot-sim refuses a bad world before building anything", "[e2e][world]") {
  e2e::TempDir dir;
  const std::string bad = dir.file("bad.json");
  std::ofstream(bad)
      << R"({"size": [2, 2], "line": {"points": [[0,0], [1,0], [1,1], [2]]}, "start": {"pose": [0,0,0]}})";
  const e2e::SimRun run = e2e::run_sim("samples/line_follower.sfc", bad, 1);
  CHECK(run.exit_code == 1);
  CHECK(run.output.find("bad.json: line.points[3]: expected [x, y]") != std::string::npos);
  CHECK(run.trace.empty());

  const e2e::SimRun missing = e2e::run_sim("samples/line_follower.sfc", dir.file("nowhere.json"), 1);
  CHECK(missing.exit_code == 2);
  CHECK(missing.output.find("no such world file") != std::string::npos);
}

// docs/security.md: every number of a world is finite and in range, every key given once.
TEST_CASE("world files: absurd numbers and duplicate keys are refused, naming the field", "[e2e][world]") {
  // 1e309 is past a double: nlohmann reports it as out_of_range, which once escaped (abort).
  CHECK(error_of(R"({"size": [2, 2], "start": {"pose": [1e309, 0, 0]}})") ==
        "w.json: not a usable JSON document: number overflow parsing '1e309'");
  // A heading of 1e308 degrees tripped an ODE assertion.
  CHECK(error_of(R"({"size": [2, 2], "start": {"pose": [0, 0, 1e308]}})") ==
        "w.json: start.pose[2]: expected a number between -1e+06 and 1e+06, got 1e+308");
  CHECK(error_of(std::string(R"({"size": [2, 2], "walls": [{"from": [0, 0], "to": [1, 0], "height": 1e7}], )") +
                 kStart + "}") == "w.json: walls[0].height: expected a number between -1e+06 and 1e+06, got 1e+07");
  CHECK(error_of(std::string(R"({"size": [2, 2], "size": [3, 3], )") + kStart + "}") ==
        "w.json: size: the key is given twice in one object");
  CHECK(error_of(R"({"size": [2, 2], "start": {"pose": [0, 0, 0], "pose": [1, 1, 0]}})") ==
        "w.json: pose: the key is given twice in one object");
  CHECK(error_of(std::string(R"({"size": [1e6, 2], )") + kStart + "}") == "(accepted)");
}
