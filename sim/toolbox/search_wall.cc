// SearchWall: a sonar sweep while standing still, then the wall geometry of wall_fit.
#include <cmath>

#include "carbot_toolbox.h"
#include "wall_fit.h"

namespace carbot::toolbox {
namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;
constexpr double kFrom = -100 * kDeg, kTo = 100 * kDeg, kStep = 10 * kDeg;
constexpr double kSonarX = 0.10;  ///< m, the sonar ahead of the centre (sim/core/carbot_model.h)

}  // namespace

SearchWall::SearchWall(Environment& ee, afp::Out<float> angle) : ee_(ee), angle_(std::move(angle)) {}

void SearchWall::start(afp::Context&) {
  ee_.halt();
  angles_.clear();
  ranges_.clear();
  aim_ = kFrom;
  waited_ = 0;
  ee_.aim_sonar(aim_);
}

afp::StepResult SearchWall::step(afp::Context& ctx) {
  ee_.halt();
  if (!ee_.sonar_at(aim_) || ++waited_ < 2) return afp::running;  // the mount settles, then one echo
  angles_.push_back(aim_);
  ranges_.push_back(ee_.sonar_range());
  waited_ = 0;
  aim_ += kStep;
  if (aim_ <= kTo + 1e-9) {
    ee_.aim_sonar(aim_);
    return afp::running;
  }
  std::vector<SonarSample> sweep;
  for (size_t i = 0; i < angles_.size(); ++i) sweep.push_back({angles_[i], ranges_[i]});
  const WallFit wall = fit_wall(sweep, kSonarX, ee_.max_range());
  if (!wall.found) return NO_WALL_FOUND;
  angle_.write(ctx, static_cast<float>(wall.turn / kDeg));
  return WALL_FOUND;
}

void SearchWall::stop() { ee_.halt(); }

}  // namespace carbot::toolbox
