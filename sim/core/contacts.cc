// Collision handling: robot geoms against the environment, never robot against robot.
#include <algorithm>

#include "core/simulation_impl.h"

namespace carbot {
namespace {

constexpr int kMaxContacts = 4;

/// Friction coefficient by robot part. dContactApprox1 makes mu a coefficient (a fraction
/// of the normal force); without it ODE reads mu as a force in newtons.
double friction(Part p) {
  switch (p) {
    case Part::Wheel: return 0.9;
    case Part::Caster: return 0.0;
    case Part::Chassis: return 0.4;
    case Part::Bumper: return 0.0;
  }
  return 0.0;
}

void near_callback(void* data, dGeomID a, dGeomID b) {
  auto* sim = static_cast<Simulation::Impl*>(data);
  // dSpaceCollide2 hands us (robot geom, environment geom); keep that order.
  if (dGeomGetSpace(a) != sim->robot_space) std::swap(a, b);
  const Part part = part_of(a);

  dContact contact[kMaxContacts];
  const int n = dCollide(a, b, kMaxContacts, &contact[0].geom, sizeof(dContact));
  if (n == 0) return;

  if (part == Part::Bumper) {  // a sensor: it notices, it never pushes
    if (b != sim->floor) sim->bumper_touch_step = true;
    return;
  }
  const double mu = friction(part);
  for (int i = 0; i < n; ++i) {
    dSurfaceParameters& s = contact[i].surface;
    s.mode = dContactApprox1 | dContactSoftERP | dContactSoftCFM;
    s.mu = mu;
    s.soft_erp = 0.2;
    s.soft_cfm = 1e-4;
    dJointID j = dJointCreateContact(sim->ode_world, sim->contacts, &contact[i]);
    dJointAttach(j, dGeomGetBody(contact[i].geom.g1), dGeomGetBody(contact[i].geom.g2));
  }
}

}  // namespace

void Simulation::Impl::collide() {
  dSpaceCollide2(reinterpret_cast<dGeomID>(robot_space), reinterpret_cast<dGeomID>(env_space), this, &near_callback);
}

}  // namespace carbot
