#include "recording.h"

#include "chart_nodes.h"

#include <algorithm>
#include <utility>

namespace gfec::viewer {

namespace {

/// The rows of the instances that the places of outline chart `c` run (its own rows are
/// rows[first, ...)), each instance's rows followed by its own instances'.
void instance_rows(const ChartOutline &outline, const ChartOutline::Chart &c, const std::string &path,
                   const std::string &prefix, std::size_t first, std::vector<Row> &rows,
                   std::vector<Instance> &instances) {
  for (std::size_t i = 0; i < c.places.size(); ++i) {
    const int runs = c.places[i].runs;
    if (runs < 0 || static_cast<std::size_t>(runs) >= outline.charts.size()) continue;
    const ChartOutline::Chart &sub = outline.charts[static_cast<std::size_t>(runs)];
    Instance in;
    in.path = path.empty() ? c.places[i].name : path + "." + c.places[i].name;
    in.chart = sub.name;
    in.first = rows.size();
    in.count = sub.places.size();
    in.parent_row = first + i;
    const std::string inner = chart_nodes::instance_prefix(prefix, i);
    for (std::size_t q = 0; q < sub.places.size(); ++q)
      rows.push_back(
          {in.path + "/" + sub.places[q].name, chart_nodes::place(inner, q), sub.places[q].terminal, in.path, -1});
    instances.push_back(in);
    instance_rows(outline, sub, in.path, inner, in.first, rows, instances);
  }
}

}  // namespace

const char *robot_colour(std::size_t i) {
  static const char *const kRobots[] = {"#1f6fd1", "#7b4fc9", "#16a3a3", "#a0522d",
                                        "#d6409f", "#6b6b6b", "#26262b", "#3a7d1a"};
  return kRobots[i % (sizeof kRobots / sizeof kRobots[0])];
}

void outline_rows(const ChartOutline &outline, std::vector<Row> &rows, std::vector<Instance> &instances) {
  if (outline.charts.empty()) return;
  const ChartOutline::Chart &c = outline.charts.front();
  const std::size_t first = rows.size();
  for (std::size_t i = 0; i < c.places.size(); ++i)
    rows.push_back({c.places[i].name, chart_nodes::place("", i), c.places[i].terminal, "", -1});
  instance_rows(outline, c, "", "", first, rows, instances);
}

RecordingBuilder::RecordingBuilder(std::string tool, std::string chart_name, std::string chart_kind,
                                   std::string chart_file, double period)
    : tool_(std::move(tool)),
      chart_({{"name", std::move(chart_name)}, {"kind", std::move(chart_kind)}, {"file", std::move(chart_file)}}),
      period_(period) {}

void RecordingBuilder::set_title(std::string title, std::string subtitle) {
  title_ = std::move(title);
  subtitle_ = std::move(subtitle);
}

void RecordingBuilder::set_picture(std::string svg, std::string note) {
  svg_ = std::move(svg);
  svg_note_ = std::move(note);
}

void RecordingBuilder::add_row(Row row) {
  nlohmann::json j = {{"name", std::move(row.name)}, {"node", std::move(row.node)}, {"terminal", row.terminal}};
  if (!row.group.empty()) j["group"] = std::move(row.group);
  if (row.robot >= 0) j["robot"] = row.robot;
  rows_.push_back(std::move(j));
}

void RecordingBuilder::add_instance(const Instance &in) {
  instances_.push_back({{"path", in.path}, {"chart", in.chart}, {"first", in.first}, {"count", in.count}});
}

std::size_t RecordingBuilder::add_robot(std::string name, std::string colour, std::size_t first, std::size_t count) {
  Robot r;
  r.fields = {{"name", std::move(name)}, {"colour", std::move(colour)}, {"first", first}, {"count", count}};
  robots_.push_back(std::move(r));
  return robots_.size() - 1;
}

void RecordingBuilder::add_tick(const std::vector<std::size_t> &active) { active_.record(frames_++, active); }

void RecordingBuilder::record_calls(long frame, const std::vector<std::string> &calls) { calls_.record(frame, calls); }

void RecordingBuilder::record_calls(std::size_t robot, long frame, const std::vector<std::string> &calls) {
  robots_.at(robot).calls.record(frame, calls);
}

void RecordingBuilder::record_status(long frame, const std::string &status) { status_.record(frame, status); }

void RecordingBuilder::record_status(std::size_t robot, long frame, const std::string &status) {
  robots_.at(robot).status.record(frame, status);
}

std::size_t RecordingBuilder::add_var(std::string type, std::string name, std::string initial) {
  Var v;
  v.fields = {{"type", std::move(type)}, {"name", std::move(name)}, {"init", std::move(initial)}};
  vars_.push_back(std::move(v));
  return vars_.size() - 1;
}

void RecordingBuilder::record_var(std::size_t var, long frame, const std::string &value) {
  vars_.at(var).values.record(frame, value);
}

void RecordingBuilder::add_event(long frame, std::string kind, std::string text) {
  events_.emplace_back(frame, std::move(kind), std::move(text));
}

void RecordingBuilder::add_fired(long frame, std::string node, std::string text) {
  fired_.push_back({frame, std::move(node), std::move(text)});
}

void RecordingBuilder::set(const std::string &key, nlohmann::json value) { extra_[key] = std::move(value); }

void RecordingBuilder::set_robot(std::size_t robot, const std::string &key, nlohmann::json value) {
  robots_.at(robot).fields[key] = std::move(value);
}

nlohmann::json RecordingBuilder::data() const {
  using nlohmann::json;
  auto events = events_;
  std::stable_sort(events.begin(), events.end(),
                   [](const auto &a, const auto &b) { return std::get<0>(a) < std::get<0>(b); });
  json event_list = json::array();
  for (const auto &[k, kind, text] : events) event_list.push_back({k, kind, text});
  json doc = {
      {"format", 1},
      {"tool", tool_},
      {"title", title_},
      {"subtitle", subtitle_},
      {"chart", chart_},
      {"period", period_},
      {"frames", frames_},
      {"svg", svg_},
      {"svg_note", svg_note_},
      {"rows", rows_},
      {"instances", instances_},
      {"active", active_.json()},
      // Several robots: each robot's calls (below); the run's own list is then empty.
      {"calls", robots_.empty() ? calls_.json() : json(nullptr)},
      {"events", event_list},
      {"fired", fired_},
      {"status", status_.json()},
      {"world", nullptr},
  };
  if (!robots_.empty()) {
    json list = json::array();
    for (const Robot &r : robots_) {
      json j = r.fields;
      j["calls"] = r.calls.json();
      j["status"] = r.status.json();
      list.push_back(std::move(j));
    }
    doc["robots"] = std::move(list);
  }
  json vars = json::array();
  for (const Var &v : vars_) {
    json j = v.fields;
    j["values"] = v.values.json();
    vars.push_back(std::move(j));
  }
  doc["vars"] = std::move(vars);
  doc["vars_note"] = vars_note_;
  for (const auto &[key, value] : extra_) doc[key] = value;
  return doc;
}

nlohmann::json RecordingBuilder::since(const Cursor &c) const {
  using nlohmann::json;
  auto texts = [&](std::size_t i) { return i < c.texts.size() ? c.texts[i] : std::size_t{0}; };
  json events = json::array();
  for (std::size_t i = c.events; i < events_.size(); ++i) {
    const auto &[k, kind, text] = events_[i];
    events.push_back({k, kind, text});
  }
  // A plan's supervisors fire at the frame being added (a live monitor adds them so): a page
  // holding frames before c.frames lacks those from c.frames on.
  json fired = json::array();
  for (const json &f : fired_)
    if (f[0].get<long>() >= c.frames) fired.push_back(f);
  json doc = {{"frames", frames_},
              {"active", active_.since(c.frames)},
              {"fired", fired},
              {"status", status_.since(c.frames)},
              {"calls", robots_.empty() ? calls_.since(c.frames, texts(0)) : json(nullptr)},
              {"events", events},
              {"events_total", events_.size()}};
  if (!robots_.empty()) {
    json list = json::array();
    for (std::size_t r = 0; r < robots_.size(); ++r)
      list.push_back(
          {{"calls", robots_[r].calls.since(c.frames, texts(r + 1))}, {"status", robots_[r].status.since(c.frames)}});
    doc["robots"] = std::move(list);
  }
  return doc;
}

}  // namespace gfec::viewer
