// Finding a wall in a sonar sweep: the geometry behind SearchWall, kept apart so it can be
// tested on made-up sweeps.
#pragma once

#include <vector>

namespace carbot::toolbox {

/// One reading of a sweep: mount angle (rad, robot frame, + = left) and range (m).
struct SonarSample {
  double angle = 0;
  double range = 0;
};

/// The wall SearchWall settles on.
struct WallFit {
  bool found = false;
  double turn = 0;      ///< rad: turning in place by this makes the robot parallel to the wall, wall on the right
  double distance = 0;  ///< m: from the robot centre to the wall's line
};

/// Splits the echoes of a sweep (in angle order) into straight runs of at least 3 points
/// (walls, box faces), takes the run whose line the robot would meet driving straight on, or
/// else the nearest, and says how to turn parallel to it. `sonar_x` is the sonar's distance
/// ahead of the robot centre; ranges >= `max_range` are no echo.
WallFit fit_wall(const std::vector<SonarSample>& sweep, double sonar_x, double max_range);

}  // namespace carbot::toolbox
