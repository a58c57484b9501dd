// Several Carbots in one world (docs/sim.md, "Several robots"): in process, robots collide with
// each other and each is driven on its own; through carbot-sim, the team sample
// (samples/fetch_team.fsm) with the reference exchange, without any exchange (the contrast
// run), with a late and a lossy one.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "core/carbot_model.h"
#include "core/geometry.h"
#include "core/simulation.h"
#include "core/world.h"
#include "hal/carbot_hal.h"
#include "hal/hal_binding.h"
#include "robots/robots.h"
#include "support.h"

using namespace carbot;

namespace {

void run_for(Simulation &sim, double seconds) {
  const double end = sim.time() + seconds - 1e-9;
  while (sim.time() < end) sim.step_control();
}

/// An open floor with robots at the given poses.
World floor_with(std::vector<Start> robots) {
  World w;
  w.size = {20, 20};
  w.robots = std::move(robots);
  w.start = w.robots.front();
  return w;
}

std::string world_error(const std::string &text) {
  try {
    carbot::parse_world(text, "w.json");
  } catch (const carbot::WorldError &e) { return e.what(); }
  return "(accepted)";
}

/// The robots of a result.json by their final state: how many are in `state`.
int robots_in(const nlohmann::json &result, const std::string &state) {
  int n = 0;
  for (const auto &r : result["robots"]) n += r["state"] == state ? 1 : 0;
  return n;
}

/// The time the state log of robot `robot` first shows `event` ("state Grab PickUp()"), or -1.
double first(const nlohmann::json &result, int robot, const std::string &event) {
  for (const auto &e : result["robots"][robot]["state_log"])
    if (e["event"] == event) return e["t"].get<double>();
  return -1;
}

const char *kGrab = "state Grab PickUp()";
const char *kYield = "state Yield Park()";
const char *kCarry = "state Carry Carry()";

double item_to_destination(const nlohmann::json &result) {
  return result["items"][0]["distance_to_destination_m"].get<double>();
}

/// The team sample with the reference exchange: exactly one robot picks the item up and carries
/// it to its destination (state Done); every other one yields and parks (state Left) without
/// touching anyone, one tick after the carrier started picking up (the reports of tick t are
/// read in tick t+1).
void check_team_fetches(const char *world_file, int robots) {
  const e2e::SimRun run = e2e::run_sim("samples/fetch_team.fsm", world_file, 20);
  INFO(run.output);
  REQUIRE(run.exit_code == 0);
  const nlohmann::json &r = run.result;
  CHECK(r["status"] == "succeeded");
  REQUIRE(r["robots"].size() == static_cast<std::size_t>(robots));
  CHECK(robots_in(r, "Done") == 1);
  CHECK(robots_in(r, "Left") == robots - 1);
  CHECK(r["robot_contacts"] == 0);
  CHECK(r["bumps"] == 0);
  CHECK(r["items"][0]["held"] == false);
  CHECK(item_to_destination(r) < 0.10);
  int carrier = -1;
  for (const auto &robot : r["robots"])
    if (robot["state"] == "Done") carrier = robot["robot"];
  REQUIRE(carrier >= 0);
  CHECK(first(r, carrier, kCarry) > first(r, carrier, kGrab));
  const double grabbed = first(r, carrier, kGrab);
  REQUIRE(grabbed > 0);
  for (int i = 0; i < robots; ++i) {
    if (i == carrier) continue;
    CHECK(first(r, i, kGrab) < 0);  // never tried to pick it up
    CHECK(first(r, i, kYield) == Approx(grabbed + r["control_period_s"].get<double>()).margin(1e-6));
    CHECK(r["robots"][i]["distance_m"].get<double>() < 2.5);  // drove towards the item, then backed off
  }
  const auto &x = r["exchange"];
  CHECK(x["enabled"] == true);
  CHECK(x["reports_lost"] == 0);
  CHECK(x["reports_sent"].get<long>() > 0);
}

/// The contrast run: the same robots and chart with no exchange, so team(S) stays 0 for all.
/// Nobody yields: the others keep going for the item, which one robot is carrying, run into
/// that robot and push it about, and within 20 s the item is not delivered.
nlohmann::json check_alone_contends(const char *world_file) {
  const e2e::SimRun run = e2e::run_sim("samples/fetch_team.fsm", world_file, 20, "--no-exchange");
  INFO(run.output);
  REQUIRE(run.exit_code == 0);
  const nlohmann::json &r = run.result;
  CHECK(r["status"] == "running");
  CHECK(robots_in(r, "Left") == 0);
  CHECK(robots_in(r, "Done") == 0);
  CHECK(robots_in(r, "Carry") == 1);           // one robot got the item ...
  CHECK(r["robot_contacts"].get<int>() >= 1);  // ... and the others ran into it
  CHECK(r["items"][0]["held"] == true);        // never put down where it belongs
  CHECK(item_to_destination(r) > 0.10);
  for (const auto &robot : r["robots"]) CHECK(first(r, robot["robot"], kYield) < 0);
  CHECK(r["exchange"]["enabled"] == false);
  CHECK(r["exchange"]["reports_sent"] == 0);
  return r;
}

}  // namespace

