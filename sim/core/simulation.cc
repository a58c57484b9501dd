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

std::string Simulation::Impl::robot_name(const Robot& r) const {
  return robots.size() == 1 ? std::string("the robot") : fmt::format("robot {}", r.index);
}

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
  const std::vector<Start>& starts = world.robots.empty() ? std::vector<Start>{world.start} : world.robots;
  s.robots.resize(starts.size());
  for (std::size_t i = 0; i < starts.size(); ++i) {
    s.robots[i].index = static_cast<int>(i);
    s.robots[i].space = dSimpleSpaceCreate(nullptr);
  }
  s.env_space = dSimpleSpaceCreate(nullptr);
  s.contacts = dJointGroupCreate(0);
  s.sonar_ray = dCreateRay(nullptr, model::kSonarRange);
  if (starts.size() > 1)
    s.mast_probe = dCreateBox(nullptr, model::kMastSize, model::kMastSize,
                              model::kTotalHeight - model::kChassisZ - model::kChassisHeight / 2);
  s.build_environment();
  for (std::size_t i = 0; i < starts.size(); ++i) s.robots[i].build(s.ode_world, starts[i]);
  s.pair_touch_period.assign(starts.size() * starts.size(), 0);
  s.pair_touch_was.assign(starts.size() * starts.size(), 0);

  for (const Item& it : world.items) s.items.push_back({it.name, it.at, it.destination, false});
  s.event_done.assign(world.events.size(), false);
  s.run_due_events();
}

Simulation::~Simulation() { impl_->destroy(); }

const World& Simulation::world() const { return impl_->world; }
const SimConfig& Simulation::config() const { return impl_->config; }
double Simulation::time() const { return impl_->time(); }

int Simulation::robot_count() const { return static_cast<int>(impl_->robots.size()); }
void Simulation::select(int robot) {
  if (robot < 0 || robot >= robot_count())
    throw std::out_of_range(fmt::format("no robot {} (the world has {})", robot, robot_count()));
  impl_->selected = robot;
}
int Simulation::selected() const { return impl_->selected; }
const std::vector<RobotContact>& Simulation::robot_contacts() const { return impl_->robot_contacts; }

void Simulation::Impl::physics_step() {
  for (Robot& r : robots) {
    r.move_sonar_mount(config.physics_step);
    r.actuate();
    r.bumper_touch_step = false;
  }
  collide();
  for (Robot& r : robots) r.bumper_touch_period = r.bumper_touch_period || r.bumper_touch_step;
  dWorldStep(ode_world, config.physics_step);
  dJointGroupEmpty(contacts);  // forgetting this makes every later step far slower
  ++steps;

  for (Robot& r : robots) {
    const dReal* v = dBodyGetLinearVel(r.chassis);
    r.odometer += std::hypot(v[0], v[1]) * config.physics_step;
  }
}

void Simulation::step_control() {
  Impl& s = *impl_;
  for (Robot& r : s.robots) {
    r.set_wheel_targets();
    r.bumper_touch_period = false;
  }
  for (long i = 0; i < s.steps_per_control; ++i) s.physics_step();

  for (Robot& r : s.robots) {
    const bool was_pressed = r.bumper_pressed;
    r.bumper_pressed = r.bumper_touch_period;
    const dReal* pos = dBodyGetPosition(r.chassis);
    const dReal* R = dBodyGetRotation(r.chassis);
    const Pose p{pos[0], pos[1], std::atan2(R[4], R[0])};
    if (r.bumper_pressed && !was_pressed) {
      ++r.bumps;
      // Logged where the bumper is (its front centre): that is what touched.
      const double reach = model::kLength / 2 + model::kBumperDepth;
      r.bump_log.push_back({s.time(), {p.x + reach * std::cos(p.heading), p.y + reach * std::sin(p.heading)}});
    }
    if (!r.left_floor && (std::fabs(p.x) > s.world.size.x / 2 || std::fabs(p.y) > s.world.size.y / 2)) {
      r.left_floor = true;
      s.note(fmt::format("{} left the floor at ({:.2f}, {:.2f})", s.robot_name(r), p.x, p.y));
    }
    if (r.held >= 0) s.items[static_cast<size_t>(r.held)].at = r.gripper_point();
  }
  // A robot-robot touch is logged once per contact, where the two centres' midpoint is.
  const std::size_t n = s.robots.size();
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = a + 1; b < n; ++b) {
      const std::size_t k = a * n + b;
      if (s.pair_touch_period[k] && !s.pair_touch_was[k]) {
        const dReal* pa = dBodyGetPosition(s.robots[a].chassis);
        const dReal* pb = dBodyGetPosition(s.robots[b].chassis);
        s.robot_contacts.push_back(
            {s.time(), static_cast<int>(a), static_cast<int>(b), {(pa[0] + pb[0]) / 2, (pa[1] + pb[1]) / 2}});
      }
      s.pair_touch_was[k] = s.pair_touch_period[k];
      s.pair_touch_period[k] = 0;
    }
  s.run_due_events();
}

