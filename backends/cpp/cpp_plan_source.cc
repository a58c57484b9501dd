// plan.cpp: the wiring of a plan (docs/plans.md "The generated code") — create the plan, its actor
// and supervisor instances, then the rules actor by actor — against the afp runtime's API
// (docs/runtime.md section 7). Every statement that comes from the plan begins with a `#line`
// to the element it comes from, so that a compiler's complaint (a toolbox class that does not
// match its template) points into the plan.
#include "cpp_emit.h"
#include "cpp_names.h"

#include <fmt/format.h>

#include <algorithm>

namespace gfec::cpp_backend {

namespace {

/// Lines longer than this wrap their arguments one per line.
constexpr std::size_t kWidth = 120;

/// The CodeWriter plus what the compiler believes the current plan line is, so that a `#line`
/// is written only where a statement does not already fall on its own line.
class Writer {
public:
  Writer(const PlanContext &c, std::ostream &out)
      : w_(out, c.source_file, c.options.line_directives), sources_(c.model.sources()) {}

  /// A statement that stems from `range` in the plan (several lines when it wraps).
  void from(const SourceRange &range, const std::string &text) {
    if (sources_.knows(range.file) && w_.line_directives()) {
      std::uint32_t line = sources_.begin_of(range).line;
      if (!pointing_ || file_ != range.file || next_ != line) {
        w_.line_from(sources_, range);
        pointing_ = true;
        file_ = range.file;
        next_ = line;
      }
    }
    put(text);
  }

  /// Code of gfec's own (comments, blank lines, braces).
  void put(const std::string &text) {
    w_.line(std::string_view(text));
    next_ += 1 + static_cast<std::uint32_t>(std::count(text.begin(), text.end(), '\n'));
  }
  void blank() { put(""); }
  /// What follows, to the end of the C++ scope, one level in (the closing brace is put()).
  [[nodiscard]] CodeWriter::Scope indented() { return w_.indented(); }
  void raw(const std::string &text) {
    directive(w_, text);
    ++next_;
  }
  /// A file-level `%{ %}` block, as the user wrote it, then back to the generated file.
  void verbatim(const model::Verbatim &v) {
    w_.verbatim(sources_, v.range, v.text, v.code_begin);
    back();
  }

  /// Back to the generated file before code that no plan element stands for.
  void back() {
    w_.line_back();
    pointing_ = false;
  }

private:
  CodeWriter w_;
  const SourceManager &sources_;
  bool pointing_ = false;
  FileId file_ = 0;
  std::uint32_t next_ = 0;
};

/// `head(ee, a, b)tail`, on one line when it fits, else one argument per line.
std::string call(const std::string &head, const std::vector<std::string> &args, const std::string &tail) {
  std::string one = head;
  for (std::size_t i = 0; i < args.size(); ++i) one += (i == 0 ? "" : ", ") + args[i];
  one += tail;
  if (one.size() + 4 <= kWidth || args.size() < 2) return one;
  std::string wrapped = head + args[0] + ",";
  for (std::size_t i = 1; i < args.size(); ++i) wrapped += "\n        " + args[i] + (i + 1 < args.size() ? "," : "");
  return wrapped + tail;
}

class PlanWriter {
public:
  PlanWriter(const PlanContext &c, const PlanWiring &w, Writer &out)
      : c_(c), w_(w), p_(c.plan_of(w)), out_(out), used_(p_.actors.size()) {
    for (const auto &a : p_.actors)
      for (const auto &r : a.rules) mark(r.target);
    for (const auto &g : p_.globals)
      for (const auto &r : g.rules) mark(r.target);
    for (const auto &a : p_.actors)
      for (const auto &s : a.supervisors)
        for (const auto &r : s.rules) mark(r.target);
    if (p_.start) used_[p_.start] = true;
  }