TEST_CASE("team model: robots collide with each other and the bumper feels another robot", "[e2e][team]") {
  // Robot 0 drives at robot 1, which stands 1.2 m ahead facing it.
  Simulation sim(floor_with({{{0, 0}, 0}, {{1.2, 0}, 180}}));
  REQUIRE(sim.robot_count() == 2);
  sim.select(0);
  sim.drive(0.25, 0);
  run_for(sim, 6);
  sim.select(0);
  CHECK(sim.bumps() == 1);  // felt robot 1
  REQUIRE(sim.robot_contacts().size() == 1);
  CHECK(sim.robot_contacts().front().a == 0);
  CHECK(sim.robot_contacts().front().b == 1);
  // Where: between the two centres (robot 0 stopped with its bumper at robot 1's).
  CHECK(sim.robot_contacts().front().at.x == Approx((1.2 - 0.46 + 1.2) / 2).margin(0.05));
  // Robot 0 did not drive through robot 1: their centres stay a body apart. Robot 1's motors
  // hold its wheels as strongly as robot 0's drive them, so it is hardly pushed.
  const Pose p0 = sim.pose();
  sim.select(1);
  const Pose p1 = sim.pose();
  CHECK(p0.x > 0.7);                 // it drove up to robot 1
  CHECK(p1.x > 1.2 - 0.005);         // robot 1 was not pulled, nor passed
  CHECK(p1.x - p0.x > 0.40 - 0.01);  // two half lengths (soft contacts)
  CHECK(sim.bumps() == 1);           // bumper to bumper: robot 1 felt it too
}

TEST_CASE("team model: the sonar sees another robot's mast, not past it", "[e2e][team]") {
  // Robot 1 stands 1.5 m ahead of robot 0, facing away: its mast (6 cm square, 10 cm ahead of
  // its centre) is 1.6 - 0.03 m from robot 0's centre, whose sonar sits 10 cm ahead.
  Simulation sim(floor_with({{{0, 0}, 0}, {{1.5, 0}, 0}}));
  sim.select(0);
  CHECK(sim.sonar_range() == Approx(1.6 - 0.03 - 0.10).margin(0.005));
  sim.select(1);
  CHECK(sim.sonar_range() == Approx(model::kSonarRange));  // nothing ahead of robot 1
  // Half a metre to the side, robot 1 is outside the beam.
  Simulation aside(floor_with({{{0, 0}, 0}, {{1.5, 0.5}, 0}}));
  CHECK(aside.sonar_range() == Approx(model::kSonarRange));
}

TEST_CASE("team model: each robot is driven on its own and grips only a free item", "[e2e][team]") {
  World w = floor_with({{{0, 0}, 0}, {{0, 2}, 180}});
  w.items.push_back({"cup", {0.29, 0}, {1, 1}});
  Simulation sim(w);
  sim.select(1);
  sim.drive(0.2, 0);
  sim.select(0);
  CHECK(sim.grip(0));  // the cup lies at robot 0's gripper point
  run_for(sim, 2);
  CHECK(sim.pose().x == Approx(0).margin(0.01));  // robot 0 was told nothing
  CHECK(sim.holder(0) == 0);
  sim.select(1);
  CHECK(sim.pose().x < -0.3);  // robot 1 drove (heading 180: towards -x)
  CHECK(sim.held_item() == -1);
  CHECK_FALSE(sim.grip(0));  // robot 0 holds it
}

TEST_CASE("team libraries: an interface call acts on the robot of its context, not the selected one", "[e2e][team]") {
  // The simulation has robot 0 selected; the calls name robot 1 through their first argument,
  // as an engine built with carbot-sim's instance context passes it (docs/sim.md "Several
  // robots"), and the library passes it on to every HAL call.
  Simulation sim(floor_with({{{0, 0}, 0}, {{0, 2}, 0}}));
  hal::bind(&sim);
  sim.select(0);
  linebot_reset();
  CarbotRobot *const first = carbot_robot_handle(0), *const second = carbot_robot_handle(1);
  CHECK(first != second);
  CHECK(carbot_robot_of(second) == 1);
  LineBot_Left_FW(second);
  LineBot_Right_FW(second);
  CHECK(carbot_robot_count(second) == 2);
  sim.select(1);
  CHECK(sim.commanded_forward() == Approx(0.2));
  sim.select(0);
  CHECK(sim.commanded_forward() == Approx(0));  // the bound robot was told nothing
  // Each robot's library state is its own: robot 0's left side alone turns it, robot 1 goes on.
  LineBot_Left_FW(first);
  sim.select(0);
  CHECK(sim.commanded_forward() == Approx(0.1));
  sim.select(1);
  CHECK(sim.commanded_forward() == Approx(0.2));
  hal::bind(nullptr);
}

