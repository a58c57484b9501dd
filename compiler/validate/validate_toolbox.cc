// Toolboxes (§8): the templates a toolbox developer implements once per robot.
#include "validate/families.h"
#include "validate/types.h"

#include <fmt/format.h>

namespace gfec::validation {

namespace {

model::Template::Kind kind_of(ast::Template::Kind k) {
  switch (k) {
  case ast::Template::Kind::Actor: return model::Template::Kind::Actor;
  case ast::Template::Kind::Computation: return model::Template::Kind::Computation;
  case ast::Template::Kind::Supervisor: return model::Template::Kind::Supervisor;
  }
  return model::Template::Kind::Actor;
}

const char *kind_word(ast::Template::Kind k) {
  switch (k) {
  case ast::Template::Kind::Actor: return "actor";
  case ast::Template::Kind::Computation: return "computation";
  case ast::Template::Kind::Supervisor: return "supervisor";
  }
  return "template";
}

/// Lowers the parameters; false if a type is wrong.
bool lower_params(Context &cx, const ast::Template &t, model::Template &out) {
  bool ok = true;
  Namespace params;
  for (const ast::TemplateParam &p : t.params) {
    model::TemplateParam mp;
    mp.dir = p.dir == ast::ParamDir::Out ? model::ParamDir::Out : model::ParamDir::In;
    mp.name = p.name.text;
    if (auto type = lower_type(p.type, kScalar | kString | kObject, "a template parameter", cx.diag)) mp.type = *type;
    else ok = false;
    params.declare(p.name, Sym::TemplateParam, -1, cx.diag);
    out.params.push_back(std::move(mp));
  }
  return ok;
}

void lower_outcomes(Context &cx, const ast::Template &t, model::Template &out) {
  bool supervisor = t.kind == ast::Template::Kind::Supervisor;
  if (t.outcomes.empty())
    cx.diag.error(
        t.name.range, ErrorKind::NoOutcome,
        fmt::format("{} '{}' has no {}", kind_word(t.kind), t.name.text, supervisor ? "event" : "result state"));
  Namespace outcomes;
  for (const ast::Name &o : t.outcomes) {
    outcomes.declare(o, supervisor ? Sym::Event : Sym::ResultState, -1, cx.diag);
    out.outcomes.emplace_back(o.text);
  }
}

void lower_period(Context &cx, const ast::Template &t, model::Template &out) {
  if (!t.period) return;
  if (t.kind != ast::Template::Kind::Supervisor)
    cx.diag.error(t.period->range, ErrorKind::Period, "only a supervisor has a period");
  else if (t.period->ms <= 0) cx.diag.error(t.period->range, ErrorKind::Period, "the period must be positive");
  else out.period_ms = t.period->ms;
}

}  // namespace

void declare_toolbox(Context &cx, const ast::Toolbox &toolbox) {
  model::Toolbox box;
  box.name = toolbox.name.text;
  box.range = toolbox.range;
  const model::ToolboxId box_index = cx.model.toolboxes.next_id();
  cx.declare_global(cx.toolboxes, toolbox.name, Sym::Toolbox, box_index);
  for (const ast::Template &t : toolbox.templates) {
    model::Template out;
    out.kind = kind_of(t.kind);
    out.name = t.name.text;
    out.toolbox = box_index;
    out.range = t.range;
    bool ok = lower_params(cx, t, out);
    lower_outcomes(cx, t, out);
    lower_period(cx, t, out);
    const model::TemplateId index = cx.model.templates.next_id();
    cx.model.templates.push_back(std::move(out));
    cx.templates.push_back(&t);
    cx.template_ok.push_back(ok);
    box.templates.push_back(index);
    cx.declare_global(cx.plan_names, t.name, Sym::Template, index);
  }
  cx.model.toolboxes.push_back(std::move(box));
}

}  // namespace gfec::validation
