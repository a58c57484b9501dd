#include "event_log.h"

namespace gfec::interp {

Layer layer_of(EventKind kind) {
  switch (kind) {
  case EventKind::Tick:
  case EventKind::Call:
  case EventKind::Av:
  case EventKind::State:
  case EventKind::Agent:
  case EventKind::Output: return Layer::Observable;
  case EventKind::Lost:
  case EventKind::Gained:
  case EventKind::Enabled: return Layer::Hooks;
  default: return Layer::Explanation;
  }
}

std::string EventLog::render(const RenderOptions &options) const {
  std::string out;
  for (const Event &e : events_) {
    Layer layer = layer_of(e.kind);
    if (layer == Layer::Hooks && !options.hooks) continue;
    if (layer == Layer::Explanation && !options.explain) continue;
    if (options.indent) out.append(static_cast<std::size_t>(2 * e.depth), ' ');
    out += e.text;
    out += '\n';
  }
  return out;
}

}  // namespace gfec::interp
