// The Carbot's physical description: every dimension, mass and limit in one place, so that
// docs/sim.md, the physics and the robot libraries agree. SI units; body frame x forward,
// y left, z up, origin at the chassis centre (= the centre of mass and of rotation).
#pragma once

namespace carbot::model {

// Chassis: a box on ~3 cm ground clearance; a sonar mast makes the robot 22 cm tall.
constexpr double kLength = 0.40;  ///< along x
constexpr double kWidth = 0.35;   ///< along y
constexpr double kChassisHeight = 0.14;
constexpr double kClearance = 0.03;    ///< floor to chassis bottom
constexpr double kTotalHeight = 0.22;  ///< floor to top of the sonar
constexpr double kChassisMass = 4.40;
constexpr double kChassisZ = kClearance + kChassisHeight / 2;  ///< chassis centre above floor

// Two driven wheels on the centre line, front and rear, each steerable through +-100 degrees.
constexpr double kWheelOffset = 0.13;  ///< |x| of each wheel
constexpr double kWheelRadius = 0.04;
constexpr double kWheelWidth = 0.03;
constexpr double kWheelMass = 0.15;
constexpr double kSteerStop = 1.75;   ///< rad, mechanical stop either way
constexpr double kSteerGain = 25.0;   ///< 1/s, steering servo P gain
constexpr double kSteerRate = 8.0;    ///< rad/s, steering servo rate limit
constexpr double kSteerTorque = 4.0;  ///< N m
constexpr double kDriveTorque = 0.8;  ///< N m per wheel
constexpr double kTopSpeed = 0.31;    ///< m/s, wheel ground speed limit

// Two frictionless caster balls left and right keep it level.
constexpr double kCasterY = 0.14;
constexpr double kCasterRadius = 0.03;

// Total mass: chassis + 2 wheels = 4.7 kg.
constexpr double kMass = kChassisMass + 2 * kWheelMass;

// Front bumper: a sensor-only slab across the whole front, corners included.
constexpr double kBumperDepth = 0.03;
constexpr double kBumperWidth = kWidth + 0.02;
constexpr double kBumperHeight = 0.10;

// Ultrasonic range finder on a turnable mount on top of the chassis, front half.
constexpr double kSonarX = 0.10;
constexpr double kSonarZ = 0.20;     ///< above the floor
constexpr double kSonarRange = 4.0;  ///< m; "no echo" reads as this
constexpr double kSonarMinRange = 0.02;
constexpr double kSonarHalfBeam = 0.13;  ///< rad (~7.5 deg): the fan spans +-this
constexpr int kSonarRays = 5;
constexpr double kSonarMaxIncidence = 0.87;                 ///< rad (~50 deg): beyond this no echo returns
constexpr double kSonarMountStop = 3.14159265358979323846;  ///< the mount turns +-180 deg
constexpr double kSonarMountRate = 6.0;                     ///< rad/s, mount servo
/// The mast the sonar sits on: a 6 cm square post from the chassis top to the robot's full
/// height, above the sonar's position. Another robot's sonar sees it (the chassis is below the beam).
constexpr double kMastSize = 0.06;

// Two downward infrared line sensors just behind the bumper.
constexpr double kIrX = 0.17;
constexpr double kIrY = 0.035;  ///< |y| of each; 7 cm apart

// Gripper: items within reach of this point (in front of the bumper) can be picked up.
constexpr double kGripX = kLength / 2 + kBumperDepth + 0.06;
constexpr double kGripReach = 0.10;

}  // namespace carbot::model
