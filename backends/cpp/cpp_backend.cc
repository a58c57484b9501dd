#include "cpp_backend.h"

#include "cpp_emit.h"
#include "cpp_plan_context.h"

#include <stdexcept>

namespace gfec {

namespace {

/// The plan the driver chose; without a choice, the first plan of the main file. Anything else
/// is a bug of the caller, not an error in the user's input.
const model::Plan &pick_plan(const model::Model &model, const EmitOptions &options) {
  if (options.plan >= 0 && static_cast<std::size_t>(options.plan) < model.plans.size())
    return model.plans[static_cast<std::size_t>(options.plan)];
  for (const auto &plan : model.plans)
    if (plan.in_main_file) return plan;
  throw std::invalid_argument("cpp back end: the model has no plan to compile");
}

const model::Toolbox &pick_toolbox(const model::Model &model, const EmitOptions &options) {
  if (options.toolbox >= 0 && static_cast<std::size_t>(options.toolbox) < model.toolboxes.size())
    return model.toolboxes[static_cast<std::size_t>(options.toolbox)];
  for (const auto &box : model.toolboxes)
    if (model.sources == nullptr || box.range.file == model.main_file) return box;
  throw std::invalid_argument("toolbox-skeleton back end: the model has no toolbox");
}

class CppBackend : public Backend {
public:
  std::vector<OutputFile> emit(const model::Model &model, const EmitOptions &options) const override {
    cpp_backend::PlanContext c = cpp_backend::make_plan_context(model, pick_plan(model, options), options);
    // plan.cpp first (the primary output), then plan.hpp beside it.
    return {{options.output_path, cpp_backend::emit_plan_source(c)},
            {replace_extension(options.output_path, ".hpp"), cpp_backend::emit_plan_header(c)}};
  }
};

class ToolboxSkeletonBackend : public Backend {
public:
  std::vector<OutputFile> emit(const model::Model &model, const EmitOptions &options) const override {
    const model::Toolbox &box = pick_toolbox(model, options);
    // The header first (what the wiring includes), then the source to fill in beside it.
    std::string source = replace_extension(options.output_path, ".cpp");
    if (source == options.output_path) source += ".cpp";  // -o x.cpp must not name both files
    return {{options.output_path, cpp_backend::emit_skeleton_header(model, box, options)},
            {source, cpp_backend::emit_skeleton_source(model, box, options, base_name(source))}};
  }
};

} // namespace

std::unique_ptr<Backend> make_cpp_backend() { return std::make_unique<CppBackend>(); }

std::unique_ptr<Backend> make_toolbox_skeleton_backend() { return std::make_unique<ToolboxSkeletonBackend>(); }

} // namespace gfec
