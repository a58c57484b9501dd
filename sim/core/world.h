// The world a Carbot lives in, as read from a world file (docs/sim.md, "World files").
// Plain data: loading checks every field, the simulation only reads it.
#pragma once

#include <stdexcept>
#include <cstddef>
#include <string>
#include <vector>

namespace carbot {

/// A point or vector on the floor, metres; x right, y up (the floor is centred at the origin).
struct Vec2 {
  double x = 0;
  double y = 0;
};

/// The painted line: a polyline of `width` metres, closed (a loop) or open.
struct Line {
  double width = 0.05;
  bool closed = false;
  std::vector<Vec2> points;  ///< empty: the world has no line
};

/// A wall: a thin vertical slab from `from` to `to`.
struct Wall {
  Vec2 from, to;
  double thickness = 0.05;
  double height = 0.30;
};

/// A box obstacle: axis-aligned, `size` = [w (along x), d (along y)] metres.
struct Box {
  Vec2 center;
  Vec2 size;
  double height = 0.30;
};

/// An item the robot can pick up, and where it belongs.
struct Item {
  std::string name;
  Vec2 at;
  Vec2 destination;
};

/// Something that happens at a time: the escape button is pressed, or a carried item drops.
struct Event {
  enum class Kind { PressEscape, DropItem };
  Kind kind = Kind::PressEscape;
  double at = 0;        ///< seconds of simulated time
  std::string item;     ///< DropItem: the item's name
  bool has_to = false;  ///< DropItem: lands at `to` instead of under the gripper
  Vec2 to;
};

/// A robot's pose at the start.
struct Start {
  Vec2 position;
  double heading_deg = 0;  ///< counter-clockwise from +x
};

/// A whole world file.
struct World {
  std::string name;  ///< the file's stem, for titles ("oval")
  std::string path;  ///< as given, for messages
  Vec2 size{4, 3};   ///< floor [w, h], centred at the origin
  Line line;
  std::vector<Wall> walls;
  std::vector<Box> boxes;
  std::vector<Item> items;
  Start start;                ///< the first robot's start (= robots[0])
  std::vector<Start> robots;  ///< every robot's start, in robot (agent) order; at least one
  std::vector<Event> events;
};

/// The most robots a world may hold (the robot libraries keep per-robot state for this many).
constexpr int kMaxRobots = 8;

/// A world file is at most this many bytes (read without blocking, and only a regular file:
/// docs/security.md), ...
constexpr std::size_t kMaxWorldBytes = 4u << 20;
/// ... and holds at most this many walls, boxes and items in all, line points and events: each
/// wall, box and item is tested against the robot's sensors and bumpers in every physics step,
/// so the run's cost grows with them (100,000 walls took 6 to 9 s per simulated second).
constexpr std::size_t kMaxWorldObstacles = 1000;
constexpr std::size_t kMaxLinePoints = 10000;
constexpr std::size_t kMaxWorldEvents = 10000;

/// A world file that cannot be used; what() is "FILE: FIELD: what is wrong".
struct WorldError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Reads and checks a world file. Throws WorldError naming the file and the field.
World load_world(const std::string& path);

/// Parses world text (for tests); `path` only names it in messages.
World parse_world(const std::string& text, const std::string& path);

}  // namespace carbot
