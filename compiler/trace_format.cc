#include "trace_format.h"

#include <fmt/format.h>

namespace gfec::trace {

namespace {

void describe(const model::Model &model, const model::Chart &chart, std::string &text) {
  text += fmt::format("{} {} {}\n", chart.kind == model::Chart::Kind::Fsm ? "fsm" : "sfc", chart.name, chart.team);
  for (const auto &p : chart.places) text += fmt::format("place {}{}\n", p.name.str(), p.runs ? " runs" : "");
  for (const auto &t : chart.transitions) text += fmt::format("transition {}\n", t.name.str());
  (void)model;
}

/// The instances below `chart`, as the C engine numbers them (EngineContext::each_instance).
void instances(const model::Model &model, const model::Chart &chart, const std::string &prefix, Layout &layout,
               std::string &text) {
  for (const auto &p : chart.places) {
    if (!p.runs) continue;
    const model::Chart &sub = model.charts.at(p.runs);
    InstanceSlots in;
    in.path = prefix + p.name.str();
    in.chart = p.runs;
    in.first = layout.values;
    in.places = sub.places.size();
    layout.values += in.places;
    text += "instance " + in.path + "\n";
    describe(model, sub, text);
    layout.instances.push_back(in);
    instances(model, sub, in.path + ".", layout, text);
  }
}

}  // namespace

Layout layout_of(const model::Model &model, model::ChartId id) {
  const model::Chart &chart = model.charts.at(id);
  Layout layout;
  layout.chart = id;
  layout.fsm = chart.kind == model::Chart::Kind::Fsm;
  layout.places = chart.places.size();
  layout.values = layout.places;
  std::string text = fmt::format("gfec trace {}\n", kVersion);
  describe(model, chart, text);
  instances(model, chart, "", layout, text);
  if (layout.fsm) layout.status = static_cast<std::ptrdiff_t>(layout.values++);
  if (chart.team > 0) {
    layout.agent = static_cast<std::ptrdiff_t>(layout.values++);
    layout.team = static_cast<std::size_t>(chart.team);
    layout.values += layout.team;
  }
  std::uint32_t h = 2166136261u;
  for (unsigned char ch : text) h = (h ^ ch) * 16777619u;
  layout.fingerprint = h;
  return layout;
}

std::uint32_t crc32(const std::uint8_t *data, std::size_t n) {
  std::uint32_t crc = 0xFFFFFFFFu;
  for (std::size_t i = 0; i < n; ++i) {
    crc ^= data[i];
    for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
  }
  return ~crc;
}

}  // namespace gfec::trace
