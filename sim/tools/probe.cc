// sim_probe [PHYSICS_STEP]: drives the Carbot through fixed manoeuvres on an empty floor and
// prints what it measured, to check that commanded and measured motion agree (docs/sim.md,
// "The model"), and how fast one step size runs.
#include <chrono>
#include <cstdio>
#include <cstdlib>

#include "core/geometry.h"
#include "core/simulation.h"

using namespace carbot;

static void phase(Simulation& sim, const char* what, double v, double w, double seconds) {
  const Pose a = sim.pose();
  const double t0 = sim.time();
  sim.drive(v, w);
  while (sim.time() < t0 + seconds - 1e-9) sim.step_control();
  const Pose b = sim.pose();
  std::printf(
      "%-22s cmd v=%5.2f w=%5.2f | moved %6.3f m, turned %7.2f deg, v=%5.3f w=%6.3f, pose (%.3f, %.3f, %.1f deg)\n",
      what, v, w, distance({a.x, a.y}, {b.x, b.y}), deg(wrap_angle(b.heading - a.heading)), sim.forward_speed(),
      sim.turn_rate(), b.x, b.y, deg(b.heading));
}

int main(int argc, char** argv) {
  World w;
  w.size = {20, 20};
  SimConfig config;
  if (argc > 1) config.physics_step = std::atof(argv[1]);
  Simulation sim(w, config);
  phase(sim, "settle", 0, 0, 1);
  phase(sim, "forward 0.31", 0.31, 0, 3);
  phase(sim, "stop", 0, 0, 1);
  phase(sim, "turn in place 1.5", 0, 1.5, 2);
  phase(sim, "stop", 0, 0, 1);
  phase(sim, "backward 0.2", -0.2, 0, 2);
  phase(sim, "arc 0.2, 0.5", 0.2, 0.5, 4);
  phase(sim, "arc 0.2, -0.5", 0.2, -0.5, 4);
  phase(sim, "stop", 0, 0, 1);

  auto t0 = std::chrono::steady_clock::now();
  sim.drive(0.2, 0.3);
  const double sim0 = sim.time();
  while (sim.time() < sim0 + 60) sim.step_control();
  double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("60 s simulated in %.3f s wall: %.0fx real time\n", wall, 60 / wall);
}
