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
  std::string text = ticks_missing ? std::to_string(ticks_missing) + " tick" + (ticks_missing == 1 ? "" : "s") + " lost"
                                   : "ticks lost";
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
  return {{"state", state_},         {"silent", silent_},   {"lost_ticks", lost_ticks_}, {"losses", losses_},
          {"last_loss", last_loss_}, {"ended", ended_why_}, {"waiting", pending_.size()}};
}

nlohmann::json LiveRecording::page_data() const {
  std::lock_guard<std::mutex> lock(m_);
  nlohmann::json d = rec_.data();
  d["ticks"] = tick_offset_.json();
  d["calls_note"] = "";
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