TEST_CASE("team: carbot-sim builds a C engine with its robot as instance context", "[e2e][team]") {
  e2e::TempDir dir;
  const e2e::SimRun run =
      e2e::run_sim("samples/fetch_team.fsm", "sim/worlds/fetch_hall.json", 1, "--work-dir " + dir.file("engine"));
  INFO(run.output);
  REQUIRE(run.exit_code == 0);
  auto text = [&](const std::string &name) {
    std::ifstream in(dir.file("engine/" + name));
    std::stringstream all;
    all << in.rdbuf();
    return all.str();
  };
  // gfec ran with --context-type: the engine's calls take the robot first, and the shim sets it.
  CHECK(text("engine.h").find("void DriveToItem(struct CarbotRobot *ctx);") != std::string::npos);
  CHECK(text("engine.c").find("DriveToItem(m->ctx)") != std::string::npos);
  CHECK(text("shim.c").find("Fetch_set_context((Fetch *)m, robot);") != std::string::npos);
}

TEST_CASE("team world files: start lists one pose per robot", "[e2e][team][world]") {
  const World w = e2e::world("sim/worlds/fetch_room.json");
  REQUIRE(w.robots.size() == 3);
  CHECK(w.start.position.x == w.robots[0].position.x);
  CHECK(e2e::world("sim/worlds/cleanup.json").robots.size() == 1);  // the one-robot form
  CHECK(world_error(R"({"size": [2, 2], "start": []})") == "w.json: start: expected at least one robot");
  CHECK(world_error(R"({"size": [2, 2], "start": [{"pose": [0, 0, 0]}, {"pose": [1, 0]}]})") ==
        "w.json: start[1].pose: expected [x, y, heading_deg]");
  CHECK(world_error(R"({"size": [2, 2], "start": [{"pose": [0, 0, 0]}, {"pos": [1, 0, 0]}]})") ==
        "w.json: start[1].pos: unknown field (expected one of: pose)");
  std::string nine = R"({"size": [9, 9], "start": [)";
  for (int i = 0; i < 9; ++i) nine += std::string(i ? ", " : "") + "{\"pose\": [" + std::to_string(i) + ", 0, 0]}";
  CHECK(world_error(nine + "]}") == "w.json: start: expected at most 8 robots, got 9");
}

TEST_CASE("team: with the exchange one of three robots fetches the cup, the others park", "[e2e][team]") {
  check_team_fetches("sim/worlds/fetch_room.json", 3);
}

TEST_CASE("team: with the exchange one of two robots fetches the book in the hall, the other parks", "[e2e][team]") {
  check_team_fetches("sim/worlds/fetch_hall.json", 2);
}

TEST_CASE("team: without the exchange three robots chase the cup and run into each other", "[e2e][team]") {
  const nlohmann::json r = check_alone_contends("sim/worlds/fetch_room.json");
  CHECK(r["bumps"].get<int>() >= 2);
}

TEST_CASE("team: without the exchange the second robot in the hall runs into the carrier", "[e2e][team]") {
  check_alone_contends("sim/worlds/fetch_hall.json");
}

TEST_CASE("team: with reports two seconds late the others run into the carrier before yielding", "[e2e][team]") {
  const e2e::SimRun run =
      e2e::run_sim("samples/fetch_team.fsm", "sim/worlds/fetch_room.json", 20, "--exchange-delay 200");
  INFO(run.output);
  REQUIRE(run.exit_code == 0);
  const nlohmann::json &r = run.result;
  CHECK(r["exchange"]["delay_ticks"] == 200);
  CHECK(r["robot_contacts"].get<int>() >= 1);
  int carrier = -1;
  for (const auto &robot : r["robots"])
    if (robot["state"] == "Done") carrier = robot["robot"];
  REQUIRE(carrier >= 0);
  // Each other robot yields 2 s and one tick after the carrier started picking up.
  for (int i = 0; i < 3; ++i)
    if (i != carrier) CHECK(first(r, i, kYield) == Approx(first(r, carrier, kGrab) + 2.01).margin(1e-6));
  CHECK(robots_in(r, "Left") == 2);
}

