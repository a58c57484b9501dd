#include "run_chart.h"

#include <fmt/format.h>

namespace gfec::interp {

RunResult run_chart(const model::Model &model, int chart, Environment &env, std::uint64_t ticks,
                    EngineOptions options, Diagnostics &diag) {
  RunResult result;
  try {
    Engine engine(model, chart, options);
    for (std::uint64_t t = 0; t < ticks; ++t) {
      engine.run(env, &result.log);
      result.ticks = engine.ticks();
    }
    result.completed = true;
  } catch (const RuntimeError &e) {
    std::string when = result.ticks < ticks ? fmt::format("during tick {}", result.ticks + 1) : "";
    if (result.log.events().empty()) when = "in init";
    diag.error(e.range, "runtime", fmt::format("{} {}", e.what(), when));
  }
  return result;
}

} // namespace gfec::interp
