// The Carbot's sensors: infrared line spots, the ultrasonic fan, the sonar mount servo.
#include <algorithm>
#include <cmath>

#include "core/carbot_model.h"
#include "core/geometry.h"
#include "core/simulation_impl.h"

namespace carbot {

// Analytic: the sensor's spot is straight below it on the floor; it sees black while the
// spot lies within half the line width of the painted polyline.
Vec2 Robot::ir_spot(Side side) const {
  dVector3 p;
  const double y = side == Side::Left ? model::kIrY : -model::kIrY;
  dBodyGetRelPointPos(chassis, model::kIrX, y, -model::kChassisHeight / 2, p);
  return {p[0], p[1]};
}

bool Simulation::Impl::line_black(const Robot& r, Side side) const {
  if (world.line.points.empty()) return false;
  return locate_on_line(world.line, r.ir_spot(side)).distance < world.line.width / 2;
}

// A fan of rays across the beam, each placed from the chassis pose and the mount angle and
// collided against the environment only. A ray that meets a surface more obliquely than
// kSonarMaxIncidence returns no echo, as real ultrasound glances off; the reading is the
// nearest echo of the fan.
//
// Of another robot the beam (20 cm above the floor) meets only the sonar mast: its chassis ends
// at 17 cm, and the beam passes over it as over a low crate.
double Simulation::Impl::sonar_range(const Robot& r) const {
  const dReal* pos = dBodyGetPosition(r.chassis);
  const dReal* R = dBodyGetRotation(r.chassis);
  const double heading = std::atan2(R[4], R[0]);
  const double c = std::cos(heading), s = std::sin(heading);
  const double ox = pos[0] + c * model::kSonarX, oy = pos[1] + s * model::kSonarX;

  double best = model::kSonarRange;
  auto echo = [&](dGeomID geom, double dx, double dy) {
    dContactGeom hit;
    if (dCollide(sonar_ray, geom, 1, &hit, sizeof(hit)) == 0) return;
    const double cos_incidence = std::fabs(hit.normal[0] * dx + hit.normal[1] * dy);
    if (cos_incidence < std::cos(model::kSonarMaxIncidence)) return;
    best = std::min(best, std::max(static_cast<double>(hit.depth), model::kSonarMinRange));
  };
  for (int i = 0; i < model::kSonarRays; ++i) {
    const double spread = model::kSonarRays == 1 ? 0 : -1.0 + 2.0 * i / (model::kSonarRays - 1);
    const double a = heading + r.sonar_angle + spread * model::kSonarHalfBeam;
    const double dx = std::cos(a), dy = std::sin(a);
    dGeomRaySet(sonar_ray, ox, oy, model::kSonarZ, dx, dy, 0);
    for (int g = 0; g < dSpaceGetNumGeoms(env_space); ++g) {
      dGeomID geom = dSpaceGetGeom(env_space, g);
      if (geom != floor) echo(geom, dx, dy);
    }
    for (const Robot& other : robots) {
      if (&other == &r) continue;
      dVector3 m;
      const double top = model::kChassisZ + model::kChassisHeight / 2;
      dBodyGetRelPointPos(other.chassis, model::kSonarX, 0, 0, m);
      dGeomSetPosition(mast_probe, m[0], m[1], (top + model::kTotalHeight) / 2);
      dGeomSetRotation(mast_probe, dBodyGetRotation(other.chassis));
      echo(mast_probe, dx, dy);
    }
  }
  return best;
}

void Robot::move_sonar_mount(double physics_step) {
  const double max_move = model::kSonarMountRate * physics_step;
  sonar_angle += std::clamp(sonar_target - sonar_angle, -max_move, max_move);
}

}  // namespace carbot
