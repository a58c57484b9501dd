// Toolboxes (§8): the templates a toolbox developer implements once per robot.
#include "validate/families.h"
#include "validate/types.h"

#include "naming/naming.h"

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

/// The toolbox's classes (docs/toolbox.md) live in C++'s global namespace, beside what the
/// standard headers declare there, and hold afp's members: a name that clashes with either
/// would not compile. Reported as reserved, like a keyword.
bool check_class_name(Context &cx, const ast::Name &name, Sym kind) {
  const char *what = nullptr;
  if (kind == Sym::Toolbox ? naming::is_template_scope_name(name.text) : naming::is_template_member(name.text))
    what = kind == Sym::Toolbox ? "a name inside the C++ class of every template (afp's base classes or the "
                                  "skeleton declare it), where it would hide the environment's type,"
                                : "a member of the C++ class of every template (afp's base classes or the "
                                  "skeleton declare it)";
  else if (kind != Sym::ResultState && kind != Sym::Event && naming::is_c_library_global(name.text))
    what = naming::c_library_function(name.text)
               ? "a function of the C library, which the C++ standard headers declare in the global namespace,"
               : "a type of the C library, which the C++ standard headers declare in the global namespace,";
  if (!what) return true;
  cx.diag.error(name.range, ErrorKind::ReservedName,
                fmt::format("'{}' is {} and cannot name {}", name.text, what, with_article(kind)));
  return false;
}

/// Inside a template's class, a member of the toolbox's name would hide the environment's type,
/// which the constructor and the member `ee_` are declared with.
void check_environment_name(Context &cx, const ast::Toolbox &toolbox) {
  const std::string_view box = toolbox.name.text;
  for (const ast::Template &t : toolbox.templates) {
    auto clash = [&](const std::string &what) {
      cx.diag
          .error(toolbox.name.range, ErrorKind::ReservedName,
                 fmt::format("toolbox '{}' names the C++ type of its environment, which {} of template '{}' would hide "
                             "inside the template's class",
                             box, what, t.name.text))
          .note(t.name.range, fmt::format("template '{}' declared here", t.name.text));
    };
    for (const ast::Name &o : t.outcomes)
      if (o.text == box)
        return clash(
            fmt::format("the {} '{}'", t.kind == ast::Template::Kind::Supervisor ? "event" : "result state", o.text));
    for (const ast::TemplateParam &p : t.params)
      if (std::string(p.name.text) + "_" == box)
        return clash(fmt::format("the member '{}' of parameter '{}'", box, p.name.text));
  }
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
  outcomes.uses = cx.uses;  // a rule's `STATE ->` points here (plan_wiring.cc find_outcome)
  for (const ast::Name &o : t.outcomes) {
    out.outcomes.emplace_back(o.text);
    const Sym kind = supervisor ? Sym::Event : Sym::ResultState;
    if (!outcomes.declare(o, kind, -1, cx.diag) || !check_class_name(cx, o, kind)) continue;
    // The outcomes are constants of an enumeration inside the template's class.
    if (o.text == t.name.text)
      cx.diag.error(o.range, ErrorKind::ReservedName,
                    fmt::format("{} '{}' has the name of its template, whose C++ class cannot have a member of its "
                                "own name",
                                describe(kind), o.text));
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
  if (check_class_name(cx, toolbox.name, Sym::Toolbox)) check_environment_name(cx, toolbox);
  for (const ast::Template &t : toolbox.templates) {
    check_class_name(cx, t.name, Sym::Template);
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

void check_toolbox_classes(Context &cx) {
  for (const Context::GlobalName &g : cx.global_names) {
    if (g.kind != Sym::Toolbox && g.kind != Sym::Template) continue;
    const std::string_view name = g.name->text;
    // A toolbox's environment and a template are both classes: one name for both clashes.
    if (g.kind == Sym::Toolbox)
      if (const Symbol *t = cx.plan_names.find(name); t && t->kind == Sym::Template)
        cx.diag
            .error(g.name->range, ErrorKind::DuplicateName,
                   fmt::format("toolbox '{}' has the same name as a template: both are C++ classes in the global "
                               "namespace",
                               name))
            .note(t->range, fmt::format("template '{}' declared here", name));
    // make_P is plan P's factory (docs/plans.md).
    if (name.substr(0, 5) == "make_")
      if (const Symbol *p = cx.plan_names.find(name.substr(5)); p && p->kind == Sym::Plan)
        cx.diag
            .error(g.name->range, ErrorKind::ReservedName,
                   fmt::format("'{}' is the C++ factory of plan '{}' and cannot name {}", name, p->name(),
                               with_article(g.kind)))
            .note(p->range, fmt::format("plan '{}' declared here", p->name()));
  }
}

}  // namespace gfec::validation
