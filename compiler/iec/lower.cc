// The lowering of an IEC program into the chart syntax tree (docs/iec.md "What a program is in
// gfec's chart language"). IEC names are case-insensitive and the chart language's are not, so
// every use of a variable, step or action is respelled as its declaration (`start` reads the
// `Start` declared); the range stays on what the user wrote.
#include "iec/lower.h"
#include "iec/iec_text.h"
#include "iec/nested_sfc.h"
#include "iec/spellings.h"
#include "did_you_mean.h"
#include "standard_blocks.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <iterator>
#include <deque>
#include <map>
#include <memory>
#include <set>
#include <string>

namespace gfec::iec {

namespace {}  // namespace

const char *chart_type(const std::string &iec) {
  static const char *const kMap[][2] = {
      {"BOOL", "bool"},   {"DINT", "int"},    {"REAL", "float"},   {"LREAL", "double"},
      {"TIME", "time"},   {"SINT", "int8"},   {"INT", "int16"},    {"LINT", "int64"},
      {"USINT", "uint8"}, {"UINT", "uint16"}, {"UDINT", "uint32"}, {"ULINT", "uint64"},
      {"BYTE", "uint8"},  {"WORD", "uint16"}, {"DWORD", "uint32"}, {"LWORD", "uint64"},
  };
  for (const auto &m : kMap)
    if (iec == m[0]) return m[1];
  return nullptr;
}

namespace {

bool elementary(const std::string &iec) {
  static const char *const kTypes[] = {"SINT",          "INT",   "LINT",   "USINT",   "UINT", "UDINT", "ULINT",
                                       "BYTE",          "WORD",  "DWORD",  "LWORD",   "TIME", "LTIME", "DATE",
                                       "TOD",           "DT",    "STRING", "WSTRING", "CHAR", "WCHAR", "TIME_OF_DAY",
                                       "DATE_AND_TIME", "LDATE", "LTOD",   "LDT"};
  for (const char *t : kTypes)
    if (iec == t) return true;
  return false;
}

const char *pou_kind(PouKind k) {
  switch (k) {
  case PouKind::Program: return "PROGRAM";
  case PouKind::FunctionBlock: return "FUNCTION_BLOCK";
  case PouKind::Function: return "FUNCTION";
  }
  return "POU";
}

/// A located variable's role comes from its address, whatever its section: the caller sets the
/// process image's inputs (%I) before a scan and reads its outputs (%Q) after it; %M is memory the
/// program keeps (docs/iec.md "Located variables").
void located_role(const Variable &v, ast::ValueDecl &d, Diagnostics &diag) {
  const std::string a = upper(v.address);
  const char area = a.size() > 1 && a[0] == '%' ? a[1] : '\0';
  if (a.find('*') != std::string::npos) {
    diag.error(*v.located, ErrorKind::NotSupported,
               fmt::format("the address '{}' of '{}' is left open ('*'), to be given by a VAR_CONFIG: not "
                           "supported yet",
                           v.address, v.name.text));
  } else if (area == 'I' || area == 'Q' || area == 'M') {
    d.role = area == 'I' ? ast::VarRole::In : area == 'Q' ? ast::VarRole::Out : ast::VarRole::Local;
    d.is_const = d.is_const && area == 'M';
    d.address = v.address;
  } else {
    diag.error(*v.located, ErrorKind::NotSupported,
               fmt::format("'{}' is not a direct address gfec reads: a located variable is at %I (an input), %Q "
                           "(an output) or %M (memory), as '%IX0.0'",
                           v.address));
  }
}

/// The function blocks a POU may instantiate, by their upper-case names: the project's
/// FUNCTION_BLOCKs and the standard blocks. IEC names are case-insensitive: a type, an instance's
/// member and a parameter are respelled as the block declares them.
struct KnownBlocks {
  std::map<std::string, std::string> spelled;  ///< upper-case name -> as declared
  std::map<std::string, Spellings> members;    ///< a FUNCTION_BLOCK's; a standard block's are upper case
  /// Type aliases, upper case -> upper case: the file's, and Beremiz's SVGHMI types (docs/iec.md
  /// "Type aliases").
  std::map<std::string, std::string> aliases;

  /// `type` (upper case) with its aliases followed to the type they name; a chain that goes
  /// round stops where it started, an unknown type then.
  std::string resolve(std::string type) const {
    for (std::size_t hops = 0; hops <= aliases.size(); ++hops) {
      auto it = aliases.find(type);
      if (it == aliases.end()) return type;
      type = it->second;
    }
    return type;
  }

