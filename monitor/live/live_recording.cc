#include "live_recording.h"

#include <algorithm>
#include <string>
#include <utility>

namespace gfec::live {

namespace {

std::string robot_name(std::size_t i) { return "robot " + std::to_string(i); }

}  // namespace

LiveRecording::LiveRecording(const LiveChart &chart, std::size_t robots)
    : rec_("gfec monitor", chart.name, chart.kind, chart.file, chart.period), robots_(std::max<std::size_t>(1, robots)),
      per_(chart.rows.size()), status_(robots_, "running"), last_tick_(robots_, -1), started_(robots_, false),
      done_(robots_, false), last_rows_(robots_) {
  rec_.set_picture(chart.svg, chart.svg_note);
  rec_.set_title(chart.name + " (" + chart.kind + "): live", "gfec monitor " + chart.file + " \u00b7 " + chart.source);
  plan_ = chart.kind == "plan";
  period_ = chart.period;
  level_rows_ = chart.level_rows;
  supervisor_nodes_ = chart.supervisor_nodes;
  for (std::size_t row : level_rows_) level_paths_.push_back(row < chart.rows.size() ? chart.rows[row].group : "");
  if (robots_ == 1) {
    for (const viewer::Row &row : chart.rows) rec_.add_row(row);
    for (const viewer::Instance &in : chart.instances) rec_.add_instance(in);
  } else {
    per_ = 0;
    for (const viewer::Row &row : chart.rows)
      if (row.group.empty()) ++per_;
    for (std::size_t i = 0; i < robots_; ++i) {
      for (const viewer::Row &row : chart.rows)
        if (row.group.empty())
          rec_.add_row({robot_name(i) + "/" + row.name, row.node, row.terminal, robot_name(i), static_cast<int>(i)});
      rec_.add_robot(robot_name(i), viewer::robot_colour(i), i * per_, per_);
    }
  }
}

void LiveRecording::started(std::size_t robot) {
  std::lock_guard<std::mutex> lock(m_);
  if (robot >= robots_) return;
  started_[robot] = true;
  if (state_ == "waiting") state_ = "live";
}

void LiveRecording::tick(const monitor::DecodedTick &t) {
  std::lock_guard<std::mutex> lock(m_);
  if (t.robot >= robots_) return;
  started_[t.robot] = true;
  if (state_ == "waiting") state_ = "live";
  silent_ = 0;
  // One engine: every tick it hands on is the next frame, even an engine started again (its
  // ticks from 1 again; the decoder reports that as a loss).
  if (robots_ == 1) {
    last_tick_[0] = t.tick;
    add_frame(t.tick, {&t});
    return;
  }
  // A team's tick at or before the last frame's comes too late to be shown (a robot that joined late).
  if (static_cast<std::int64_t>(t.tick) <= last_frame_tick_ || static_cast<std::int64_t>(t.tick) <= last_tick_[t.robot])
    return;
  last_tick_[t.robot] = t.tick;
  Pending &p = pending_[t.tick];
  if (p.has.empty()) {
    p.has.assign(robots_, false);
    p.ticks.resize(robots_);
  }
  p.has[t.robot] = true;
  p.ticks[t.robot] = t;
  if (!t.status.empty() && t.status != "running") done_[t.robot] = true;
  flush_team(false);
}

void LiveRecording::event(const monitor::DecodedPlanEvent &e) {
  using trace::PlanRecord;
  std::lock_guard<std::mutex> lock(m_);
  if (state_ == "waiting") state_ = "live";
  silent_ = 0;
  const std::uint32_t period_ms = std::max<std::uint32_t>(1, static_cast<std::uint32_t>(period_ * 1000 + 0.5));
  const std::int64_t tick = e.ms / period_ms + 1;
  std::vector<std::size_t> on;
  for (std::size_t level = 0; level < e.active.size() && level < level_rows_.size(); ++level)
    if (e.active[level] > 0) on.push_back(level_rows_[level] + e.active[level] - 1);
  std::sort(on.begin(), on.end());
  // The frames between the last event and this one: the last event's state, which held. Not
  // across a loss (what ran then is unknown: the tick numbers jump) nor a plan time that went
  // back (the trace started again), and at most an hour of frames.
  constexpr std::int64_t kMaxFill = 360000;
  if (rec_.frames() > 0 && !plan_gap_ && tick > last_frame_tick_ + 1 && tick - last_frame_tick_ <= kMaxFill)
    for (std::int64_t t = last_frame_tick_ + 1; t < tick; ++t) rec_.add_tick(last_rows_[0]);
  const long frame = rec_.frames();
  tick_offset_.record(frame, static_cast<long>(tick) - frame - 1);
  last_frame_tick_ = tick;
  plan_gap_ = false;
  // The first frame, or the plan run again after it ended (a program that starts it anew).
  if (frame == 0 || (status_[0] != "running" && e.record != PlanRecord::Ended)) {
    status_[0] = "running";
    rec_.record_status(frame, "running");
  }
  switch (e.record) {
  case PlanRecord::Started: rec_.add_event(frame, "actor", e.text); break;
  case PlanRecord::Finished: rec_.add_event(frame, "state", e.text); break;
  case PlanRecord::Interrupted:
    rec_.add_event(frame, "supervisor", e.text);
    // The picture is the plan's own: a sub-plan's supervisor is said, not lit.
    rec_.add_fired(
        frame, e.level == 0 && e.supervisor < supervisor_nodes_.size() ? supervisor_nodes_[e.supervisor] : "", e.text);
    break;
  case PlanRecord::Failed: rec_.add_event(frame, "fail", e.text); break;
  case PlanRecord::Ended:
    rec_.add_event(frame, "status", e.text);
    if (e.level == 0) {
      status_[0] = e.status;
      rec_.record_status(frame, e.status);
    }
    break;
  case PlanRecord::State: break;
  }
  last_rows_[0] = on;
  rec_.add_tick(on);
}

void LiveRecording::flush_team(bool all) {
  while (!pending_.empty()) {
    auto oldest = pending_.begin();
    const std::uint32_t tick = oldest->first;
    bool ready = all || pending_.rbegin()->first - tick >= kTeamSlack;
    if (!ready) {
      // Every robot has sent this tick, or a later one (this one was lost), or has ended. Robots
      // not heard from yet are waited for too (their first frames may just be late).
      ready = true;
      for (std::size_t r = 0; r < robots_; ++r)
        if (!done_[r] && !oldest->second.has[r] && last_tick_[r] < static_cast<std::int64_t>(tick)) ready = false;
    }
    if (!ready) return;
    std::vector<const monitor::DecodedTick *> shown(robots_, nullptr);
    for (std::size_t r = 0; r < robots_; ++r)
      if (oldest->second.has[r]) shown[r] = &oldest->second.ticks[r];
    add_frame(tick, shown);
    pending_.erase(oldest);
  }
}

void LiveRecording::add_frame(std::uint32_t tick, const std::vector<const monitor::DecodedTick *> &robots) {
  const long frame = rec_.frames();
  tick_offset_.record(frame, static_cast<long>(tick) - frame - 1);
  last_frame_tick_ = tick;
  std::vector<std::size_t> on;
  for (std::size_t r = 0; r < robots.size(); ++r) {
    const monitor::DecodedTick *t = robots[r];
    if (!t) {
      if (robots_ > 1) rec_.record_calls(r, frame, {});
      // An ended robot stays in its final state; a robot whose tick did not come shows none.
      if (done_[r] && static_cast<std::int64_t>(tick) > last_tick_[r])
        on.insert(on.end(), last_rows_[r].begin(), last_rows_[r].end());
      continue;
    }
    const std::size_t rows = robots_ == 1 ? per_ : std::min(per_, t->activation.size());
    last_rows_[r].clear();
    for (std::size_t i = 0; i < rows && i < t->activation.size(); ++i)
      if (t->activation[i] > 0) last_rows_[r].push_back(r * per_ + i);
    on.insert(on.end(), last_rows_[r].begin(), last_rows_[r].end());
    const std::string status = t->status.empty() ? "running" : t->status;
    if (status != status_[r]) rec_.add_event(frame, "status", robots_ == 1 ? status : robot_name(r) + ": " + status);
    status_[r] = status;
    if (robots_ == 1) {
      rec_.record_status(frame, status);
      rec_.record_calls(frame, t->calls);
    } else {
      rec_.record_status(r, frame, status);
      rec_.record_calls(r, frame, t->calls);
    }
  }
  if (robots_ > 1) {
    // The team's status: running while any robot runs, else the first robot's end.
    std::string team = "running";
    if (std::none_of(status_.begin(), status_.end(), [](const std::string &s) { return s == "running"; }))
      team = status_.front();
    rec_.record_status(frame, team);
  }
  std::sort(on.begin(), on.end());
  rec_.add_tick(on);
}

void LiveRecording::lost(std::size_t robot, std::uint64_t ticks_missing, const std::string &why) {
  std::lock_guard<std::mutex> lock(m_);
  lost_ticks_ += ticks_missing;
  ++losses_;
  last_loss_ = why;
  plan_gap_ = true;
  const std::string unit = plan_ ? "event" : "tick";
  std::string text = ticks_missing
                         ? std::to_string(ticks_missing) + " " + unit + (ticks_missing == 1 ? "" : "s") + " lost"
                         : unit + "s lost";
  if (robots_ > 1) text = robot_name(robot) + ": " + text;
  if (!why.empty()) text += ": " + why;
  // Before the next frame shown: the gap is between the last frame and it.
  rec_.add_event(rec_.frames(), "lost", text);
}

void LiveRecording::silent(double seconds) {
  std::lock_guard<std::mutex> lock(m_);
  silent_ = seconds;
}

void LiveRecording::ended(const std::string &why) {
  std::lock_guard<std::mutex> lock(m_);
  flush_team(true);
  state_ = "ended";
  ended_why_ = why;
  rec_.add_event(std::max(0L, rec_.frames() - 1), "note", "the stream ended: " + why);
}

nlohmann::json LiveRecording::link() const {
  return {{"state", state_},
          {"silent", silent_},
          {"lost_ticks", lost_ticks_},
          {"losses", losses_},
          {"last_loss", last_loss_},
          {"ended", ended_why_},
          {"waiting", pending_.size()},
          {"unit", plan_ ? "event" : "tick"}};
}

nlohmann::json LiveRecording::page_data() const {
  std::lock_guard<std::mutex> lock(m_);
  nlohmann::json d = rec_.data();
  d["ticks"] = tick_offset_.json();
  d["calls_note"] = plan_ ? "A plan's actors and supervisors are C++ classes of the toolbox: the trace carries "
                            "no calls; the events list their starts, finishes and interruptions."
                          : "";
  d["live"] = {{"update", "live"}, {"link", link()}};
  return d;
}

nlohmann::json LiveRecording::update(const viewer::RecordingBuilder::Cursor &cursor) const {
  std::lock_guard<std::mutex> lock(m_);
  nlohmann::json d = rec_.since(cursor);
  d["ticks"] = tick_offset_.since(cursor.frames);
  d["link"] = link();
  return d;
}

long LiveRecording::frames() const {
  std::lock_guard<std::mutex> lock(m_);
  return rec_.frames();
}

}  // namespace gfec::live
