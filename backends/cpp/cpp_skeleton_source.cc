// The skeleton's source: one body per member function, saying what the runtime expects of it.
// Inputs are read in start() as the contract asks; every body that must decide something
// (step, check, compute) throws "not implemented" until it is written, so a plan that runs
// an unfinished toolbox ends in error and says where, instead of driving on made-up results.
#include "cpp_emit.h"
#include "cpp_names.h"

#include <fmt/format.h>

namespace gfec::cpp_backend {

namespace {

/// `const float distance = distance_.read(ctx);` for each input: what start() (or compute())
/// is for. False if there is none (ctx is then unused).
bool read_inputs(CodeWriter &w, const model::Template &t, const MemberNames &n, const char *keep) {
  bool any = false;
  for (std::size_t i = 0; i < t.params.size(); ++i) {
    if (t.params[i].dir != model::ParamDir::In) continue;
    w.line("const {} {} = {}.read(ctx);", cpp_type(t.params[i].type), n.param[i], n.member[i]);
    w.line("(void){};  // TODO: {}", n.param[i], keep);
    any = true;
  }
  return any;
}

/// `rest_.write(ctx, value)`: how the outputs are written, for the comments.
std::string outputs(const model::Template &t, const MemberNames &n) {
  std::string list;
  for (std::size_t i = 0; i < t.params.size(); ++i)
    if (t.params[i].dir == model::ParamDir::Out)
      list += fmt::format("{}{}.write(ctx, value)", list.empty() ? "" : ", ", n.member[i]);
  return list;
}

std::string outcome_list(const model::Template &t) {
  std::string list;
  for (std::size_t k = 0; k < t.outcomes.size(); ++k)
    list += (k == 0 ? "" : k + 1 == t.outcomes.size() ? " or " : ", ") + outcome_name(t, static_cast<int>(k));
  return list;
}

/// The body that decides (step, check, compute): until written, the component fails.
void deciding_body(CodeWriter &w, const std::string &cls, const char *fn, const std::vector<std::string> &todo,
                   const std::string &unused) {
  for (const auto &line : todo) w.line(std::string_view(line));
  if (!unused.empty()) w.line(std::string_view(unused));
  w.line("throw afp::Error(\"{}::{} is not implemented\");", cls, fn);
}

void computation(CodeWriter &w, const model::Template &t, const MemberNames &n, const std::string &cls) {
  const std::string out = outputs(t, n);
  auto body = w.block(fmt::format("int {}::compute(afp::Context& ctx) {{", cls));
  bool reads = read_inputs(w, t, n, "compute with it");
  std::vector<std::string> todo{fmt::format("// TODO: compute and return {}.", outcome_list(t))};
  if (!out.empty()) todo.push_back("//       Write the outputs first: " + out + ";");
  deciding_body(w, cls, "compute", todo, fmt::format("{}(void){};", reads ? "" : "(void)ctx, ", n.env_member));
}

void actor_or_supervisor(CodeWriter &w, const model::Template &t, const MemberNames &n, const std::string &cls) {
  const bool supervisor = t.kind == model::Template::Kind::Supervisor;
  const std::string out = outputs(t, n);
  {
    auto body = w.block(fmt::format("void {}::start(afp::Context& ctx) {{", cls));
    if (!read_inputs(w, t, n,
                     supervisor ? "keep what check() needs in a member" : "keep what step() needs in a member"))
      w.line("(void)ctx;");
    w.line(supervisor ? "// TODO: begin watching." : "// TODO: begin the action on {}.", n.env_member);
  }
  w.blank();
  std::vector<std::string> todo;
  if (supervisor) {
    w.line("afp::CheckResult {}::check(afp::Context& ctx) {{", cls);
    todo.push_back(fmt::format("// TODO: look at the robot through {}; return afp::no_event, or the event: {}.",
                               n.env_member, outcome_list(t)));
  } else {
    w.line("afp::StepResult {}::step(afp::Context& ctx) {{", cls);
    todo.push_back(fmt::format("// TODO: advance the action on {}; return afp::running until it ends in {}.",
                               n.env_member, outcome_list(t)));
  }
  if (!out.empty()) todo.push_back("//       Write the outputs first: " + out + ";");
  {
    CodeWriter::Scope body(w, "}");  // the function opened above
    deciding_body(w, cls, supervisor ? "check" : "step", todo, fmt::format("(void)ctx, (void){};", n.env_member));
  }
  w.blank();
  auto body = w.block(fmt::format("void {}::stop() {{", cls));
  w.line(supervisor ? "// TODO: end the watch (release what start() took); must not throw."
                    : "// TODO: halt what start() began.");
}

void template_bodies(CodeWriter &w, const model::Template &t) {
  const MemberNames n = member_names(t);
  const std::string cls = class_name(t);
  w.line("// {}", template_signature(t));
  w.blank();
  if (t.kind == model::Template::Kind::Computation) computation(w, t, n, cls);
  else actor_or_supervisor(w, t, n, cls);
}

}  // namespace

void emit_skeleton_source(const model::Model &model, const model::Toolbox &box, const EmitOptions &options,
                          const std::string &source_name, std::ostream &out) {
  CodeWriter w(out, source_name, false);
  w.line(std::string_view(banner(options.source_name, "skeleton of toolbox " + box.name)));
  w.line("// A starting point: write the bodies and keep this file (regenerating overwrites it). Until");
  w.line("// a body is written, the component fails with \"not implemented\" and the plan ends in error.");
  directive(w, "#include " + c_string_literal(base_name(options.output_path)));
  for (model::TemplateId i : box.templates) {
    w.blank();
    template_bodies(w, model.templates.at(i));
  }
}

}  // namespace gfec::cpp_backend
