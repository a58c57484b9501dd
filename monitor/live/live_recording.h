// The live page's recording (docs/live.md "The live page"): a RunSink that appends each decoded
// tick to the run viewer's recording as it arrives, and what the page's HTTP handlers read of it.
// The monitor's reading thread writes, the HTTP server's threads read: one mutex guards it all.
#pragma once

#include "plan_sink.h"
#include "recording.h"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <cstdint>
#include <map>
#include <mutex>
#include <string>
#include <vector>

namespace gfec::live {

/// The chart as the page shows it: what the monitor knows of it before any tick arrives.
struct LiveChart {
  std::string name, kind, file;  ///< kind: "sfc", "fsm" or "plan"
  double period = 0.01;          ///< seconds between ticks (the chart's period; a plan's frame)
  /// Its rows and sub-chart instances (viewer::outline_rows): the order of DecodedTick::activation.
  std::vector<viewer::Row> rows;
  std::vector<viewer::Instance> instances;
  std::string svg, svg_note;  ///< the picture, or "" and why there is none
  std::string source;         ///< where the stream comes from ("stdin", "tcp 127.0.0.1:5000"): the subtitle
  /// A plan: by level (trace::PlanLayout::levels), the row of the level's first actor - the rows
  /// are the plan's actors, then each sub-plan level's, grouped by its path; and the picture's
  /// node of each of the plan's own supervisors, in the trace's order (globals, then each actor's).
  std::vector<std::size_t> level_rows;
  std::vector<std::string> supervisor_nodes;
};

/// Robots of a team stream their ticks separately; a frame of the page is one tick of every
/// robot. A robot's tick is held back until every other robot has sent that tick (or a later
/// one), or until it is this many ticks behind the newest: then the frame is shown without it.
constexpr std::uint32_t kTeamSlack = 32;

/// A chart's ticks (tick) or a plan's events (event) become the page's frames. A plan's frame is
/// `period` of plan time: an event at t ms is tick t / period + 1, the frames between two events
/// hold the state of the first (the page's time axis is the plan's), and an event at the tick of
/// the last frame gets a frame of its own, with the same tick, so that every event's state shows.
class LiveRecording final : public monitor::PlanSink {
public:
  /// `robots` > 1: a team, each robot's rows under its name and in its colour. A team shows the
  /// chart's own rows only (a team machine is never a sub-chart; its instances are left out).
  LiveRecording(const LiveChart &chart, std::size_t robots = 1);

  void started(std::size_t robot) override;
  void tick(const monitor::DecodedTick &t) override;
  void event(const monitor::DecodedPlanEvent &e) override;
  void lost(std::size_t robot, std::uint64_t ticks_missing, const std::string &why) override;
  void silent(double seconds) override;
  void ended(const std::string &why) override;

  /// The whole recording so far with its `live` section: the page's data when it is loaded.
  nlohmann::json page_data() const;
  /// What a page holding `cursor` lacks, and the link's state (docs/viewer.md "Live mode").
  nlohmann::json update(const viewer::RecordingBuilder::Cursor &cursor) const;
  long frames() const;

private:
  struct Pending {
    std::vector<bool> has;
    std::vector<monitor::DecodedTick> ticks;
  };
  void add_frame(std::uint32_t tick, const std::vector<const monitor::DecodedTick *> &robots);
  void flush_team(bool all);
  nlohmann::json link() const;

  mutable std::mutex m_;
  viewer::RecordingBuilder rec_;
  std::size_t robots_, per_;  ///< robots, and rows per robot
  /// The engine's tick number of each frame, as a change list of (tick - frame - 1): the ticks
  /// of a stream joined late or with gaps (lost ticks) are not frames 0, 1, 2 ...
  viewer::ChangeList tick_offset_;
  std::vector<std::string> status_;      ///< each robot's last status ("running")
  std::vector<std::int64_t> last_tick_;  ///< each robot's last tick handed on (-1: none)
  std::vector<bool> started_;
  /// A team's robot whose engine ended (succeeded, failed): it sends no more ticks, so it is not
  /// waited for, and its last activation - final, so exact - shows in the frames after.
  std::vector<bool> done_;
  std::vector<std::vector<std::size_t>> last_rows_;
  std::map<std::uint32_t, Pending> pending_;  ///< a team's ticks not yet a frame
  std::int64_t last_frame_tick_ = -1;
  std::string state_ = "waiting";  ///< waiting, live, ended
  double silent_ = 0;
  std::uint64_t lost_ticks_ = 0, losses_ = 0;
  std::string last_loss_, ended_why_;
  // A plan's.
  bool plan_ = false;
  double period_ = 0.01;
  std::vector<std::size_t> level_rows_;
  std::vector<std::string> supervisor_nodes_;
  std::vector<std::string> level_paths_;  ///< by level: "" for the plan, its path for a sub-plan
  bool plan_gap_ = false;                 ///< events were lost since the last frame: no fill
};

}  // namespace gfec::live
