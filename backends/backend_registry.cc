#include "backend_registry.h"

#include "c_backend.h"
#include "c_engine_options.h"
#include "chart_backend.h"
#include "cpp_backend.h"
#include "dot_backend.h"
#include "json_backend.h"

#include <fmt/format.h>

namespace gfec {

namespace {

using pipeline::kCharts;
using pipeline::kPlan;
using pipeline::kToolbox;

// Back ends register here as they land, with what they accept and write.
const std::vector<BackendInfo> kBackends = {
    {"c", kCharts, ".c", ".h", "a C99 engine: the default for an sfc or fsm", "docs/c-engine.md", make_c_backend,
     c_backend::make_c_engine_option_group},
    {"cpp", kPlan, ".cpp", ".hpp", "a plan's wiring against the afp runtime: the default for a plan", "docs/plans.md",
     make_cpp_backend},
    {"toolbox-skeleton", kToolbox, ".hpp", ".cpp", "a toolbox's C++ classes to fill in", "docs/toolbox.md",
     make_toolbox_skeleton_backend},
    {"json", kCharts | kPlan, ".json", "", "the validated model, for tools", "docs/model-json.md", make_json_backend},
    {"dot", kCharts | kPlan, ".dot", "", "a picture in Graphviz DOT", "docs/cli.md", make_dot_backend},
    {"svg", kCharts | kPlan, ".svg", "", "the same picture rendered by Graphviz's dot (needs dot on PATH)",
     "docs/cli.md", make_svg_backend},
    {"chart", kCharts, ".sfc", "", "chart text, e.g. a converted ALICA plan", "docs/alica.md", make_chart_backend},
};

}  // namespace

const std::vector<BackendInfo> &backends() { return kBackends; }

const BackendInfo *find_backend(std::string_view name) {
  for (const auto &b : kBackends)
    if (name == b.name) return &b;
  return nullptr;
}

const BackendInfo &default_backend(unsigned kind) {
  // The first back end that accepts the kind: the table lists each kind's usual one first.
  for (const auto &b : kBackends)
    if (b.accepts_kind(kind)) return b;
  return kBackends.front();
}

std::string backend_names_list() {
  std::string names;
  for (const auto &b : kBackends) names += fmt::format("{}{}", names.empty() ? "" : ", ", b.name);
  return names;
}

std::string accepted_kinds(const BackendInfo &b) { return pipeline::kinds_text(b.accepts, "and"); }

std::string backends_help() {
  std::string s = "Back ends (--emit=NAME; without it an sfc or fsm gives a C engine, a plan C++ wiring):\n";
  for (const auto &b : kBackends)
    s += fmt::format("  {:<18} {}\n  {:<18} compiles {}; writes {}{}{}; {}\n", b.name, b.summary, "", accepted_kinds(b),
                     b.extension, b.single_file() ? "" : " and ", b.companions, b.help);
  return s;
}

std::vector<BackendOptionsGiven> add_backend_options(CLI::App &app) {
  std::vector<BackendOptionsGiven> groups;
  for (const auto &b : kBackends) {
    if (!b.option_group) continue;
    groups.push_back({&b, b.option_group()});
    groups.back().group->add_to(app);
  }
  return groups;
}

std::unique_ptr<Backend> make_backend(std::string_view name) {
  const BackendInfo *b = find_backend(name);
  return b ? b->make() : nullptr;
}

}  // namespace gfec
