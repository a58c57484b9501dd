// sim_rtf: how much faster than real time the simulator runs one Carbot.
//
// Drives the oval with the LineBot library and a hand-written copy of the GFE line follower
// (two sides, each running until its sensor sees black), for each physics step in turn, and
// prints the real-time factor. It measures; it never fails on time.
//   sim_rtf [--seconds S] [--world W.json]
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "core/simulation.h"
#include "core/world.h"
#include "hal/carbot_hal.h"
#include "hal/hal_binding.h"
#include "robots/robots.h"

using namespace carbot;

namespace {

/// One side of the GFE line follower: forward until the line, stopped until white again.
struct SideController {
  bool running = true;
  using Condition = bool (*)(CarbotRobot*);
  using Action = void (*)(CarbotRobot*);
  void tick(CarbotRobot* robot, Condition black, Condition white, Action fw, Action stop) {
    if (running && black(robot)) running = false;
    else if (!running && white(robot)) running = true;
    running ? fw(robot) : stop(robot);
  }
};

double measure(const World& world, double physics_step, double seconds, double& metres) {
  Simulation sim(world, SimConfig{physics_step, 0.010});
  hal::bind(&sim);
  linebot_reset();
  SideController left, right;
  CarbotRobot* robot = carbot_robot_handle(0);  // the calls' context, as an engine passes it
  const auto start = std::chrono::steady_clock::now();
  while (sim.time() < seconds - 1e-9) {
    left.tick(robot, LineBot_Left_IR_Black, LineBot_Left_IR_White, LineBot_Left_FW, LineBot_Left_Stop);
    right.tick(robot, LineBot_Right_IR_Black, LineBot_Right_IR_White, LineBot_Right_FW, LineBot_Right_Stop);
    sim.step_control();
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  hal::bind(nullptr);
  metres = sim.odometer();
  return wall;
}

}  // namespace

int main(int argc, char** argv) {
  double seconds = 60;
  std::string world_file = SIM_WORLDS_DIR "/oval.json";
  for (int i = 1; i + 1 < argc; i += 2) {
    if (std::strcmp(argv[i], "--seconds") == 0) seconds = std::atof(argv[i + 1]);
    else if (std::strcmp(argv[i], "--world") == 0) world_file = argv[i + 1];
  }
  World world;
  try {
    world = load_world(world_file);
  } catch (const WorldError& e) {
    std::fprintf(stderr, "sim_rtf: %s\n", e.what());
    return 2;
  }
  std::printf("sim_rtf: one Carbot following the line of %s for %.0f s simulated (10 ms control period)\n",
              world.name.c_str(), seconds);
  std::printf("%-14s %12s %12s %14s\n", "physics step", "wall time", "driven", "real-time x");
  for (double step : {0.001, 0.002, 0.005}) {
    double metres = 0;
    const double wall = measure(world, step, seconds, metres);
    std::printf("%11.0f ms %10.3f s %10.2f m %13.0fx%s\n", step * 1000, wall, metres, seconds / wall,
                step == 0.002 ? "   (carbot-sim's default)" : "");
  }
  return 0;
}
