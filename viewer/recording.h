// The run viewer's recording (docs/viewer.md "The recording"): what a page showing a run reads.
// One builder for every tool that records a run (gfec run --html, carbot-sim --html; next a live
// monitor and an editor preview). It takes plain data - names, node ids, tick rows - and never
// the compiler's model: carbot-sim, which does not link the compiler, builds with it too.
#pragma once

#include "viewer_page.h"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <map>
#include <string>
#include <tuple>
#include <vector>

namespace gfec::viewer {

/// A line of the timeline: a place, state or actor, lit in the chart's picture by its node id.
struct Row {
  std::string name;       ///< "Grab", "Search/Grab" (an instance's), "robot 1/Grab"
  std::string node;       ///< its node in the picture (support/chart_nodes.h); "" for none
  bool terminal = false;  ///< an fsm's success or failure state
  std::string group;      ///< the instance path or robot name it is shown under ("" for none)
  int robot = -1;         ///< several robots: whose row (-1: not a team recording)
};

/// Robot `i`'s colour in every page and picture of several robots (a lit state, a path, a badge).
const char *robot_colour(std::size_t i);

/// A sub-chart instance (docs/c-engine.md "Sub-charts"): rows [first, first + count).
struct Instance {
  std::string path;   ///< "Patrol", "Search.Grab"
  std::string chart;  ///< the chart it runs
  std::size_t first = 0, count = 0;
  std::size_t parent_row = 0;  ///< the row of the place that runs it
};

/// A chart and the charts its places run, as plain data: what the timeline's rows are made of.
struct ChartOutline {
  struct Place {
    std::string name;
    bool terminal = false;
    int runs = -1;  ///< the index in `charts` of the chart this place runs, or -1
  };
  struct Chart {
    std::string name;
    std::vector<Place> places;
  };
  std::vector<Chart> charts;  ///< charts[0] is the chart the run runs
};

/// The rows of charts[0] and of every sub-chart instance, depth first in declaration order (the
/// order of gfec run's `av` lines, of the engine's instances and of the picture's frames): an
/// instance's row is named "path/place", grouped under its path, its node prefixed as the DOT
/// back end prefixes that instance's nodes. Appends to `rows` and `instances`.
void outline_rows(const ChartOutline &outline, std::vector<Row> &rows, std::vector<Instance> &instances);

/// Builds a recording a tick at a time: describe the chart and its picture, then append ticks
/// as they come (a live monitor appends while the run goes on), then take data() - at the end,
/// or at any tick for a page of the run so far.
class RecordingBuilder {
public:
  /// `tool` names the recorder ("gfec run"); `period` is the seconds between ticks.
  RecordingBuilder(std::string tool, std::string chart_name, std::string chart_kind, std::string chart_file,
                   double period);

  void set_title(std::string title, std::string subtitle);
  /// The chart's picture (gfec's SVG), or "" and a note saying why there is none.
  void set_picture(std::string svg, std::string note);
  void add_row(Row row);
  void add_instance(const Instance &instance);
  /// Several robots (docs/viewer.md "Several robots"): robot `return`, whose rows are
  /// [first, first + count). A recording with robots keeps calls and status per robot.
  std::size_t add_robot(std::string name, std::string colour, std::size_t first, std::size_t count);

  /// Appends the next tick (frame frames()): the rows active after it.
  void add_tick(const std::vector<std::size_t> &active);
  /// The calls a tick made, as texts ("Move(2) = true", a nested call indented).
  void record_calls(long frame, const std::vector<std::string> &calls);
  void record_calls(std::size_t robot, long frame, const std::vector<std::string> &calls);
  /// The run's (or a robot's) status from `frame` on: "running", "succeeded", ...
  void record_status(long frame, const std::string &status);
  void record_status(std::size_t robot, long frame, const std::string &status);
  /// A var of the chart (docs/viewer.md "Vars"): its declaration as the picture's note gives it
  /// ("int", "parts", "0"); returns its index for record_var.
  std::size_t add_var(std::string type, std::string name, std::string initial);
  /// Var `var`'s value after tick `frame`, as the log prints it; it holds until the next one.
  /// A var never recorded shows its initial value; a recorder that does not know the values
  /// (carbot-sim) records none and says so with set_vars_note.
  void record_var(std::size_t var, long frame, const std::string &value);
  void set_vars_note(std::string note) { vars_note_ = std::move(note); }
  /// An entry of the events list; events are listed in frame order, those of one frame as added.
  void add_event(long frame, std::string kind, std::string text);
  /// A plan's supervisor that fired: its node, lit for a second, and what it was. A live
  /// recording adds it at the frame it is about to add (since() hands on those from its cursor).
  void add_fired(long frame, std::string node, std::string text);
  /// A part of the recording this builder does not know (a world, a path, items): kept as given.
  void set(const std::string &key, nlohmann::json value);
  void set_robot(std::size_t robot, const std::string &key, nlohmann::json value);

  long frames() const { return frames_; }
  /// The recording so far, as docs/viewer.md describes it; viewer::page() makes it a page.
  nlohmann::json data() const;

  /// What a page holding the recording up to a point lacks (docs/viewer.md "Live mode").
  struct Cursor {
    long frames = 0;                 ///< the frames it holds
    std::size_t events = 0;          ///< the events it holds, in the order they were added
    std::vector<std::size_t> texts;  ///< the call texts it holds: the run's, then each robot's
  };
  /// The frames from cursor.frames on (active, status, calls, per robot too), the events from
  /// number cursor.events on and the call texts the page lacks; `frames` is the new count.
  /// Nothing of a frame before `frames()` changes once it is added, so the page appends.
  nlohmann::json since(const Cursor &cursor) const;

private:
  struct Robot {
    nlohmann::json fields;
    CallRecorder calls;
    ChangeList status;
  };
  std::string tool_, title_, subtitle_, svg_, svg_note_;
  nlohmann::json chart_;
  double period_;
  long frames_ = 0;
  nlohmann::json rows_ = nlohmann::json::array(), instances_ = nlohmann::json::array();
  ChangeList active_, status_;
  CallRecorder calls_;
  std::vector<std::tuple<long, std::string, std::string>> events_;
  nlohmann::json fired_ = nlohmann::json::array();
  std::vector<Robot> robots_;
  struct Var {
    nlohmann::json fields;
    ChangeList values;
  };
  std::vector<Var> vars_;
  std::string vars_note_;
  std::map<std::string, nlohmann::json> extra_;
};

}  // namespace gfec::viewer
