#include "cpp_backend.h"

#include "cpp_emit.h"
#include "cpp_names.h"
#include "cpp_plan_context.h"

#include <ostream>
#include <stdexcept>

namespace gfec {

namespace {

/// The plan or toolbox the pipeline chose (pipeline/compilation.h); none is a bug of the caller.
const model::Plan &chosen_plan(const model::Model &model, const EmitOptions &options) {
  if (!model.plans.contains(options.plan)) throw std::invalid_argument("cpp back end: no plan chosen to compile");
  return model.plans[options.plan];
}

const model::Toolbox &chosen_toolbox(const model::Model &model, const EmitOptions &options) {
  if (!model.toolboxes.contains(options.toolbox))
    throw std::invalid_argument("toolbox-skeleton back end: no toolbox chosen");
  return model.toolboxes[options.toolbox];
}

class CppBackend : public Backend {
public:
  void emit(const model::Model &model, const EmitOptions &options, OutputSink &sink) const override {
    cpp_backend::PlanContext c = cpp_backend::make_plan_context(model, chosen_plan(model, options), options);
    // plan.cpp first (the primary output), then plan.hpp beside it, each written as it is made.
    cpp_backend::emit_plan_source(c, sink.open(options.output_path));
    cpp_backend::emit_plan_header(c, sink.open(replace_extension(options.output_path, ".hpp")));
  }
};

class ToolboxSkeletonBackend : public Backend {
public:
  void emit(const model::Model &model, const EmitOptions &options, OutputSink &sink) const override {
    const model::Toolbox &box = chosen_toolbox(model, options);
    // The header first (what the wiring includes), then the source to fill in beside it.
    std::string source = replace_extension(options.output_path, ".cpp");
    if (source == options.output_path) source += ".cpp";  // -o x.cpp must not name both files
    cpp_backend::emit_skeleton_header(model, box, options, sink.open(options.output_path));
    cpp_backend::emit_skeleton_source(model, box, options, base_name(source), sink.open(source));
  }
  std::string default_output(const model::Model &model, const EmitOptions &options) const override {
    return cpp_backend::toolbox_header(chosen_toolbox(model, options));
  }
};

}  // namespace

std::unique_ptr<Backend> make_cpp_backend() { return std::make_unique<CppBackend>(); }

std::unique_ptr<Backend> make_toolbox_skeleton_backend() { return std::make_unique<ToolboxSkeletonBackend>(); }

}  // namespace gfec
