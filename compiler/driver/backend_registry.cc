#include "backend_registry.h"

#include "c_backend.h"
#include "chart_backend.h"
#include "cpp_backend.h"
#include "dot_backend.h"
#include "json_backend.h"

namespace gfec {

namespace {

struct Entry {
  const char *name;
  std::unique_ptr<Backend> (*make)();
};

// Back ends register here as they land; the driver reports an unknown --emit with this list.
const Entry kBackends[] = {
    {"c", make_c_backend},        // the GFE-style C engine of an sfc or fsm (docs/c-engine.md)
    {"cpp", make_cpp_backend},    // a plan's wiring against the afp runtime (docs/plans.md)
    {"toolbox-skeleton", make_toolbox_skeleton_backend},  // a toolbox's C++ classes to fill in (docs/toolbox.md)
    {"json", make_json_backend},  // the validated model for tools (docs/model-json.md)
    {"dot", make_dot_backend},    // a picture in Graphviz DOT
    {"svg", make_svg_backend},    // the same picture rendered by Graphviz's dot
    {"chart", make_chart_backend},  // chart text, e.g. a converted ALICA plan (docs/alica.md)
};

} // namespace

std::unique_ptr<Backend> make_backend(std::string_view name) {
  for (const auto &e : kBackends)
    if (e.name && name == e.name) return e.make();
  return nullptr;
}

std::vector<std::string> backend_names() {
  std::vector<std::string> names;
  for (const auto &e : kBackends)
    if (e.name) names.emplace_back(e.name);
  return names;
}

} // namespace gfec
