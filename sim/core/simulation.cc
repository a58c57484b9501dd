// Building the world on ODE and running it: fixed physics steps grouped into control periods.
#include "core/simulation.h"

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "core/carbot_model.h"
#include "core/geometry.h"
#include "core/simulation_impl.h"

namespace carbot {
namespace {

/// ODE must be initialised once per process before anything else ("INTERNAL ERROR 2" otherwise).
void init_ode_once() {
  static const bool done = [] {
    dInitODE2(0);
    dAllocateODEDataForThread(dAllocateMaskAll);
    return true;
  }();
  (void)done;
}

constexpr double kEscapeHold = 0.25;  ///< s the button stays down after a press event

}  // namespace

void Simulation::Impl::note(std::string text) { notes.push_back({time(), std::move(text)}); }

void Simulation::Impl::build_environment() {
  floor = dCreatePlane(env_space, 0, 0, 1, 0);
  for (const Wall& w : world.walls) {
    const double len = distance(w.from, w.to) + w.thickness;  // overlap at corners: no gaps
    dGeomID g = dCreateBox(env_space, len, w.thickness, w.height);
    dGeomSetPosition(g, (w.from.x + w.to.x) / 2, (w.from.y + w.to.y) / 2, w.height / 2);
    dMatrix3 R;
    dRFromAxisAndAngle(R, 0, 0, 1, std::atan2(w.to.y - w.from.y, w.to.x - w.from.x));
    dGeomSetRotation(g, R);
  }
  for (const Box& b : world.boxes) {
    dGeomID g = dCreateBox(env_space, b.size.x, b.size.y, b.height);
    dGeomSetPosition(g, b.center.x, b.center.y, b.height / 2);
  }
}

Simulation::Simulation(const World& world, SimConfig config) : impl_(std::make_unique<Impl>()) {
  const double ratio = config.control_period / config.physics_step;
  if (!(config.physics_step > 0) || ratio < 1 || std::fabs(ratio - std::round(ratio)) > 1e-9)
    throw std::invalid_argument(fmt::format("the physics step ({} s) must divide the control period ({} s)",
                                            config.physics_step, config.control_period));
  init_ode_once();
  Impl& s = *impl_;
  s.world = world;
  s.config = config;
  s.steps_per_control = std::lround(ratio);

  s.ode_world = dWorldCreate();
  dWorldSetGravity(s.ode_world, 0, 0, -9.81);
  dWorldSetERP(s.ode_world, 0.2);
  dWorldSetCFM(s.ode_world, 1e-5);
  dWorldSetAutoDisableFlag(s.ode_world, 0);
  s.robot_space = dSimpleSpaceCreate(nullptr);
  s.env_space = dSimpleSpaceCreate(nullptr);
  s.contacts = dJointGroupCreate(0);
  s.sonar_ray = dCreateRay(nullptr, model::kSonarRange);
  s.build_environment();
  s.build_robot();

  for (const Item& it : world.items) s.items.push_back({it.name, it.at, it.destination, false});
  s.event_done.assign(world.events.size(), false);
  s.run_due_events();
}

Simulation::~Simulation() { impl_->destroy(); }

const World& Simulation::world() const { return impl_->world; }
const SimConfig& Simulation::config() const { return impl_->config; }
double Simulation::time() const { return impl_->time(); }

void Simulation::Impl::physics_step() {
  move_sonar_mount();
  actuate();
  bumper_touch_step = false;
  collide();
  bumper_touch_period = bumper_touch_period || bumper_touch_step;
  dWorldStep(ode_world, config.physics_step);
  dJointGroupEmpty(contacts);  // forgetting this makes every later step far slower
  ++steps;

  const dReal* v = dBodyGetLinearVel(chassis);
  odometer += std::hypot(v[0], v[1]) * config.physics_step;
}

void Simulation::step_control() {
  Impl& s = *impl_;
  s.set_wheel_targets();
  s.bumper_touch_period = false;
  for (long i = 0; i < s.steps_per_control; ++i) s.physics_step();

  const bool was_pressed = s.bumper_pressed;
  s.bumper_pressed = s.bumper_touch_period;
  const Pose p = pose();
  if (s.bumper_pressed && !was_pressed) {
    ++s.bumps;
    // Logged where the bumper is (its front centre): that is what touched.
    const double reach = model::kLength / 2 + model::kBumperDepth;
    s.bump_log.push_back({s.time(), {p.x + reach * std::cos(p.heading), p.y + reach * std::sin(p.heading)}});
  }
  if (!s.left_floor && (std::fabs(p.x) > s.world.size.x / 2 || std::fabs(p.y) > s.world.size.y / 2)) {
    s.left_floor = true;
    s.note(fmt::format("the robot left the floor at ({:.2f}, {:.2f})", p.x, p.y));
  }
  if (s.held >= 0) s.items[s.held].at = gripper_point();
  s.run_due_events();
}

void Simulation::Impl::drop_held(const Vec2* to) {
  ItemState& it = items[held];
  dVector3 g;
  dBodyGetRelPointPos(chassis, model::kGripX, 0, 0, g);
  it.at = to ? *to : Vec2{g[0], g[1]};
  it.held = false;
  held = -1;
}

// Events fire at the first control boundary at or after their time. A "drop" waits until the
// named item is held, so a world can say "drop it once it has been carried for a while".
void Simulation::Impl::run_due_events() {
  const double now = time() + 1e-9;
  for (size_t i = 0; i < world.events.size(); ++i) {
    const Event& e = world.events[i];
    if (event_done[i] || e.at > now) continue;
    if (e.kind == Event::Kind::PressEscape) {
      escape_until = time() + kEscapeHold;
      ++escape_presses;
      event_done[i] = true;
      note("escape pressed");
      continue;
    }
    if (held < 0 || items[held].name != e.item) continue;
    const int index = held;
    drop_held(e.has_to ? &e.to : nullptr);
    event_done[i] = true;
    note(fmt::format("'{}' dropped; it lies at ({:.2f}, {:.2f})", e.item, items[index].at.x, items[index].at.y));
  }
}

// --- Motion and pose ------------------------------------------------------------------------

void Simulation::drive(double forward, double turn_rate) {
  impl_->cmd_forward = std::isfinite(forward) ? forward : 0;
  impl_->cmd_turn = std::isfinite(turn_rate) ? turn_rate : 0;
}
double Simulation::commanded_forward() const { return impl_->cmd_forward; }
double Simulation::commanded_turn_rate() const { return impl_->cmd_turn; }

Pose Simulation::pose() const {
  const dReal* p = dBodyGetPosition(impl_->chassis);
  const dReal* R = dBodyGetRotation(impl_->chassis);
  return {p[0], p[1], std::atan2(R[4], R[0])};
}

double Simulation::forward_speed() const {
  const dReal* v = dBodyGetLinearVel(impl_->chassis);
  const double h = pose().heading;
  return v[0] * std::cos(h) + v[1] * std::sin(h);
}

double Simulation::turn_rate() const { return dBodyGetAngularVel(impl_->chassis)[2]; }
double Simulation::odometer() const { return impl_->odometer; }
bool Simulation::left_floor() const { return impl_->left_floor; }

// --- Sensors --------------------------------------------------------------------------------

bool Simulation::line_black(Side side) const { return impl_->line_black(side); }
Vec2 Simulation::ir_spot(Side side) const { return impl_->ir_spot(side); }
double Simulation::sonar_range() const { return impl_->sonar_range(); }
void Simulation::aim_sonar(double angle) {
  if (!std::isfinite(angle)) return;
  impl_->sonar_target = std::fmax(-model::kSonarMountStop, std::fmin(model::kSonarMountStop, angle));
}
double Simulation::sonar_angle() const { return impl_->sonar_angle; }
double Simulation::sonar_target() const { return impl_->sonar_target; }
bool Simulation::bumper() const { return impl_->bumper_pressed; }
int Simulation::bumps() const { return impl_->bumps; }
const std::vector<Bump>& Simulation::bump_log() const { return impl_->bump_log; }
bool Simulation::escape() const { return impl_->time() < impl_->escape_until - 1e-9; }
int Simulation::escape_presses() const { return impl_->escape_presses; }

// --- Items ----------------------------------------------------------------------------------

const std::vector<ItemState>& Simulation::items() const { return impl_->items; }

Vec2 Simulation::gripper_point() const {
  dVector3 g;
  dBodyGetRelPointPos(impl_->chassis, model::kGripX, 0, 0, g);
  return {g[0], g[1]};
}

int Simulation::held_item() const { return impl_->held; }

bool Simulation::grip(int index) {
  Impl& s = *impl_;
  if (s.held >= 0 || index < 0 || index >= static_cast<int>(s.items.size())) return s.held == index;
  ItemState& it = s.items[index];
  if (distance(it.at, gripper_point()) > model::kGripReach) return false;
  it.held = true;
  it.at = gripper_point();
  s.held = index;
  return true;
}

void Simulation::release() {
  if (impl_->held >= 0) impl_->drop_held(nullptr);
}

const std::vector<SimNote>& Simulation::notes() const { return impl_->notes; }

}  // namespace carbot
