// Collision handling: each robot's geoms against the environment, and each pair of robots
// against each other; a robot's own geoms never collide with each other.
#include <algorithm>

#include "core/simulation_impl.h"

namespace carbot {
namespace {

constexpr int kMaxContacts = 4;
constexpr double kSoftCfm = 1e-4;  ///< robot against the environment
/// Robot against robot: two robots pushing each other with stalled motors make ODE's LCP
/// degenerate ("LCP internal error, s <= 0") at the world's stiffness; a softer contact
/// (a spring of ~33 kN/m at a 2 ms step: about a millimetre of give under the 40 N two
/// Carbot drives push with) keeps it well posed.
constexpr double kRobotSoftCfm = 3e-3;

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

/// What a near callback collides: robot `a` against the environment (b == nullptr) or
/// against robot `b`.
struct Pair {
  Simulation::Impl* sim;
  Robot* a;
  Robot* b;
};

void make_contacts(Simulation::Impl* sim, dContact* contact, int n, double mu, double cfm) {
  for (int i = 0; i < n; ++i) {
    dSurfaceParameters& s = contact[i].surface;
    s.mode = dContactApprox1 | dContactSoftERP | dContactSoftCFM;
    s.mu = mu;
    s.soft_erp = 0.2;
    s.soft_cfm = cfm;
    dJointID j = dJointCreateContact(sim->ode_world, sim->contacts, &contact[i]);
    dJointAttach(j, dGeomGetBody(contact[i].geom.g1), dGeomGetBody(contact[i].geom.g2));
  }
}

void near_callback(void* data, dGeomID a, dGeomID b) {
  const Pair& pair = *static_cast<Pair*>(data);
  Simulation::Impl* sim = pair.sim;
  // dSpaceCollide2 hands us one geom of each space; keep the order (robot a's first).
  if (dGeomGetSpace(a) != pair.a->space) std::swap(a, b);
  const Part part = part_of(a);

  dContact contact[kMaxContacts];
  const int n = dCollide(a, b, kMaxContacts, &contact[0].geom, sizeof(dContact));
  if (n == 0) return;

  if (!pair.b) {                 // against the environment
    if (part == Part::Bumper) {  // a sensor: it notices, it never pushes
      if (b != sim->floor) pair.a->bumper_touch_step = true;
      return;
    }
    make_contacts(sim, contact, n, friction(part), kSoftCfm);
    return;
  }
  // Robot against robot: a bumper feels the other robot (and pushes nothing); other parts
  // push each other with the lower of their two frictions.
  sim->touch_pair(pair.a->index, pair.b->index);
  const Part other = part_of(b);
  if (part == Part::Bumper) pair.a->bumper_touch_step = true;
  if (other == Part::Bumper) pair.b->bumper_touch_step = true;
  if (part == Part::Bumper || other == Part::Bumper) return;
  make_contacts(sim, contact, n, std::min(friction(part), friction(other)), kRobotSoftCfm);
}

}  // namespace

void Simulation::Impl::collide() {
  for (Robot& r : robots) {
    Pair pair{this, &r, nullptr};
    dSpaceCollide2(reinterpret_cast<dGeomID>(r.space), reinterpret_cast<dGeomID>(env_space), &pair, &near_callback);
  }
  for (std::size_t i = 0; i < robots.size(); ++i)
    for (std::size_t j = i + 1; j < robots.size(); ++j) {
      Pair pair{this, &robots[i], &robots[j]};
      dSpaceCollide2(reinterpret_cast<dGeomID>(robots[i].space), reinterpret_cast<dGeomID>(robots[j].space), &pair,
                     &near_callback);
    }
}

}  // namespace carbot
