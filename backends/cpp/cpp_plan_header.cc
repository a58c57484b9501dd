// plan.hpp: what an application needs to run the plan — the factory, and through the toolbox
// headers the environment type it takes. The plan declares its own config entries (the
// executors put them into the afp::Configuration), so the header lists them only in a comment.
#include "cpp_emit.h"
#include "cpp_names.h"

#include <fmt/format.h>

namespace gfec::cpp_backend {

namespace {

/// `float walldist = 30, float wallangle`: the entries as the plan declares them.
std::string entries(const model::Plan &p) {
  std::string list;
  for (const auto &e : p.config) {
    list += fmt::format("{}{} {}", list.empty() ? "" : ", ", model::type_name(e.type), e.name);
    if (!e.init) continue;
    switch (e.init->kind) {
    case model::Expr::Kind::Bool: list += e.init->bool_value ? " = true" : " = false"; break;
    case model::Expr::Kind::String: list += " = " + c_string_literal(e.init->text); break;
    default: list += " = " + e.init->text;
    }
  }
  return list;
}

}  // namespace

void emit_plan_header(const PlanContext &c, std::ostream &out) {
  CodeWriter w(out, c.header_file, false);
  w.line(std::string_view(banner(c.options.source_name, "plan " + c.plan.name)));
  w.line("// Do not edit: change the plan and regenerate. How to run it: docs/plans.md.");
  directive(w, "#ifndef " + c.guard);
  directive(w, "#define " + c.guard);
  w.blank();
  directive(w, "#include <afp/afp.h>");
  w.blank();
  directive(w, "#include <memory>");
  w.blank();
  for (model::ToolboxId box : c.toolboxes)
    directive(w, "#include " + c_string_literal(toolbox_header(c.model.toolboxes[box])));
  if (!c.toolboxes.empty()) w.blank();
  const PlanWiring &top = c.plans.back();
  w.line("/// A new instance of plan {}, for one run by an afp::SteppedExecutor or afp::ThreadedExecutor,",
         c.plan.name);
  std::string list = entries(c.plan);
  if (list.empty()) w.line("/// which declare its config entries (it has none of its own).");
  else w.line("/// which declare its config entries in the afp::Configuration: {}.", list);
  for (const auto &sub : c.plans)
    if (sub.internal)
      w.line("/// Its sub-plan {} is defined inside it and declares its own entries too.", c.plan_of(sub).name);
  w.line("std::unique_ptr<afp::Plan> {}({});", top.factory, c.factory_params(top));
  w.blank();
  directive(w, "#endif  // " + c.guard);
}

}  // namespace gfec::cpp_backend