TEST_CASE("team: a lossy exchange is repeatable with its seed, trace and picture carry every robot", "[e2e][team]") {
  const std::string lossy = "--exchange-loss 0.9 --seed 7";
  const e2e::SimRun a = e2e::run_sim("samples/fetch_team.fsm", "sim/worlds/fetch_room.json", 20, lossy);
  const e2e::SimRun b = e2e::run_sim("samples/fetch_team.fsm", "sim/worlds/fetch_room.json", 20, lossy);
  INFO(a.output);
  REQUIRE(a.exit_code == 0);
  CHECK(a.trace_text == b.trace_text);
  CHECK(a.result == b.result);
  const auto &x = a.result["exchange"];
  CHECK(x["loss"] == 0.9);
  CHECK(x["seed"] == 7);
  // About 90% of the reports were lost.
  const double lost = x["reports_lost"].get<double>() / x["reports_sent"].get<double>();
  CHECK(lost == Approx(0.9).margin(0.03));

  // The trace: a robot column, every robot once per tick, in robot order.
  std::istringstream in(a.trace_text);
  std::string line;
  std::getline(in, line);
  CHECK(line == "t,robot,x,y,heading,active");
  int rows = 0, expected_robot = 0;
  bool in_order = true;
  while (std::getline(in, line)) {
    int robot = -1;
    double t = 0;
    if (std::sscanf(line.c_str(), "%lf,%d,", &t, &robot) != 2) continue;
    in_order = in_order && robot == expected_robot;
    expected_robot = (expected_robot + 1) % 3;
    ++rows;
  }
  CHECK(in_order);
  CHECK(rows % 3 == 0);
  CHECK(rows / 3 == static_cast<int>(std::lround(a.result["sim_time_s"].get<double>() / 0.01)) + 1);
  // The picture names each robot.
  for (const char *label : {"robot 0", "robot 1", "robot 2"}) CHECK(a.svg.find(label) != std::string::npos);
}

// Not a team machine: each robot runs its own engine, with the HAL bound to it while it ticks,
// and its own copy of the LineBot library's state (its side speeds); no exchange. Two line
// followers on opposite straights of the oval both follow the line: each robot's sensor reads
// and motor commands are its own.
TEST_CASE("team: two line followers share the oval, each on its own engine and library state", "[e2e][team]") {
  e2e::TempDir dir;
  nlohmann::json oval;
  std::ifstream(e2e::source("sim/worlds/oval.json")) >> oval;
  oval["start"] = nlohmann::json::parse(R"([{"pose": [-0.4, -0.7, 0]}, {"pose": [0.4, 0.7, 180]}])");
  const std::string world_file = dir.file("two_on_the_oval.json");
  std::ofstream(world_file) << oval.dump();
  const e2e::SimRun run = e2e::run_sim("samples/line_follower.sfc", world_file, 30);
  INFO(run.output);
  REQUIRE(run.exit_code == 0);
  CHECK(run.result["status"] == "running");
  CHECK(run.result["robot_contacts"] == 0);
  CHECK(run.result.count("exchange") == 0);  // not a team machine
  const World w = carbot::load_world(world_file);
  for (int robot = 0; robot < 2; ++robot) {
    std::istringstream in(run.trace_text);
    std::string line;
    std::getline(in, line);
    double worst = 0, travelled = 0, last_along = -1;
    const double length = line_length(w.line);
    while (std::getline(in, line)) {
      double t = 0, x = 0, y = 0;
      int r = -1;
      if (std::sscanf(line.c_str(), "%lf,%d,%lf,%lf", &t, &r, &x, &y) != 4 || r != robot) continue;
      const LinePosition at = locate_on_line(w.line, {x, y});
      worst = std::max(worst, at.distance);
      if (last_along >= 0) {
        double step = at.along - last_along;
        if (step > length / 2) step -= length;
        if (step < -length / 2) step += length;
        travelled += step;
      }
      last_along = at.along;
    }
    INFO("robot " << robot << ": worst " << worst << " m, travelled " << travelled << " m");
    CHECK(worst < 0.04);
    CHECK(travelled > 4.0);  // ~0.2 m/s for 30 s, counter-clockwise (the line's order)
  }
}

TEST_CASE("team: more robots than the team's size are refused", "[e2e][team]") {
  e2e::TempDir dir;
  const std::string five = dir.file("five.json");
  std::ofstream(five) << R"({"size": [6, 6], "items": [{"name": "cup", "at": [0, 0], "destination": [1, 1]}],
    "start": [{"pose": [-2, 0, 0]}, {"pose": [2, 0, 180]}, {"pose": [0, 2, -90]}, {"pose": [0, -2, 90]},
              {"pose": [-2, -2, 45]}]})";
  const e2e::SimRun run = e2e::run_sim("samples/fetch_team.fsm", five, 1);
  CHECK(run.exit_code == 1);
  CHECK(run.output.find("5 robots, but Fetch is a team of at most 4 agents") != std::string::npos);
}