  const std::string *type(const std::string &iec_upper) const {
    auto it = spelled.find(iec_upper);
    return it == spelled.end() ? nullptr : &it->second;
  }
  /// `member` of a block `type` (as declared), respelled as the block declares it.
  void respell_member(const std::string &type, ast::Name &member, std::deque<std::string> &strings) const {
    auto it = members.find(upper(type));
    if (it != members.end()) it->second.respell(member);
    else if (upper(member.text) != member.text) member.text = strings.emplace_back(upper(member.text));
  }
};

/// The instances a POU declares: upper-case name -> block type as declared.
using Instances = std::map<std::string, std::string>;

void respell_members(ast::Expr &e, const Instances &inst, const KnownBlocks &known, std::deque<std::string> &strings) {
  for (ast::Expr *a : e.args)
    if (a) respell_members(*a, inst, known, strings);
  if (e.kind != ast::Expr::Kind::Path || e.args.size() != 2 || !e.args[0] || !e.args[1]) return;
  auto it = inst.find(upper(e.args[0]->name.text));
  if (it != inst.end()) known.respell_member(it->second, e.args[1]->name, strings);
}

template <typename Stmts> void respell_members_in(Stmts &block, const Instances &inst, const KnownBlocks &known,
                                                  const Spellings &names, std::deque<std::string> &strings) {
  for (ast::Stmt &s : block) {
    if (s.value) respell_members(*s.value, inst, known, strings);
    if (s.call) respell_members(*s.call, inst, known, strings);
    if (s.kind == ast::Stmt::Kind::Invoke && s.target) {
      auto it = inst.find(upper(s.target->text));
      for (ast::Stmt &a : s.then_block) {
        if (a.value) respell_members(*a.value, inst, known, strings);
        if (it != inst.end() && a.target) known.respell_member(it->second, *a.target, strings);
      }
      continue;
    }
    if (s.kind == ast::Stmt::Kind::Assign && s.target && s.target->text.find('.') != std::string_view::npos) {
      // `inst.IN := x`: both names respelled, joined again.
      const std::size_t dot = s.target->text.find('.');
      ast::Name head{s.target->text.substr(0, dot), s.target->range};
      ast::Name member{s.target->text.substr(dot + 1), s.target->range};
      names.respell(head);
      auto it = inst.find(upper(head.text));
      if (it != inst.end()) known.respell_member(it->second, member, strings);
      s.target->text = strings.emplace_back(fmt::format("{}.{}", head.text, member.text));
    }
    respell_members_in(s.then_block, inst, known, names, strings);
    respell_members_in(s.else_block, inst, known, names, strings);
  }
}

/// IEC writes a BOOL's values 0 and 1 too (`Q := 0;`, as MatIEC's library does): an integer
/// literal 0 or 1 becomes FALSE or TRUE where it is a BOOL's initial value or is assigned to a
/// BOOL variable of the POU. Anywhere else an integer stays one, and the validator says so.
void bool_literal(const std::string &type, ast::ExprPtr &value) {
  if (upper(type) == "BOOL" && value && value->kind == ast::Expr::Kind::Int &&
      (value->text() == "0" || value->text() == "1")) {
    value->bool_value = value->text() == "1";
    value->kind = ast::Expr::Kind::Bool;
  }
}

template <typename Stmts> void bool_literals_in(Stmts &block, const Spellings &bools) {
  for (ast::Stmt &s : block) {
    if (s.kind == ast::Stmt::Kind::Assign && s.target && s.assign_op == AssignOp::Set && bools.declared(s.target->text))
      bool_literal("BOOL", s.value);
    bool_literals_in(s.then_block, bools);
    bool_literals_in(s.else_block, bools);
  }
}

/// The POU's BOOL variables, by IEC's case-insensitive names: where bool_literals_in applies.
Spellings bool_variables(const std::vector<Variable> &vars) {
  Spellings bools;
  for (const Variable &v : vars)
    if (upper(v.type.text) == "BOOL") bools.declare(v.name);
  return bools;
}

ast::ValueDecl lower_variable(Variable &v, Diagnostics &diag, const KnownBlocks *known = nullptr) {
  ast::ValueDecl d;
  // A PROGRAM's VAR_IN_OUT is the caller's variable, read and written by the scan: an `inout`
  // (docs/iec.md "What a program is in gfec's chart language").
  d.role = v.section == Section::Input    ? ast::VarRole::In
           : v.section == Section::Output ? ast::VarRole::Out
           : v.section == Section::InOut  ? ast::VarRole::InOut
                                          : ast::VarRole::Local;
  d.is_const = v.constant && v.section == Section::Local;
  d.name = v.name;
  d.range = v.range;
  const std::string t = known ? known->resolve(upper(v.type.text)) : upper(v.type.text);
  const std::string *block = known ? known->type(t) : nullptr;
  if (const char *c = chart_type(t)) {
    d.type = {c, v.type.range};
  } else if (block) {
    d.type = {*block, v.type.range};  // an instance (docs/iec.md "Function blocks")
    if (v.section != Section::Local)
      diag.error(
          v.type.range, ErrorKind::NotSupported,
          fmt::format("a function-block instance as an input or output ('{}') is not supported yet", v.name.text));
  } else {
    d.type = {"int", v.type.range};  // reported: what follows is still checked
    std::string head = t.substr(0, t.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZ_0123456789"));
    if (elementary(head))
      diag.error(v.type.range, ErrorKind::NotSupported,
                 fmt::format("the IEC type '{}' is not supported yet: gfec reads BOOL, the integers, REAL, "
                             "LREAL and TIME variables",
                             v.type.text));
    else
      diag.error(v.type.range, ErrorKind::NotSupported,
                 fmt::format("'{}' is not an elementary type gfec reads: function-block instances and "
                             "user-defined types are not supported yet",
                             v.type.text));
  }
  if (v.located) located_role(v, d, diag);
  d.init = std::move(v.init);
  bool_literal(t, d.init);  // `Lamp AT %QX0.0 : BOOL := 1;`, as MatIEC's tests write
  return d;
}

/// The names a block of statements assigns (as respelled: as declared).
template <typename Stmts> void assigned_names(const Stmts &block, std::set<std::string_view> &out) {
  for (const ast::Stmt &s : block) {
    if (s.kind == ast::Stmt::Kind::Assign && s.target) out.insert(s.target->text);
    assigned_names(s.then_block, out);
    assigned_names(s.else_block, out);
  }
}

/// A %I variable that the program assigns is an `inout` of the chart: the caller sets it before
/// each scan, as the PLC's input image is refreshed, and what the program writes holds until then
/// (docs/iec.md "Located variables"). MatIEC and OpenPLC run such programs; a VAR_INPUT stays
/// read-only, as the standard has it.
void written_inputs(ast::Chart &c) {
  std::set<std::string_view> assigned;
  for (const ast::ActionDecl &a : c.actions) assigned_names(a.body, assigned);
  for (const ast::Place &p : c.places) assigned_names(p.action, assigned);
  for (ast::ValueDecl &v : c.values)
    if (v.role == ast::VarRole::In && !v.address.empty() && assigned.count(v.name.text)) v.role = ast::VarRole::InOut;
}

/// `A.Q` and `A.A` as the ST parser left them (calls named ".Q", ".A"): of an action, its flags
/// `active(A)` and `running(A)` (docs/iec.md "Action flags"); of anything else, a located error.
void action_flags(ast::Expr &e, const std::map<std::string, bool> &actions, Diagnostics &diag) {
  for (ast::Expr *a : e.args)
    if (a) action_flags(*a, actions, diag);
  if (e.kind != ast::Expr::Kind::Call || (e.name.text != ".Q" && e.name.text != ".A")) return;
  const bool q = e.name.text == ".Q";
  if (e.args.size() != 2 || !e.args[0] || !e.args[1]) return;  // the reader makes them so
  if (actions.count(upper(e.args[0]->name.text))) {
    ast::ExprList of;
    of.push_back(clone(*e.args[0]));
    e.name.text = q ? "active" : "running";
    e.args = std::move(of);
    return;
  }
  if (!q) {
    diag.error(e.range, ErrorKind::NotSupported,
               fmt::format("'{}.{}': '{}' is no ACTION of the program, and '.A' is an action's flag",
                           e.args[0]->name.text, e.args[1]->name.text, e.args[0]->name.text));
    return;
  }
  // Not an action: a member read, `inst.Q` of a function-block instance; the validator says
  // what else it is.
  ast::ExprList parts;
  parts.push_back(clone(*e.args[0]));
  parts.push_back(clone(*e.args[1]));
  e.kind = ast::Expr::Kind::Path;
  e.name = {};
  e.args = std::move(parts);
}

template <typename Stmts>
void action_flags_in(Stmts &block, const std::map<std::string, bool> &actions, Diagnostics &diag) {
  for (ast::Stmt &s : block) {
    if (s.value) action_flags(*s.value, actions, diag);
    if (s.call) action_flags(*s.call, actions, diag);
    action_flags_in(s.then_block, actions, diag);
    action_flags_in(s.else_block, actions, diag);
  }
}

/// `Step.T` compared with a TIME literal the period does not divide, made exact. The chart
/// language compares `elapsed(P)` with a duration in whole ticks, the duration rounded up
/// (docs/language.md §5.3), which is the time comparison for `>=` and `<`; IEC compares times.
/// With `.T` a whole number of periods, `T > d` is `T >= d` rounded up and `T <= d` is `T < d`
/// rounded up; `T = d` never holds and `T <> d` always does (docs/iec.md "The scan").
void exact_step_times(ast::Expr &e, double period_ms) {
  for (ast::Expr *a : e.args)
    if (a) exact_step_times(*a, period_ms);
  if (e.kind != ast::Expr::Kind::Binary || e.args.size() != 2 || !e.args[0] || !e.args[1]) return;
  auto is_elapsed = [](const ast::Expr &x) { return x.kind == ast::Expr::Kind::Call && x.name.text == "elapsed"; };
  BinaryOp op = e.binary_op;
  const ast::Expr *duration = nullptr;
  if (is_elapsed(*e.args[0]) && e.args[1]->kind == ast::Expr::Kind::Duration) {
    duration = e.args[1];
  } else if (is_elapsed(*e.args[1]) && e.args[0]->kind == ast::Expr::Kind::Duration) {
    duration = e.args[0];
    // d OP T is T OP' d
    op = op == BinaryOp::Lt   ? BinaryOp::Gt
         : op == BinaryOp::Gt ? BinaryOp::Lt
         : op == BinaryOp::Le ? BinaryOp::Ge
         : op == BinaryOp::Ge ? BinaryOp::Le
                              : op;
  }
  if (!duration || period_ms <= 0) return;
  const double periods = duration->duration_ms / period_ms;
  if (periods == std::floor(periods)) return;  // a whole number of periods: already exact
  const bool mirrored = duration == e.args[0];
  switch (op) {
  case BinaryOp::Gt: e.binary_op = mirrored ? BinaryOp::Le : BinaryOp::Ge; break;
  case BinaryOp::Le: e.binary_op = mirrored ? BinaryOp::Gt : BinaryOp::Lt; break;
  case BinaryOp::Eq:
  case BinaryOp::Ne:
    e.kind = ast::Expr::Kind::Bool;
    e.bool_value = op == BinaryOp::Ne;
    e.args = ast::ExprList();
    break;
  default: break;
  }
}

template <typename Stmts> void exact_step_times_in(Stmts &block, double period_ms) {
  for (ast::Stmt &s : block) {
    if (s.value) exact_step_times(*s.value, period_ms);
    if (s.call) exact_step_times(*s.call, period_ms);
    exact_step_times_in(s.then_block, period_ms);
    exact_step_times_in(s.else_block, period_ms);
  }
}

/// The first place `e` reads a step's time (`Step.T`), or null. A TIME literal alone needs no
/// period: as a TIME value it counts milliseconds.
const SourceRange *time_read(const ast::Expr &e) {
  if (e.kind == ast::Expr::Kind::Call && e.name.text == "elapsed") return &e.range;
  for (const ast::Expr *a : e.args)
    if (const SourceRange *r = a ? time_read(*a) : nullptr) return r;
  return nullptr;
}

template <typename Stmts> const SourceRange *time_read(const Stmts &block) {
  for (const ast::Stmt &s : block) {
    const SourceRange *r = s.value ? time_read(*s.value) : nullptr;
    if (!r) r = time_read(s.then_block);
    if (!r) r = time_read(s.else_block);
    if (r) return r;
  }
  return nullptr;
}

/// The first place the chart reads a step's time: a timed association, `Step.T`.
const SourceRange *time_read(const ast::Chart &c) {
  for (const ast::Place &p : c.places)
    if (p.extras)
      for (const ast::Association &a : p.extras->associations)
        if (a.duration_ms) return &a.duration_range;
  for (const ast::Transition &t : c.transitions)
    if (const SourceRange *r = t.condition ? time_read(*t.condition) : nullptr) return r;
  for (const ast::ActionDecl &a : c.actions)
    if (const SourceRange *r = time_read(a.body)) return r;
  for (const ast::ValueDecl &v : c.values)
    if (const SourceRange *r = v.init ? time_read(*v.init) : nullptr) return r;
  return nullptr;
}

}  // namespace

std::optional<ast::Period> period_of(const Project &project, const Pou &pou, Diagnostics &diag) {
  std::optional<ast::Period> found;
  const std::string name = upper(pou.name.text);
  for (const Task &t : project.tasks) {
    bool runs =
        std::any_of(t.programs.begin(), t.programs.end(), [&](const ast::Name &p) { return upper(p.text) == name; });
    if (!runs || !t.interval_ms) continue;
    if (!found) {
      found = ast::Period{*t.interval_ms, t.interval_range};
    } else if (found->ms != *t.interval_ms) {
      diag.error(t.interval_range, ErrorKind::Period,
                 fmt::format("program '{}' runs in tasks of different INTERVALs; gfec runs a program at one period",
                             pou.name.text))
          .note(found->range, "the other INTERVAL");
    }
  }
  return found;
}

namespace {

/// An association naming a variable rather than an ACTION is IEC's Boolean action: the variable
/// is the action's Q. It becomes a generated action `V_Q { V = active(V_Q); }`, held as written,
/// run before the POU's actions: TRUE while Q, FALSE in its final run (docs/iec.md "Boolean
/// actions"). The steps of every SFC of the POU are looked at, an action's SFC too. Returns
/// the POU's actions (upper case), the generated ones with them.
std::map<std::string, bool> boolean_actions(Pou &pou, Spellings &names, ast::File &file) {
  std::map<std::string, const Variable *> variables;
  for (const Variable &v : pou.variables) variables.emplace(upper(v.name.text), &v);
  std::map<std::string, bool> actions;
  for (const Action &a : pou.actions) actions.emplace(upper(a.name.text), true);
  std::map<std::string, std::string_view> boolean_actions;  ///< variable (upper case) -> its action
  std::vector<Action> generated;
  std::vector<Step *> steps;
  for (Step &s : pou.steps) steps.push_back(&s);
  for (Action &a : pou.actions)
    for (Step &s : a.steps) steps.push_back(&s);
  for (Step *s : steps)
    for (ast::Association &as : s->associations) {
      const std::string n = upper(as.action.text);
      auto v = variables.find(n);
      if (v == variables.end() || actions.count(n)) continue;
      auto [it, fresh] = boolean_actions.emplace(n, std::string_view());
      if (fresh) {
        std::string name = std::string(v->second->name.text) + "_Q";
        while (names.declared(name)) name += '_';
        it->second = file.strings.emplace_back(std::move(name));
        Action &a = generated.emplace_back();
        a.name = {it->second, as.action.range};
        names.declare(a.name);
        a.range = as.action.range;
        ast::Stmt &st = a.body.emplace_back();
        st.kind = ast::Stmt::Kind::Assign;
        st.range = as.action.range;
        st.target.emplace(ast::Name{v->second->name.text, as.action.range});
        auto call = std::make_unique<ast::Expr>();
        call->kind = ast::Expr::Kind::Call;
        call->range = as.action.range;
        call->name = {"active", as.action.range};
        auto arg = std::make_unique<ast::Expr>();
        arg->kind = ast::Expr::Kind::Name;
        arg->range = as.action.range;
        arg->name = a.name;
        call->args.push_back(std::move(arg));
        st.value = std::move(call);
      }
      as.action = {it->second, as.action.range};
    }
  for (Action &a : generated) actions.emplace(upper(a.name.text), true);
  pou.actions.insert(pou.actions.begin(), std::make_move_iterator(generated.begin()),
                     std::make_move_iterator(generated.end()));
  return actions;
}

/// The names of a POU's scope: its variables, the steps of each of its SFCs, its actions. A
/// name declared again in another case (`Fill`, `FILL`) is an error here: IEC names are
/// case-insensitive and the chart language's are not, so the validator would take them for two.
/// One declared again in the same case is the validator's to report.
Spellings pou_names(const Pou &pou, Diagnostics &diag) {
  Spellings names;
  std::map<std::string, ast::Name> first;
  auto declare = [&](const ast::Name &n) {
    auto [it, fresh] = first.emplace(upper(n.text), n);
    if (!fresh && it->second.text != n.text)
      diag.error(n.range, ErrorKind::DuplicateName,
                 fmt::format("'{}' is declared again as '{}': IEC names are case-insensitive", it->second.text, n.text))
          .note(it->second.range, "the first declaration");
    names.declare(n);
  };
  for (const Variable &v : pou.variables) declare(v.name);
  for (const Step &s : pou.steps) declare(s.name);
  for (const Action &a : pou.actions) {
    declare(a.name);
    for (const Step &s : a.steps) declare(s.name);
  }
  return names;
}

/// `A.Q`, `A.A`, BOOL 0/1 in the conditions of the transitions of the SFCs inside actions.
void inner_conditions(Pou &pou, const std::map<std::string, bool> &actions, Diagnostics &diag) {
  for (Action &a : pou.actions)
    for (Transition &t : a.transitions)
      if (t.condition) action_flags(*t.condition, actions, diag);
}

/// A FUNCTION_BLOCK: a block of the chart language (docs/iec.md "Function blocks").
void lower_function_block(Pou &pou, ast::File &file, Diagnostics &diag, const KnownBlocks &known) {
  Spellings names = pou_names(pou, diag);
  Instances instances;
  ast::BlockDecl &b = file.blocks.emplace_back();
  b.name = pou.name;
  b.range = pou.range;
  for (Variable &v : pou.variables) {
    if (v.section == Section::InOut || v.section == Section::External) {
      // A VAR_IN_OUT is a reference to the caller's variable, a VAR_EXTERNAL a program's global;
      // an instance, inlined into the program, holds copies of its own (docs/iec.md "Function
      // blocks", "Global variables").
      const bool in_out = v.section == Section::InOut;
      diag.error(v.name.range, ErrorKind::NotSupported,
                 fmt::format("a {} in a function block ('{}' of '{}') is not supported yet: {}",
                             in_out ? "VAR_IN_OUT" : "VAR_EXTERNAL", v.name.text, pou.name.text,
                             in_out ? "pass it as an input and read it back as an output"
                                    : "declare it VAR_EXTERNAL in the PROGRAM and pass it to the block as an input"));
      continue;
    }
    if (v.constant) {
      diag.error(v.name.range, ErrorKind::NotSupported,
                 fmt::format("a constant in a function block ('{}') is not supported yet", v.name.text));
      continue;
    }
    ast::ValueDecl d = lower_variable(v, diag, &known);
    if (d.init) names.respell(*d.init);
    if (known.type(upper(v.type.text))) instances.emplace(upper(v.name.text), d.type.text);
    b.values.push_back(std::move(d));
  }
  const bool sfc = !pou.steps.empty() || !pou.transitions.empty();
  if (sfc && pou.body) {
    diag.error(
            pou.steps.empty() ? pou.transitions.front().range : pou.steps.front().range, ErrorKind::Syntax,
            fmt::format("function block '{}' has both statements and an SFC: IEC gives a POU one body", pou.name.text))
        .note(pou.body_range, "the statements");
    return;
  }
  // An SFC body (docs/iec.md "SFC inside actions and function blocks"): each call is one scan of
  // it, compiled into statements; the actions its steps hold run inside that scan.
  const std::map<std::string, bool> actions = boolean_actions(pou, names, file);
  const Spellings bools = bool_variables(pou.variables);
  for (Transition &t : pou.transitions)
    if (t.condition) action_flags(*t.condition, actions, diag);
  inner_conditions(pou, actions, diag);
  for (Action &a : pou.actions) {
    bool_literals_in(a.body, bools);
    action_flags_in(a.body, actions, diag);
  }
  InnerSfcs inner;
  if (sfc) inner = compile_inner_sfcs(pou, true, names, file, diag, std::nullopt);
  for (const Action &a : pou.actions)
    if (!inner.inner.count(upper(a.name.text)))
      diag.error(a.name.range, ErrorKind::NotSupported,
                 fmt::format("action '{}' of function block '{}' is held by no step{}: such an action runs only when "
                             "called ('inst.{}();'), which is not supported yet",
                             a.name.text, pou.name.text, sfc ? " of its SFC" : " (its body is no SFC)", a.name.text));
  for (ast::ValueDecl &v : inner.variables) b.values.push_back(std::move(v));
  if (pou.body) {
    bool_literals_in(*pou.body, bools);
    action_flags_in(*pou.body, {}, diag);  // `x.Q` outside an SFC is an instance's output
    names.respell_block(*pou.body);
    respell_members_in(*pou.body, instances, known, names, file.strings);
    rewrite_inner_reads(*pou.body, inner);
    b.body = std::move(*pou.body);
  }
}

/// Turns `pou` into an sfc of the chart language and appends it to `file.charts`: its variables
/// (BOOL, DINT, REAL, LREAL as bool, int, float, double, a known block's instances; every other
/// type a located "not supported yet" error), steps, transitions (ordered by PRIORITY within
/// their divergence), named actions and the period. A FUNCTION_BLOCK becomes a block of
/// `file.blocks`; a FUNCTION, or a PROGRAM whose body is not an SFC, is reported and adds
/// nothing. Returns whether a chart was added.
bool lower_pou(Pou &&pou, const std::optional<ast::Period> &period, ast::File &file, Diagnostics &diag,
               const KnownBlocks &known) {
  if (pou.kind == PouKind::FunctionBlock) {
    lower_function_block(pou, file, diag, known);
    return false;  // a block, not a program
  }
  if (pou.kind != PouKind::Program) {
    diag.error(pou.name.range, ErrorKind::NotSupported,
               fmt::format("{} '{}' is not supported yet: gfec compiles PROGRAMs", pou_kind(pou.kind), pou.name.text));
    return false;
  }
  if (pou.other_body) {
    for (Variable &v : pou.variables) lower_variable(v, diag);  // their problems too, in one pass
    diag.error(*pou.other_body, ErrorKind::NotSupported,
               fmt::format("program '{}': a body that is not a sequential function chart is not supported yet",
                           pou.name.text));
    return false;
  }
  if (pou.body && !pou.steps.empty()) {
    diag.error(pou.steps.front().range, ErrorKind::Syntax,
               fmt::format("program '{}' has both statements and an SFC: IEC gives a POU one body", pou.name.text))
        .note(pou.body_range, "the statements");
    return false;
  }
  Spellings names = pou_names(pou, diag);

  ast::Chart &c = file.charts.emplace_back();
  c.kind = ast::Chart::Kind::Sfc;
  c.name = pou.name;
  c.range = pou.range;
  if (period) c.periods.push_back(*period);
  Instances instances;
  for (Variable &v : pou.variables) {
    ast::ValueDecl d = lower_variable(v, diag, &known);
    if (d.init) names.respell(*d.init);
    if (known.type(upper(v.type.text))) instances.emplace(upper(v.name.text), d.type.text);
    c.values.push_back(std::move(d));
  }
  std::map<std::string, bool> actions = boolean_actions(pou, names, file);
  // `A.Q` and `A.A` are an action's flags or, `Q` of an instance, its output: told apart before
  // the members of instances are respelled.
  for (Transition &t : pou.transitions)
    if (t.condition) action_flags(*t.condition, actions, diag);
  inner_conditions(pou, actions, diag);
  const Spellings bools = bool_variables(pou.variables);
  for (Action &a : pou.actions) {
    bool_literals_in(a.body, bools);
    action_flags_in(a.body, actions, diag);
  }
  if (pou.body) {
    bool_literals_in(*pou.body, bools);
    action_flags_in(*pou.body, actions, diag);
  }
  // The SFCs inside actions become statements (docs/iec.md "SFC inside actions and function
  // blocks"): the actions their steps hold run inside them, not as the chart's.
  InnerSfcs inner =
      compile_inner_sfcs(pou, false, names, file, diag, period ? std::optional<double>(period->ms) : std::nullopt);
  for (ast::ValueDecl &v : inner.variables) c.values.push_back(std::move(v));
  if (pou.body) {
    // A body of statements: one initial step that is never left runs them every scan, as the
    // place block of step 4 of a tick (docs/iec.md "Programs without an SFC"). The step is
    // named Body, or Body_ (…) when the program has a name so.
    std::string step = "Body";
    while (names.declared(step)) step += '_';
    ast::Place &p = c.places.emplace_back();
    p.initial = true;
    p.has_body = true;
    p.name = {file.strings.emplace_back(std::move(step)), pou.name.range};
    p.range = pou.range;
    names.respell_block(*pou.body);
    respell_members_in(*pou.body, instances, known, names, file.strings);
    p.action = std::move(*pou.body);
  }
  for (Step &s : pou.steps) {
    ast::Place &p = c.places.emplace_back();
    p.initial = s.initial;
    p.name = s.name;
    p.range = s.range;
    if (!s.associations.empty()) {
      for (ast::Association &as : s.associations) {
        names.respell(as.action);
        std::string q = upper(as.qualifier.text);
        if (q != as.qualifier.text) as.qualifier.text = file.strings.emplace_back(std::move(q));
      }
      p.extra().associations = std::move(s.associations);
    }
  }
  order_by_priority(pou.transitions);  // PRIORITY first within a divergence (docs/iec.md)
  for (Transition &t : pou.transitions) {
    ast::Transition &x = c.transitions.emplace_back();
    for (ast::Name &n : t.from) names.respell(n);
    for (ast::Name &n : t.to) names.respell(n);
    x.set_places(t.from, t.to);
    x.parenthesised_inputs = t.parenthesised_from || t.from.size() != 1;
    x.parenthesised_outputs = t.parenthesised_to || t.to.size() != 1;
    if (t.name) {
      x.named = true;
      x.name = *t.name;
    }
    x.range = t.range;
    x.condition = std::move(t.condition);
    if (x.condition) names.respell(*x.condition);
    if (x.condition) respell_members(*x.condition, instances, known, file.strings);
  }
  // An unnamed transition is T<position> in the chart language, which a PLC program may have
  // given to another one (`TRANSITION T1 FROM ...` third in the file): such a one is named
  // T<position>_ instead (docs/iec.md), rather than the chart's duplicate-name error.
  std::set<std::string_view> taken;
  for (const Variable &v : pou.variables) taken.insert(v.name.text);
  for (const Step &st : pou.steps) taken.insert(st.name.text);
  for (const Action &a : pou.actions) taken.insert(a.name.text);
  for (const ast::Transition &t : c.transitions)
    if (t.named) taken.insert(t.name.text);
  for (std::size_t i = 0; i < c.transitions.size(); ++i) {
    ast::Transition &t = c.transitions[i];
    std::string name = fmt::format("T{}", i);
    if (t.named || !taken.count(name)) continue;
    while (taken.count(name)) name += '_';
    t.named = true;
    t.name = {file.strings.emplace_back(std::move(name)), t.range};
    taken.insert(t.name.text);
  }
  for (Action &a : pou.actions) {
    if (inner.inner.count(upper(a.name.text))) continue;
    ast::ActionDecl &d = c.actions.emplace_back();
    d.name = a.name;
    d.range = a.range;
    names.respell_block(a.body);
    respell_members_in(a.body, instances, known, names, file.strings);
    d.body = std::move(a.body);
  }
  for (ast::ValueDecl &v : c.values)
    if (v.init) action_flags(*v.init, actions, diag);
  written_inputs(c);
  if (period) {
    for (ast::Transition &t : c.transitions)
      if (t.condition) exact_step_times(*t.condition, period->ms);
    for (ast::ActionDecl &a : c.actions) exact_step_times_in(a.body, period->ms);
  }
  // The validator would ask for chart text's `period`; an IEC program gets it from its task.
  if (!period && !inner.period_reported)
    if (const SourceRange *at = time_read(c))
      diag.error(*at, ErrorKind::MissingPeriod,
                 fmt::format("program '{}' reads a time, but no TASK with an INTERVAL runs it", c.name.text))
          .note(c.name.range, fmt::format("run it in a task of a CONFIGURATION: 'TASK t (INTERVAL := T#10ms); "
                                          "PROGRAM i WITH t : {};', or give the period on the command line: "
                                          "'--period 10ms'",
                                          c.name.text));
  if (!inner.x.empty() || !inner.q.empty()) {
    for (ast::Transition &t : c.transitions)
      if (t.condition) rewrite_inner_reads(*t.condition, inner);
    for (ast::ActionDecl &a : c.actions) rewrite_inner_reads(a.body, inner);
    for (ast::Place &p : c.places) rewrite_inner_reads(p.action, inner);
  }
  return true;
}

/// A type as written, for comparing an external's with its global's: upper case, no spaces.
std::string type_key(std::string_view type) {
  std::string out;
  for (char c : upper(type))
    if (!std::isspace(static_cast<unsigned char>(c))) out += c;
  return out;
}

/// The file's VAR_GLOBALs by their upper-case names (one scope for all its configurations and
/// resources); a name declared twice is an error at the second.
std::map<std::string, const Variable *> global_scope(const Project &project, Diagnostics &diag) {
  std::map<std::string, const Variable *> scope;
  for (const Variable &g : project.globals) {
    auto [it, fresh] = scope.emplace(upper(g.name.text), &g);
    if (!fresh)
      diag.error(g.name.range, ErrorKind::DuplicateName,
                 fmt::format("global variable '{}' is declared twice", g.name.text))
          .note(it->second->name.range, "the first declaration");
  }
  return scope;
}

/// Each VAR_EXTERNAL of a PROGRAM becomes a variable of the program (Section::Local) with its
/// global's type, initial value, constness and address, so the lowering that follows makes it
/// what a VAR of the program would be, a located one's role from the address (docs/iec.md
/// "Global variables"). An external that matches no global is reported and stays a variable
/// of its own declaration, so the program is still checked.
void resolve_externals(Project &project, Diagnostics &diag) {
  const std::map<std::string, const Variable *> globals = global_scope(project, diag);
  struct User {
    std::string_view program;
    SourceRange at;
  };
  std::map<std::string, User> first_user;  ///< a global (upper case) -> the first program naming it
  for (Pou &p : project.pous) {
    if (p.kind != PouKind::Program) continue;
    for (Variable &v : p.variables) {
      if (v.section != Section::External) continue;
      v.section = Section::Local;
      const std::string key = upper(v.name.text);
      auto it = globals.find(key);
      if (it == globals.end()) {
        Diagnostic &d = diag.error(v.name.range, ErrorKind::UnknownName,
                                   fmt::format("'{}' is declared VAR_EXTERNAL in program '{}', but no VAR_GLOBAL of "
                                               "the file declares it",
                                               v.name.text, p.name.text));
        if (!suggest_nearest(d, v.name, project.globals,
                             [](const Variable &g) -> const ast::Name & { return g.name; }) &&
            project.globals.empty())
          // Beremiz declares the globals of its extensions (Python, HMI) outside the PLCopen file.
          d.note("the file declares no global variables: a CONFIGURATION or RESOURCE declares them in a "
                 "VAR_GLOBAL section (PLCopen: globalVars)");
        continue;
      }
      const Variable &g = *it->second;
      if (type_key(v.type.text) != type_key(g.type.text)) {
        diag.error(v.type.range, ErrorKind::TypeMismatch,
                   fmt::format("external '{}' is declared {} in program '{}', but the global is {}", v.name.text,
                               v.type.text, p.name.text, g.type.text))
            .note(g.type.range, "the global's type");
        continue;
      }
      if (g.constant && !v.constant)
        diag.error(v.name.range, ErrorKind::NotAssignable,
                   fmt::format("global '{}' is CONSTANT: program '{}' must declare it in a VAR_EXTERNAL CONSTANT "
                               "section",
                               g.name.text, p.name.text))
            .note(g.name.range, "the CONSTANT global");
      if (v.init)
        diag.error(v.init->range, ErrorKind::Syntax,
                   fmt::format("external '{}' takes its initial value from its VAR_GLOBAL: IEC gives a VAR_EXTERNAL "
                               "none",
                               v.name.text))
            .note(g.name.range, "the global");
      if (v.located)
        diag.error(*v.located, ErrorKind::Syntax,
                   fmt::format("external '{}' takes its address from its VAR_GLOBAL: IEC gives a VAR_EXTERNAL none",
                               v.name.text))
            .note(g.name.range, "the global");
      // Named as the global is, whatever case the program writes: the engine's field is the
      // global the configuration declares, the same in every program's engine.
      v.name.text = g.name.text;
      v.init = g.init ? clone(*g.init) : nullptr;
      v.constant = v.constant || g.constant;
      v.located = g.located;
      v.address = g.address;
      auto [user, fresh] = first_user.emplace(key, User{p.name.text, v.name.range});
      if (!fresh && upper(user->second.program) != upper(p.name.text))
        diag.warning(Warning::SharedGlobal, v.name.range,
                     fmt::format("global '{}' is external to program '{}' too: gfec compiles each program into an "
                                 "engine of its own, which holds its own '{}'",
                                 g.name.text, user->second.program, v.name.text))
            .note(user->second.at, fmt::format("program '{}' names it here", user->second.program));
    }
  }
}

}  // namespace

std::size_t lower(Project &&project, ast::File &file, Diagnostics &diag, std::optional<double> period_ms) {
  std::size_t added = 0;
  resolve_externals(project, diag);
  KnownBlocks known;
  // Beremiz's SVGHMI extension declares its HMI types in a library of its own, not in the project
  // file that uses them: each is another name of an elementary type (HMI_NODE of BOOL).
  static const char *const kHmiTypes[][2] = {{"HMI_SINT", "SINT"},     {"HMI_INT", "INT"},     {"HMI_DINT", "DINT"},
                                             {"HMI_LINT", "LINT"},     {"HMI_USINT", "USINT"}, {"HMI_UINT", "UINT"},
                                             {"HMI_UDINT", "UDINT"},   {"HMI_ULINT", "ULINT"}, {"HMI_REAL", "REAL"},
                                             {"HMI_STRING", "STRING"}, {"HMI_BOOL", "BOOL"},   {"HMI_NODE", "BOOL"}};
  for (const auto &h : kHmiTypes) known.aliases[h[0]] = h[1];
  for (const TypeAlias &a : project.aliases) known.aliases[upper(a.name.text)] = upper(a.base.text);
  // An alias that names itself, directly or through others, names no type: said once per cycle.
  std::map<std::string, std::string_view> alias_spelled;
  for (const TypeAlias &a : project.aliases) alias_spelled.emplace(upper(a.name.text), a.name.text);
  std::set<std::string> in_cycle;
  for (const TypeAlias &a : project.aliases) {
    const std::string self = upper(a.name.text);
    if (in_cycle.count(self)) continue;
    std::string chain(a.name.text), at = self;
    std::vector<std::string> members{self};
    for (std::size_t hops = 0; hops <= known.aliases.size(); ++hops) {
      auto it = known.aliases.find(at);
      if (it == known.aliases.end()) break;
      at = it->second;
      auto spelled = alias_spelled.find(at);
      chain += " -> " + (spelled == alias_spelled.end() ? at : std::string(spelled->second));
      if (at == self) {
        diag.error(a.name.range, ErrorKind::BadType,
                   fmt::format("data type '{}' names itself: {}", a.name.text, chain));
        in_cycle.insert(members.begin(), members.end());
        break;
      }
      members.push_back(at);
    }
  }
  for (const char *s : {"TON", "TOF", "TP", "R_TRIG", "F_TRIG", "SR", "RS", "CTU", "CTD", "CTUD"})
    if (is_standard_block(s)) known.spelled.emplace(s, s);
  for (const Pou &p : project.pous)
    if (p.kind == PouKind::FunctionBlock) {
      known.spelled[upper(p.name.text)] = std::string(p.name.text);
      Spellings &m = known.members[upper(p.name.text)];
      for (const Variable &v : p.variables) m.declare(v.name);
    }
  for (Pou &p : project.pous) {
    std::optional<ast::Period> period;
    // --period wins: the tasks' INTERVALs, even disagreeing ones, are not asked. Its range is
    // the program's name, the place a diagnostic about the period can point at.
    if (p.kind == PouKind::Program)
      period = period_ms ? ast::Period{*period_ms, p.name.range} : period_of(project, p, diag);
    if (lower_pou(std::move(p), period, file, diag, known)) ++added;
  }
  return added;
}

}  // namespace gfec::iec
