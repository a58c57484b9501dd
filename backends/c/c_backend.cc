#include "c_backend.h"

#include "c_context.h"
#include "c_emit.h"
#include "roots.h"

#include <stdexcept>

namespace gfec {

namespace {

class CBackend : public Backend {
public:
  std::vector<OutputFile> emit(const model::Model &model, const EmitOptions &options) const override {
    const model::Chart &chart = pick_chart(model, options);
    c_backend::Context c = c_backend::make_context(model, chart, options);
    // engine.c first (the primary output), then engine.h beside it.
    return {{options.output_path, c_backend::emit_source(c)},
            {replace_extension(options.output_path, ".h"), c_backend::emit_header(c)}};
  }

private:
  /// The chart the driver chose; without a choice, the one chart of the main file. Anything else
  /// is a bug of the caller, not an error in the user's input.
  static const model::Chart &pick_chart(const model::Model &model, const EmitOptions &options) {
    if (options.chart >= 0 && static_cast<std::size_t>(options.chart) < model.charts.size())
      return model.charts[static_cast<std::size_t>(options.chart)];
    const model::Chart *found = nullptr;
    int root = default_root(model);
    if (root >= 0) found = &model.charts[static_cast<std::size_t>(root)];
    if (!found && !model.charts.empty()) found = &model.charts.front();
    if (!found) throw std::invalid_argument("c back end: the model has no chart to compile");
    return *found;
  }
};

} // namespace

std::unique_ptr<Backend> make_c_backend() { return std::make_unique<CBackend>(); }

} // namespace gfec
