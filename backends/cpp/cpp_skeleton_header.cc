// <toolbox>_toolbox.h: the toolbox contract (docs/toolbox.md) written out for one toolbox. The
// environment class and every template's class with its base, its enum of states or events in
// declaration order, its constructor (environment first, then afp::In/afp::Out parameters in
// declaration order; a supervisor passes its period to afp::Supervisor) and its overrides. The
// toolbox developer fills in the environment and the bodies (the skeleton source).
#include "cpp_emit.h"
#include "cpp_names.h"

#include <fmt/format.h>

#include <algorithm>

namespace gfec::cpp_backend {

namespace {

const char *base_of(const model::Template &t) {
  switch (t.kind) {
  case model::Template::Kind::Actor: return "afp::Actor";
  case model::Template::Kind::Computation: return "afp::Computation";
  case model::Template::Kind::Supervisor: return "afp::Supervisor";
  }
  return "afp::Actor";
}

std::string param_type(const model::TemplateParam &p) {
  return fmt::format("afp::{}<{}>", p.dir == model::ParamDir::In ? "In" : "Out", cpp_type(p.type));
}

void constructor(CodeWriter &w, const model::Template &t, const std::string &env, const MemberNames &n) {
  std::string params = fmt::format("{}& {}", env, n.env_param);
  for (std::size_t i = 0; i < t.params.size(); ++i)
    params += fmt::format(", {} {}", param_type(t.params[i]), n.param[i]);
  std::string head = fmt::format("{}{}({})", t.params.empty() ? "explicit " : "", class_name(t), params);
  std::string inits;
  if (t.period_ms > 0) inits = fmt::format("afp::Supervisor({}), ", chrono_period(t.period_ms));
  inits += fmt::format("{}({})", n.env_member, n.env_param);
  for (std::size_t i = 0; i < t.params.size(); ++i)
    inits += fmt::format(", {}(std::move({}))", n.member[i], n.param[i]);
  if (head.size() + inits.size() + 12 <= 100) {
    w.line("{} : {} {{}}", head, inits);
  } else {
    w.line(std::string_view(head));
    auto continued = w.indented();
    w.line(": {} {{}}", inits);
  }
}

void overrides(CodeWriter &w, const model::Template &t) {
  switch (t.kind) {
  case model::Template::Kind::Actor:
    w.line("/// Reads the inputs (they are read when the actor starts) and begins the action.");
    w.line("void start(afp::Context& ctx) override;");
    w.line("/// Advances the action: afp::running, or the state it ended in (outputs written first).");
    w.line("afp::StepResult step(afp::Context& ctx) override;");
    w.line("/// Halts the action: called once after start(), however the actor ended.");
    w.line("void stop() override;");
    break;
  case model::Template::Kind::Computation:
    w.line("/// Reads the inputs, writes the outputs and returns the state; runs when the actor starts.");
    w.line("int compute(afp::Context& ctx) override;");
    break;
  case model::Template::Kind::Supervisor:
    w.line("/// Reads the inputs: the watch begins (with its actor, or with the plan for a global one).");
    w.line("void start(afp::Context& ctx) override;");
    w.line("/// Checks once: afp::no_event, or the event (its outputs written first).");
    w.line("afp::CheckResult check(afp::Context& ctx) override;");
    w.line("/// The watch ends; must not throw.");
    w.line("void stop() override;");
    break;
  }
}

void template_class(CodeWriter &w, const model::Template &t, const std::string &env) {
  const MemberNames n = member_names(t);
  w.line("/// {}", template_signature(t));
  w.line("class {} : public {} {{", class_name(t), base_of(t));
  w.line("public:");
  {
    auto members = w.indented();
    std::string outcomes;
    for (std::size_t k = 0; k < t.outcomes.size(); ++k)
      outcomes += (k == 0 ? "" : ", ") + outcome_name(t, static_cast<int>(k));
    w.line("enum {} {{ {} }};", t.kind == model::Template::Kind::Supervisor ? "Event" : "State", outcomes);
    w.blank();
    constructor(w, t, env, n);
    w.blank();
    overrides(w, t);
  }
  w.blank();
  w.line("private:");
  auto members = w.indented();
  w.line("{}& {};", env, n.env_member);
  for (std::size_t i = 0; i < t.params.size(); ++i) w.line("{} {};", param_type(t.params[i]), n.member[i]);
  members.end();
  w.line("};");
}

}  // namespace

void emit_skeleton_header(const model::Model &model, const model::Toolbox &box, const EmitOptions &options,
                          std::ostream &out) {
  const std::string header = base_name(options.output_path);
  const std::string guard = include_guard(header);
  const std::string env = environment_type(box);
  CodeWriter w(out, header, false);
  w.line(std::string_view(banner(options.source_name, "skeleton of toolbox " + box.name)));
  w.line("// A starting point, not generated code to keep regenerating: fill it in and keep it. Plans");
  w.line("// compiled by gfec include it as \"{}\" (docs/toolbox.md: the toolbox contract).", toolbox_header(box));
  directive(w, "#ifndef " + guard);
  directive(w, "#define " + guard);
  w.blank();
  directive(w, "#include <afp/afp.h>");
  w.blank();
  bool period = false, params = false;
  for (model::TemplateId i : box.templates) {
    period = period || model.templates.at(i).period_ms > 0;
    params = params || !model.templates.at(i).params.empty();
  }
  if (period) directive(w, "#include <chrono>");
  if (params) directive(w, "#include <utility>");
  if (period || params) w.blank();
  w.line("/// The execution environment of toolbox {}: what its templates share (the robot's sensors,", box.name);
  w.line("/// motors, libraries). A plan's factory takes it as `{}& ee` and hands it to every instance.", env);
  w.line("class {} {{", env);
  w.line("public:");
  {
    auto members = w.indented();
    w.line("// TODO: what the templates need of the robot.");
  }
  w.line("};");
  for (model::TemplateId i : box.templates) {
    w.blank();
    template_class(w, model.templates.at(i), env);
  }
  w.blank();
  directive(w, "#endif  // " + guard);
}

}  // namespace gfec::cpp_backend