  void factory() {
    out_.put(w_.internal
                 ? fmt::format("// Sub-plan {}: used as an actor, it ends in OK, INTERRUPTED or ERROR.", p_.name)
                 : fmt::format("// Plan {}: a new instance for an executor; it declares its config entries.", p_.name));
    out_.put(fmt::format("std::unique_ptr<afp::Plan> {}({}) {{", w_.factory, c_.factory_params(w_)));
    {
      auto body = out_.indented();
      create_plan();
      create_actors();
      create_supervisors();
      start_and_globals();
      for (model::ActorId a : p_.actors.ids()) actor_rules(a);
      out_.back();
      out_.put(fmt::format("return {};", c_.plan_var));
    }
    out_.put("}");
  }

private:
  void mark(const model::RuleTarget &t) {
    if (t.kind == model::RuleTarget::Kind::Actor) used_.at(t.actor) = true;
  }

  void create_plan() {
    out_.put("// **** Create Plan ****");
    out_.from(p_.range,
              fmt::format("auto {} = std::make_unique<afp::Plan>({});", c_.plan_var, c_string_literal(p_.name)));
    for (const auto &e : p_.config)
      out_.from(e.range, fmt::format("{}->declare({}, {});", c_.plan_var, c_string_literal(e.name),
                                     e.init ? initial_value(*e.init, e.type) : afp_type(e.type)));
  }

  void create_actors() {
    out_.blank();
    out_.put("// **** Create Actor instances ****");
    for (model::ActorId i : p_.actors.ids()) {
      const model::ActorUse &a = p_.actors[i];
      // An actor nothing refers to (possible only in a hand-made model) needs no handle.
      std::string lhs = used_[i] || !a.rules.empty() || !a.supervisors.empty() ? "auto* " + w_.actor[i] + " = " : "";
      std::string head = fmt::format("{}{}->add_actor({}, ", lhs, c_.plan_var, c_string_literal(a.name));
      if (a.subplan) {
        const PlanWiring &sub = c_.wiring_of(a.subplan);
        out_.from(a.range,
                  fmt::format("{}std::make_unique<afp::SubPlan>({}({})));", head, sub.factory, c_.factory_args(sub)));
      } else {
        out_.from(a.range, instance(head, a.templ, w_.actor_args[i]));
      }
    }
  }

  void create_supervisors() {
    if (p_.globals.empty() &&
        std::all_of(p_.actors.begin(), p_.actors.end(), [](const auto &a) { return a.supervisors.empty(); }))
      return;
    out_.blank();
    out_.put("// **** Create Supervisor instances ****");
    for (std::size_t g = 0; g < p_.globals.size(); ++g) supervisor(p_.globals[g], w_.global[g], w_.global_args[g]);
    for (model::ActorId a : p_.actors.ids())
      for (std::size_t s = 0; s < p_.actors[a].supervisors.size(); ++s)
        supervisor(p_.actors[a].supervisors[s], w_.local[a][s], w_.local_args[a][s]);
  }

  void supervisor(const model::SupervisorUse &s, const std::string &handle, const std::vector<std::string> &args) {
    std::string lhs = s.rules.empty() ? "" : "auto* " + handle + " = ";
    out_.from(s.range, instance(fmt::format("{}{}->add_supervisor({}, ", lhs, c_.plan_var, c_string_literal(s.name)),
                                s.templ, args));
  }

  /// `head std::make_unique<Class>(ee, args...));`
  std::string instance(const std::string &head, model::TemplateId templ, std::vector<std::string> args) {
    const model::Template &t = c_.templ(templ);
    args.insert(args.begin(), c_.env_param.at(t.toolbox));
    return call(fmt::format("{}std::make_unique<{}>(", head, class_name(t)), args, "));");
  }

  void start_and_globals() {
    out_.blank();
    out_.put(p_.globals.empty() ? "// **** Define the first actor ****"
                                : "// **** Define the first actor and the global supervision ****");
    // The model keeps no range for `start NAME;`: the plan's own line stands for it.
    if (p_.start) out_.from(p_.range, fmt::format("{}->define_first_actor({});", c_.plan_var, w_.actor[p_.start]));
    for (std::size_t g = 0; g < p_.globals.size(); ++g) {
      const model::SupervisorUse &s = p_.globals[g];
      for (const auto &r : s.rules)
        out_.from(r.range, fmt::format("{}->define_global_supervision({}, {}, {});", c_.plan_var, w_.global[g],
                                       outcome(s.templ, {}, r.outcome), target(r.target)));
    }
  }