Vec2 Robot::gripper_point() const {
  dVector3 g;
  dBodyGetRelPointPos(chassis, model::kGripX, 0, 0, g);
  return {g[0], g[1]};
}

void Simulation::Impl::drop_held(Robot& r, const Vec2* to) {
  ItemState& it = items[static_cast<size_t>(r.held)];
  it.at = to ? *to : r.gripper_point();
  it.held = false;
  r.held = -1;
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
    Robot* holder = nullptr;
    for (Robot& r : robots)
      if (r.held >= 0 && items[static_cast<size_t>(r.held)].name == e.item) holder = &r;
    if (!holder) continue;
    const int index = holder->held;
    drop_held(*holder, e.has_to ? &e.to : nullptr);
    event_done[i] = true;
    note(fmt::format("'{}' dropped; it lies at ({:.2f}, {:.2f})", e.item, items[static_cast<size_t>(index)].at.x,
                     items[static_cast<size_t>(index)].at.y));
  }
}

// --- Motion and pose ------------------------------------------------------------------------

void Simulation::drive(double forward, double turn_rate) {
  impl_->robot().cmd_forward = std::isfinite(forward) ? forward : 0;
  impl_->robot().cmd_turn = std::isfinite(turn_rate) ? turn_rate : 0;
}
double Simulation::commanded_forward() const { return impl_->robot().cmd_forward; }
double Simulation::commanded_turn_rate() const { return impl_->robot().cmd_turn; }

Pose Simulation::pose() const {
  const dReal* p = dBodyGetPosition(impl_->robot().chassis);
  const dReal* R = dBodyGetRotation(impl_->robot().chassis);
  return {p[0], p[1], std::atan2(R[4], R[0])};
}

double Simulation::forward_speed() const {
  const dReal* v = dBodyGetLinearVel(impl_->robot().chassis);
  const double h = pose().heading;
  return v[0] * std::cos(h) + v[1] * std::sin(h);
}

double Simulation::turn_rate() const { return dBodyGetAngularVel(impl_->robot().chassis)[2]; }
double Simulation::odometer() const { return impl_->robot().odometer; }
bool Simulation::left_floor() const { return impl_->robot().left_floor; }

// --- Sensors --------------------------------------------------------------------------------

bool Simulation::line_black(Side side) const { return impl_->line_black(impl_->robot(), side); }
Vec2 Simulation::ir_spot(Side side) const { return impl_->robot().ir_spot(side); }
double Simulation::sonar_range() const { return impl_->sonar_range(impl_->robot()); }
void Simulation::aim_sonar(double angle) {
  if (!std::isfinite(angle)) return;
  impl_->robot().sonar_target = std::fmax(-model::kSonarMountStop, std::fmin(model::kSonarMountStop, angle));
}
double Simulation::sonar_angle() const { return impl_->robot().sonar_angle; }
double Simulation::sonar_target() const { return impl_->robot().sonar_target; }
bool Simulation::bumper() const { return impl_->robot().bumper_pressed; }
int Simulation::bumps() const { return impl_->robot().bumps; }
const std::vector<Bump>& Simulation::bump_log() const { return impl_->robot().bump_log; }
bool Simulation::escape() const { return impl_->time() < impl_->escape_until - 1e-9; }
int Simulation::escape_presses() const { return impl_->escape_presses; }

// --- Items ----------------------------------------------------------------------------------

const std::vector<ItemState>& Simulation::items() const { return impl_->items; }

Vec2 Simulation::gripper_point() const { return impl_->robot().gripper_point(); }

int Simulation::held_item() const { return impl_->robot().held; }

int Simulation::holder(int index) const {
  for (const Robot& r : impl_->robots)
    if (r.held == index && index >= 0) return r.index;
  return -1;
}

bool Simulation::grip(int index) {
  Impl& s = *impl_;
  Robot& r = s.robot();
  if (r.held >= 0 || index < 0 || index >= static_cast<int>(s.items.size())) return r.held == index;
  ItemState& it = s.items[static_cast<size_t>(index)];
  if (it.held) return false;  // in another robot's gripper
  if (distance(it.at, r.gripper_point()) > model::kGripReach) return false;
  it.held = true;
  it.at = r.gripper_point();
  r.held = index;
  return true;
}

void Simulation::release() {
  if (impl_->robot().held >= 0) impl_->drop_held(impl_->robot(), nullptr);
}

void Simulation::set_lights(bool on) { impl_->robot().lights = on; }
bool Simulation::lights() const { return impl_->robot().lights; }
void Simulation::beep(int times) {
  Robot& r = impl_->robot();
  r.beeps += times > 0 ? times : 0;
  impl_->note(fmt::format("{} beeps {} time{}", impl_->robot_name(r), times, times == 1 ? "" : "s"));
}
int Simulation::beeps() const { return impl_->robot().beeps; }

const std::vector<SimNote>& Simulation::notes() const { return impl_->notes; }

}  // namespace carbot
