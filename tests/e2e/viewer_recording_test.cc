// The run viewer's recording (docs/viewer.md): carbot-sim --record / --html on the samples.
// A recording build must drive the robot exactly as the plain build; what it records must
// agree with the chart's semantics (an active place's action runs in its tick) and with the
// trace's `active` column; the page must be one self-contained file.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include <catch2/catch.hpp>

#include "support.h"

namespace {

using nlohmann::json;

std::string slurp(const std::string &path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// The value of a change list ([[tick, value], ...]) at `tick`.
json value_at(const json &list, long tick, const json &fallback) {
  json v = fallback;
  for (const json &entry : list) {
    if (entry[0].get<long>() > tick) break;
    v = entry[1];
  }
  return v;
}

/// The trace's `active` column, row by row.
std::vector<std::string> active_column(const std::string &trace_text) {
  std::vector<std::string> out;
  std::istringstream in(trace_text);
  std::string line;
  std::getline(in, line);
  REQUIRE(line == "t,x,y,heading,active");
  while (std::getline(in, line)) out.push_back(line.substr(line.rfind(',') + 1));
  return out;
}

struct Recorded {
  e2e::SimRun run;
  json rec;
  std::string page;
};

Recorded record(const std::string &chart, const std::string &world, double seconds, const std::string &extra = "") {
  e2e::TempDir dir;
  Recorded r;
  r.run = e2e::run_sim(chart, world, seconds,
                       "--record '" + dir.file("rec.json") + "' --html '" + dir.file("run.html") + "' " + extra);
  if (r.run.exit_code == 0) {
    r.rec = json::parse(slurp(dir.file("rec.json")));
    r.page = slurp(dir.file("run.html"));
  }
  return r;
}

}  // namespace

TEST_CASE("viewer: a recording build drives the robot exactly as the plain build", "[e2e][viewer]") {
  for (const auto &[chart, world] : {std::pair{"samples/line_follower.sfc", "sim/worlds/oval.json"},
                                     std::pair{"samples/cleanup.fsm", "sim/worlds/cleanup_drop.json"}}) {
    const e2e::SimRun plain = e2e::run_sim(chart, world, 30);
    const Recorded recorded = record(chart, world, 30);
    REQUIRE(plain.exit_code == 0);
    REQUIRE(recorded.run.exit_code == 0);
    CHECK(recorded.run.trace_text == plain.trace_text);
    CHECK(recorded.run.result["status"] == plain.result["status"]);
  }
}

TEST_CASE("viewer: the line follower's recording: places, calls, actions of active places", "[e2e][viewer]") {
  const Recorded r = record("samples/line_follower.sfc", "sim/worlds/oval.json", 20);
  REQUIRE(r.run.exit_code == 0);
  const json &rec = r.rec;
  CHECK(rec["chart"]["kind"] == "sfc");
  std::vector<std::string> rows;
  for (const json &row : rec["rows"]) rows.push_back(row["name"]);
  CHECK(rows == std::vector<std::string>{"LeftFw", "LeftStop", "RightFw", "RightStop"});
  CHECK(rec["rows"][1]["node"] == "p1");
  const long frames = rec["frames"];
  REQUIRE(frames == static_cast<long>(r.run.trace.size()));
  CHECK(frames == 2001);

  const std::vector<std::string> column = active_column(r.run.trace_text);
  REQUIRE(static_cast<long>(column.size()) == frames);
  // Started astride the line: both sides run.
  CHECK(column[0] == "LeftFw RightFw");
  const json &texts = rec["calls"]["texts"];
  std::set<std::string> changes;
  long stops = 0;
  for (long k = 0; k + 1 < frames; ++k) {
    // The recording's activation is the trace's column.
    std::string names;
    for (const json &i : value_at(rec["active"], k, json::array()))
      names += (names.empty() ? "" : " ") + rows[i.get<std::size_t>()];
    REQUIRE(names == column[static_cast<std::size_t>(k)]);
    // Each tick the action of every active place runs (after the conditions): LeftFw calls
    // Left_FW(), LeftStop calls Left_Stop(), and so on; and only those actions.
    std::set<std::string> actions, sensed;
    for (const json &i : value_at(rec["calls"]["ticks"], k, json::array())) {
      const std::string text = texts[i.get<std::size_t>()];
      if (text.find(" = ") == std::string::npos) actions.insert(text);
      else sensed.insert(text.substr(0, text.find(" = ")));
    }
    std::set<std::string> expected;
    for (const json &i : value_at(rec["active"], k, json::array())) {
      const std::string &p = rows[i.get<std::size_t>()];
      expected.insert(p == "LeftFw"     ? "Left_FW()"
                      : p == "LeftStop" ? "Left_Stop()"
                      : p == "RightFw"  ? "Right_FW()"
                                        : "Right_Stop()");
      if (p == "LeftStop") ++stops;
    }
    REQUIRE(actions == expected);
    REQUIRE(!sensed.empty());  // the conditions of the transitions leaving active places
  }
  CHECK(stops > 0);  // it did steer within 20 s
  // Stored as changes: far fewer entries than ticks.
  CHECK(rec["calls"]["ticks"].size() < static_cast<std::size_t>(frames / 4));
}

TEST_CASE("viewer: the clean-up's recording follows its states and the cup", "[e2e][viewer]") {
  const Recorded r = record("samples/cleanup.fsm", "sim/worlds/cleanup_drop.json", 60);
  REQUIRE(r.run.exit_code == 0);
  REQUIRE(r.run.result["status"] == "succeeded");
  const std::vector<std::string> column = active_column(r.run.trace_text);
  std::vector<std::string> visited;
  for (const std::string &s : column)
    if (visited.empty() || visited.back() != s) visited.push_back(s);
  CHECK(visited == std::vector<std::string>{"Z0", "Z1", "Z2", "Z1", "Z2", "Z3", "Done"});
  std::vector<std::string> item_events;
  bool succeeded_last = false;
  for (const json &e : r.rec["events"]) {
    if (e[1] == "item") item_events.push_back(e[2]);
    if (e[1] == "status" && e[2] == "succeeded") succeeded_last = e[0] == r.rec["frames"].get<long>() - 1;
  }
  CHECK(item_events == std::vector<std::string>{"cup picked up", "cup released", "cup picked up", "cup released"});
  CHECK(succeeded_last);
  CHECK(r.rec["rows"][4]["name"] == "Done");
  CHECK(r.rec["rows"][4]["terminal"] == true);
  CHECK(r.rec["rows"][0]["terminal"] == false);
}

TEST_CASE("viewer: the mission's recording lights each sub-chart instance from the compiled engine",
          "[e2e][viewer][mission]") {
  const Recorded r = record("samples/mission.fsm", "sim/worlds/mission.json", 60);
  REQUIRE(r.run.exit_code == 0);
  REQUIRE(r.run.result["status"] == "succeeded");
  // Reading the instances changes nothing: the trace is the plain build's, byte for byte.
  CHECK(r.run.trace_text == e2e::run_sim("samples/mission.fsm", "sim/worlds/mission.json", 60).trace_text);
  const json &rec = r.rec;
  std::vector<std::string> rows, nodes;
  for (const json &row : rec["rows"]) {
    rows.push_back(row["name"]);
    nodes.push_back(row["node"]);
  }
  CHECK(rows == std::vector<std::string>{"Patrol", "Tidy", "Done", "GaveUp", "Patrol/LeftFw", "Patrol/LeftStop",
                                         "Patrol/RightFw", "Patrol/RightStop", "Tidy/Z0", "Tidy/Z1", "Tidy/Z2",
                                         "Tidy/Z3", "Tidy/Done", "Tidy/Failed"});
  // The nodes of the frames gfec's picture draws: place 0 runs the frame s0_, place 1 s1_.
  CHECK(nodes[4] == "s0_p0");
  CHECK(nodes[13] == "s1_p5");
  CHECK(rec["instances"] == json::parse(R"([{"path": "Patrol", "chart": "LineFollower", "first": 4, "count": 4},
                                            {"path": "Tidy", "chart": "CleanUp", "first": 8, "count": 6}])"));

  // What each place's action calls (line_follower.sfc, cleanup.fsm); Mission's states call nothing.
  const std::map<std::string, std::string> action = {
      {"Patrol/LeftFw", "Left_FW()"},       {"Patrol/LeftStop", "Left_Stop()"}, {"Patrol/RightFw", "Right_FW()"},
      {"Patrol/RightStop", "Right_Stop()"}, {"Tidy/Z0", "DriveToItem()"},       {"Tidy/Z1", "PickUp()"},
      {"Tidy/Z2", "Transport()"},           {"Tidy/Z3", "PlaceItem()"}};
  const std::vector<std::string> column = active_column(r.run.trace_text);
  const long frames = rec["frames"];
  std::vector<std::string> tidy_states;
  long patrol_ends = -1;
  std::set<std::string> previous;
  for (long k = 0; k + 1 < frames; ++k) {
    std::set<std::string> on;
    for (const json &i : value_at(rec["active"], k, json::array())) on.insert(rows[i.get<std::size_t>()]);
    // The chart's own state is the trace's column.
    REQUIRE(on.count(column[static_cast<std::size_t>(k)]) == 1);
    // An instance is lit only while the state that runs it is current; a running LineFollower
    // has one place of each side active, a running CleanUp exactly one state.
    auto lit = [&](std::initializer_list<const char *> names) {
      return std::count_if(names.begin(), names.end(), [&](const char *n) { return on.count(n) > 0; });
    };
    const long patrol = lit({"Patrol/LeftFw", "Patrol/LeftStop", "Patrol/RightFw", "Patrol/RightStop"});
    const long tidy = lit({"Tidy/Z0", "Tidy/Z1", "Tidy/Z2", "Tidy/Z3", "Tidy/Done", "Tidy/Failed"});
    REQUIRE(patrol == (on.count("Patrol") ? 2 : 0));
    REQUIRE(lit({"Patrol/LeftFw", "Patrol/LeftStop"}) == patrol / 2);
    REQUIRE(tidy == (on.count("Tidy") ? 1 : 0));
    for (const auto &[place, call] : action)
      if (place.rfind("Tidy/", 0) == 0 && on.count(place) && (tidy_states.empty() || tidy_states.back() != place))
        tidy_states.push_back(place);
    if (on.count("Tidy/Done") && tidy_states.back() != "Tidy/Done") tidy_states.push_back("Tidy/Done");
    // The tick's actions are those of the lit places: the recorded activation and the recorded
    // calls, both from the engine, agree.
    std::set<std::string> actions, expected;
    for (const json &i : value_at(rec["calls"]["ticks"], k, json::array())) {
      const std::string text = rec["calls"]["texts"][i.get<std::size_t>()];
      if (text.find(" = ") == std::string::npos) actions.insert(text);
    }
    for (const std::string &p : on)
      if (action.count(p)) expected.insert(action.at(p));
    INFO("tick " << k);
    REQUIRE(actions == expected);
    // Mission leaves Patrol when both sides of the line follower drive: read at the start of the
    // tick, so the tick before shows LeftFw and RightFw lit.
    if (on.count("Tidy") && previous.count("Patrol")) {
      patrol_ends = k;
      CHECK(previous.count("Patrol/LeftFw") == 1);
      CHECK(previous.count("Patrol/RightFw") == 1);
    }
    previous = on;
  }
  CHECK(patrol_ends >= 1999);
  CHECK(tidy_states == std::vector<std::string>{"Tidy/Z0", "Tidy/Z1", "Tidy/Z2", "Tidy/Z3", "Tidy/Done"});
}

TEST_CASE("viewer: instances two levels deep, one of them a sequential sfc, are read from the engine",
          "[e2e][viewer]") {
  // Top's place T runs the fsm Mid, whose state M runs Ring: 70 places in a ring, each stepping
  // on every tick. Over 64 places with one active, the C engine holds Ring as a sequential sfc
  // (`current`, docs/c-engine.md), Mid as an fsm (`state`).
  e2e::TempDir dir;
  std::string ring = "import \"" + e2e::source("samples/linebot.iface") + "\";\nsfc Ring {\n";
  for (int i = 0; i < 70; ++i) ring += std::string(i == 0 ? "  initial" : " ") + " place P" + std::to_string(i) + ";\n";
  for (int i = 0; i < 70; ++i) ring += "  P" + std::to_string(i) + " -> P" + std::to_string((i + 1) % 70) + ";\n";
  ring +=
      "}\nfsm Mid { initial state M runs Ring; state N; M -> N when Left_IR_Black(); N -> M when Left_IR_White(); }\n"
      "sfc Top { period 10ms; initial place T runs Mid; }\n";
  {
    std::ofstream out(dir.file("ring.sfc"));
    out << ring;
  }
  const Recorded r = record(dir.file("ring.sfc"), "sim/worlds/oval.json", 2);
  INFO(r.run.output);
  REQUIRE(r.run.exit_code == 0);
  const json &rows = r.rec["rows"];
  REQUIRE(rows.size() == 1 + 2 + 70);
  CHECK(rows[1] == json::parse(R"({"name": "T/M", "node": "s0_p0", "terminal": false, "group": "T"})"));
  CHECK(rows[3 + 69] == json::parse(R"({"name": "T.M/P69", "node": "s0_s0_p69", "terminal": false, "group": "T.M"})"));
  CHECK(r.rec["instances"] == json::parse(R"([{"path": "T", "chart": "Mid", "first": 1, "count": 2},
                                              {"path": "T.M", "chart": "Ring", "first": 3, "count": 70}])"));
  // Top never moves the robot, so Mid stays in M; Ring's first tick enters P0 and steps to P1,
  // each further tick one place on: after tick k + 1 (frame k) P((k + 1) mod 70) is active.
  for (long k = 0; k + 1 < r.rec["frames"].get<long>(); ++k) {
    INFO("frame " << k);
    REQUIRE(value_at(r.rec["active"], k, json::array()) == json::array({0, 1, 3 + (k + 1) % 70}));
  }
}

TEST_CASE("viewer: the wall-follow plan's recording names actors and the supervisor that fired",
          "[e2e][viewer][plan]") {
  const Recorded r = record("samples/wall_follow.plan", "sim/worlds/room.json", 20);
  if (e2e::skipped_for_missing_backend(r.run)) return;
  REQUIRE(r.run.exit_code == 0);
  const std::vector<std::string> column = active_column(r.run.trace_text);
  CHECK(column[0] == "searchFirstWall");
  REQUIRE(!r.rec["fired"].empty());
  const json &first = r.rec["fired"][0];
  CHECK(first[1] == "s0_0");  // the first supervisor of the first actor in gfec's picture
  CHECK(first[2] == "touch (searchFirstWall)");
  // The robot bumps the crate after about 1.6 s, then backs up.
  const long at = first[0];
  CHECK(at > 100);
  CHECK(at < 250);
  CHECK(column[static_cast<std::size_t>(at + 1)] == "backupCollision");
}

TEST_CASE("viewer: the square plan's recording has rows for the actors of its sub-plan", "[e2e][viewer][plan]") {
  const Recorded r = record("samples/square.plan", "sim/worlds/cleanup.json", 60);
  if (e2e::skipped_for_missing_backend(r.run)) return;
  REQUIRE(r.run.exit_code == 0);
  REQUIRE(r.run.result["status"] == "succeeded");
  std::vector<std::string> rows;
  for (const json &row : r.rec["rows"]) rows.push_back(row["name"]);
  // Square's actors, then those of Side (square_side.plan) as the actor `side` ran them.
  CHECK(rows == std::vector<std::string>{"side", "count", "backOff", "side/forward", "side/turn"});
  CHECK(r.rec["rows"][3]["group"] == "side");
  CHECK(r.rec["rows"][3]["node"] == "");  // gfec's picture of Square does not draw Side's insides
  CHECK(r.rec["instances"] == json::parse(R"([{"path": "side", "chart": "Side", "first": 3, "count": 2}])"));
  // Side drives forward then turns; then CountDown counts the side: four sides on the open floor.
  // `side` stays lit while its sub-plan runs, in the page and in the trace.
  std::vector<std::string> seen, column_seen;
  for (long k = 0; k < r.rec["frames"].get<long>(); ++k) {
    std::string names;
    for (const json &i : value_at(r.rec["active"], k, json::array()))
      names += (names.empty() ? "" : " ") + rows[i.get<std::size_t>()];
    if (seen.empty() || seen.back() != names) seen.push_back(names);
  }
  for (const std::string &c : active_column(r.run.trace_text))
    if (column_seen.empty() || column_seen.back() != c) column_seen.push_back(c);
  std::vector<std::string> expected, expected_column;
  for (int side = 0; side < 4; ++side) {
    expected.insert(expected.end(), {"side side/forward", "side side/turn", "count"});
    expected_column.insert(expected_column.end(), {"side", "count"});
  }
  CHECK(seen == expected);
  CHECK(column_seen == expected_column);
}

TEST_CASE("viewer: the page is one self-contained file", "[e2e][viewer]") {
  const Recorded r = record("samples/cleanup.fsm", "sim/worlds/cleanup.json", 5);
  REQUIRE(r.run.exit_code == 0);
  const std::string &page = r.page;
  CHECK(page.rfind("<!DOCTYPE html>", 0) == 0);
  // Nothing is loaded from anywhere: no src or href attributes, no stylesheet links.
  CHECK(page.find(" src=") == std::string::npos);
  CHECK(page.find(" href=") == std::string::npos);
  CHECK(page.find("<link") == std::string::npos);
  // The data sits in one JSON script element that nothing in the run can close early.
  const std::string open = "<script type=\"application/json\" id=\"gfec-data\">";
  const std::size_t from = page.find(open);
  REQUIRE(from != std::string::npos);
  const std::size_t to = page.find("</script>", from);
  const json data = json::parse(page.substr(from + open.size(), to - from - open.size()));
  CHECK(data["chart"]["name"] == "CleanUp");
  CHECK(data["svg"].get<std::string>().find("<svg") != std::string::npos);
  CHECK(data == r.rec);
}

TEST_CASE("viewer: a team run's recording: each robot's rows, path, calls and the items", "[e2e][viewer][team]") {
  // Three robots on fetch_room for 8 s: robot 0 picks the cup up and carries it, the others yield.
  const Recorded r = record("samples/fetch_team.fsm", "sim/worlds/fetch_room.json", 8);
  REQUIRE(r.run.exit_code == 0);
  const json &rec = r.rec;
  const json &result = r.run.result;
  const long frames = rec["frames"].get<long>();
  const double period = rec["period"].get<double>();
  REQUIRE(result["robot_count"] == 3);
  REQUIRE(rec["robots"].size() == 3);
  CHECK(rec["pose"].is_null());

  // The team trace, read here (not through the recording): per robot, per row, the active
  // column and the position.
  std::vector<std::vector<std::string>> column(3);
  std::vector<std::vector<std::pair<double, double>>> where(3);
  {
    std::istringstream in(r.run.trace_text);
    std::string line;
    std::getline(in, line);
    REQUIRE(line == "t,robot,x,y,heading,active");
    while (std::getline(in, line)) {
      std::istringstream cells(line);
      std::string t, robot, x, y, h, active;
      std::getline(cells, t, ',');
      std::getline(cells, robot, ',');
      std::getline(cells, x, ',');
      std::getline(cells, y, ',');
      std::getline(cells, h, ',');
      std::getline(cells, active);
      const int i = std::stoi(robot);
      REQUIRE(i >= 0);
      REQUIRE(i < 3);
      column[i].push_back(active);
      where[i].emplace_back(std::stod(x), std::stod(y));
    }
  }
  const std::size_t states = rec["rows"].size() / 3;
  REQUIRE(states == 6);  // Go, Grab, Carry, Yield, Done, Left
  for (int i = 0; i < 3; ++i) {
    const json &robot = rec["robots"][i];
    const std::string name = "robot " + std::to_string(i);
    INFO(name);
    REQUIRE(column[i].size() == static_cast<std::size_t>(frames));
    CHECK(robot["name"] == name);
    CHECK(robot["first"].get<std::size_t>() == i * states);
    CHECK(robot["count"].get<std::size_t>() == states);
    for (std::size_t j = 0; j < states; ++j) {
      const json &row = rec["rows"][i * states + j];
      CHECK(row["group"] == name);
      CHECK(row["robot"] == i);
      CHECK(row["name"].get<std::string>().rfind(name + "/", 0) == 0);
    }
    // Every tick: robot i's active rows are the state its trace column names, and no other robot's
    // row is counted for it.
    std::vector<double> px, py;
    double ax = 0, ay = 0;
    const double scale = robot["pose"]["scale"].get<double>();
    for (std::size_t k = 0; k < robot["pose"]["x"].size(); ++k) {
      ax += robot["pose"]["x"][k].get<double>();
      ay += robot["pose"]["y"][k].get<double>();
      px.push_back(ax / scale);
      py.push_back(ay / scale);
    }
    REQUIRE(px.size() == static_cast<std::size_t>(frames));
    for (long k = 0; k < frames; ++k) {
      std::string names;
      for (const json &a : value_at(rec["active"], k, json::array())) {
        const std::size_t row = a.get<std::size_t>();
        if (row / states != static_cast<std::size_t>(i)) continue;
        names += (names.empty() ? "" : " ") + rec["rows"][row]["name"].get<std::string>().substr(name.size() + 1);
      }
      INFO("tick " << k);
      CHECK(names == column[i][k]);
      CHECK(std::abs(px[k] - where[i][k].first) < 0.0011);
      CHECK(std::abs(py[k] - where[i][k].second) < 0.0011);
    }
    // Each state change in the result's state log is where the rows change to that state.
    for (const json &e : result["robots"][i]["state_log"]) {
      const std::string state = e["event"].get<std::string>().substr(6);
      const long k = std::lround(e["t"].get<double>() / period);
      INFO(e.dump());
      CHECK(state.rfind(column[i][k], 0) == 0);
      const json at = value_at(rec["active"], k, json::array());
      CHECK(std::any_of(at.begin(), at.end(), [&](const json &a) {
        return rec["rows"][a.get<std::size_t>()]["name"] == name + "/" + column[i][k];
      }));
    }
    // The last row's state is the result's final state.
    CHECK(column[i].back() == result["robots"][i]["state"].get<std::string>());
    // Tick 0: every robot is in Go and drives to the item (its action, in its own calls).
    bool drives = false;
    for (const json &c : value_at(robot["calls"]["ticks"], 0, json::array()))
      drives = drives || robot["calls"]["texts"][c.get<std::size_t>()].get<std::string>().rfind("DriveToItem(", 0) == 0;
    CHECK(drives);
    CHECK(column[i][0] == "Go");
  }
  // Robot 0 carries the cup at the end; the others stood back.
  CHECK(result["items"][0]["held_by"] == 0);
  CHECK(value_at(rec["items"][0]["track"], frames - 1, json()) == json::array({1, 0}));
  CHECK(column[1].back() != "Grab");
  CHECK(column[1].back() != "Carry");
  // The page holds the same recording.
  CHECK(r.page.find("\"robots\":[{") != std::string::npos);
}

TEST_CASE("viewer: a team run without the exchange: the robots' contacts are events", "[e2e][viewer][team]") {
  // Without the exchange nobody yields: robots 1 and 2 run into robot 0 (docs/teams.md).
  const Recorded r = record("samples/fetch_team.fsm", "sim/worlds/fetch_room.json", 10, "--no-exchange");
  REQUIRE(r.run.exit_code == 0);
  const json &log = r.run.result["robot_contact_log"];
  REQUIRE(log.size() >= 2);
  const double period = r.rec["period"].get<double>();
  REQUIRE(r.rec["contacts"].size() == log.size());
  std::size_t contact_events = 0;
  for (const json &e : r.rec["events"]) contact_events += e[1] == "contact" ? 1 : 0;
  CHECK(contact_events == log.size());
  for (std::size_t i = 0; i < log.size(); ++i) {
    const json &c = r.rec["contacts"][i];
    CHECK(c[0].get<long>() == std::lround(log[i]["t"].get<double>() / period));
    CHECK(c[1] == log[i]["robots"][0]);
    CHECK(c[2] == log[i]["robots"][1]);
  }
}