  void actor_rules(model::ActorId i) {
    const model::ActorUse &a = p_.actors[i];
    out_.blank();
    out_.put(fmt::format("// **** Define rules for Actor {} ****", a.name));
    for (const auto &r : a.rules)
      out_.from(r.range, fmt::format("{}->define_subsequent({}, {}, {});", c_.plan_var, w_.actor[i],
                                     outcome(a.templ, a.subplan, r.outcome), target(r.target)));
    // Supervisors in declaration order: the order of their first rule is their check order.
    for (std::size_t s = 0; s < a.supervisors.size(); ++s) {
      const model::SupervisorUse &sup = a.supervisors[s];
      for (const auto &r : sup.rules)
        out_.from(r.range, fmt::format("{}->define_supervision({}, {}, {}, {});", c_.plan_var, w_.actor[i],
                                       w_.local[i][s], outcome(sup.templ, {}, r.outcome), target(r.target)));
    }
  }

  /// `Forward::FORWARD_OK`, `afp::SubPlan::OK`.
  std::string outcome(model::TemplateId templ, model::PlanId subplan, int index) const {
    if (subplan || !templ) return fmt::format("afp::SubPlan::{}", model::kSubPlanStates[index]);
    const model::Template &t = c_.templ(templ);
    return class_name(t) + "::" + outcome_name(t, index);
  }

  std::string target(const model::RuleTarget &t) const {
    switch (t.kind) {
    case model::RuleTarget::Kind::Terminate: return "afp::terminate";
    case model::RuleTarget::Kind::Ignore: return "afp::ignore";
    case model::RuleTarget::Kind::Actor: break;
    }
    return w_.actor.at(t.actor);
  }

  const PlanContext &c_;
  const PlanWiring &w_;
  const model::Plan &p_;
  Writer &out_;
  IdMap<model::ActorId, bool> used_;  ///< the first actor or the target of some rule
};

void helpers(Writer &out, const FormulaHelpers &h) {
  if (h.text) {
    out.put("/// A computed number joined to a string: the runtime's conversion to text (30.0f -> \"30\").");
    out.put(fmt::format("std::string {}(const afp::Value& number) {{ return afp::convert<std::string>(number); }}",
                        h.text_fn));
    out.blank();
  }
  if (h.divide) {
    out.put("/// int / int as in C, except that dividing by zero ends the component in error.");
    out.put(fmt::format("int {}(int a, int b) {{", h.divide_fn));
    {
      auto body = out.indented();
      out.put("if (b == 0) throw afp::Error(\"division by zero in a formula\");");
      out.put("return a / b;");
    }
    out.put("}");
    out.blank();
  }
}

}  // namespace

void emit_plan_source(const PlanContext &c, std::ostream &stream) {
  Writer out(c, stream);
  out.put(banner(c.options.source_name, "plan " + c.plan.name));
  out.put("// Do not edit: change the plan and regenerate. The wiring is described in docs/plans.md.");
  out.raw("#include " + c_string_literal(c.header_file));
  out.blank();
  out.raw("#include <memory>");
  out.raw("#include <string>");
  out.blank();
  for (model::ToolboxId box : c.toolboxes)
    out.raw("#include " + c_string_literal(toolbox_header(c.model.toolboxes[box])));
  // The `%{ %}` blocks at file level (imports' first), where the plan's own #includes go, as an
  // engine's (docs/language.md §6).
  for (const auto &v : c.model.verbatims) {
    out.blank();
    out.verbatim(v);
  }
  const bool internal = c.helpers.text || c.helpers.divide || c.plans.size() > 1;
  if (internal) {
    out.blank();
    out.put("namespace {");
    out.blank();
    helpers(out, c.helpers);
    for (const auto &w : c.plans) {
      if (!w.internal) continue;
      PlanWriter(c, w, out).factory();
      out.blank();
    }
    out.put("}  // namespace");
  }
  out.blank();
  PlanWriter(c, c.plans.back(), out).factory();
}

}  // namespace gfec::cpp_backend
