// Blocks (docs/language.md "Blocks"): see blocks.h. A block is validated once, on its first
// instance, as a chart without places whose vars are its members; each call then inlines a copy
// of its lowered body with every var moved to the instance's.
#include "validate/blocks.h"

#include "did_you_mean.h"
#include "standard_blocks.h"
#include "validate/fold.h"
#include "validate/suggest.h"
#include "validate/types.h"

#include <fmt/format.h>

#include <algorithm>
#include <set>

namespace gfec::validation {

namespace {

using model::Type;

/// Moves every var an expression or statement names by `offset`: the block's vars become the
/// instance's, which sit at vars[first, first + count) of the holder.
void shift(model::Expr &e, std::size_t offset) {
  if (e.kind == model::Expr::Kind::Var) e.refer_to(model::VarId(e.var().index() + offset));
  for (model::Expr &a : e.args) shift(a, offset);
}

void shift(model::Stmt &s, std::size_t offset) {
  if ((s.kind == model::Stmt::Kind::Assign || s.kind == model::Stmt::Kind::Invoke) && s.var.valid())
    s.var = model::VarId(s.var.index() + offset);
  shift(s.expr, offset);
  for (model::Stmt &t : s.then_block) shift(t, offset);
  for (model::Stmt &t : s.else_block) shift(t, offset);
}

bool ensure_block(Context &cx, model::BlockId id, SourceRange used_at);

/// A plain member (in, out, var) of the block being validated, as a chart declares a var.
void declare_member(Context &cx, ChartScope &s, const ast::ValueDecl &v) {
  if (v.is_const) return;  // the parser refuses constants in a block
  auto type = lower_type(v.type, kValue, "a variable", cx.diag);
  const auto role = static_cast<model::VarRole>(v.role);
  model::VarId index;
  if (type) {
    index = s.out.vars.next_id();
    s.out.vars.push_back({std::string(v.name.text), *type, role, std::nullopt, v.range, {}});
  }
  s.names.declare(v.name, Sym::Var, index, cx.diag);
}

bool ensure_block(Context &cx, model::BlockId id, SourceRange used_at) {
  BlockSource &src = cx.block_sources[id];
  model::Block &block = cx.model.blocks[id];
  switch (src.state) {
  case BlockSource::State::Done: return true;
  case BlockSource::State::Failed: return false;
  case BlockSource::State::Busy:
    cx.diag
        .error(used_at, ErrorKind::TypeMismatch, fmt::format("block '{}' contains an instance of itself", block.name))
        .note(block.name_range, fmt::format("'{}' declared here", block.name));
    return false;
  case BlockSource::State::Pending: break;
  }
  src.state = BlockSource::State::Busy;
  ErrorWatch watch(cx.diag);
  ast::BlockDecl &decl = *src.decl;
  ast::Chart shell;
  shell.kind = ast::Chart::Kind::Sfc;
  shell.name = decl.name;
  shell.range = decl.range;
  model::Chart out;
  out.name = decl.name.text;
  out.range = decl.range;
  out.name_range = decl.name.range;
  ChartScope scope(shell, out, model::ChartId());
  scope.names.uses = cx.uses;
  ChartScope *outer = cx.chart;
  cx.chart = &scope;
  for (const ast::ValueDecl &v : decl.values)
    if (!declare_instance(cx, scope, v)) declare_member(cx, scope, v);
  for (const ast::ValueDecl &v : decl.values) {
    const Symbol *sym = scope.names.find(v.name.text);
    if (!sym || sym->kind != Sym::Var || sym->index < 0 || !v.init || sym->range.begin != v.name.range.begin) continue;
    ExprScope init_scope{cx, &scope, true};
    model::Var &var = out.vars[sym->id<model::VarId>()];
    var.init = lower_initializer(v.init.get(), init_scope, var.type, var.name);
  }
  ExprScope body_scope{cx, &scope, false};
  std::vector<model::Stmt> body = lower_block(decl.body, body_scope);
  cx.chart = outer;
  block.vars.assign(out.vars.begin(), out.vars.end());
  block.instances = std::move(out.instances);
  block.body = std::move(body);
  block.clock = out.clock;
  block.functions.assign(scope.functions.begin(), scope.functions.end());
  block.consts.assign(scope.consts.begin(), scope.consts.end());
  src.state = watch.clean() ? BlockSource::State::Done : BlockSource::State::Failed;
  return src.state == BlockSource::State::Done;
}

/// The instance `name` names in the chart of `s`, or null after reporting why not.
const model::Instance *find_instance(const ast::Name &name, ExprScope &s) {
  if (!s.chart || name.text.empty()) return nullptr;
  const Symbol *sym = s.chart->names.resolve(name);
  if (!sym) {
    report_unknown(s.cx.diag, s.chart->unknown, name, "block instance", s.chart->names.of({Sym::Instance}));
    return nullptr;
  }
  if (sym->kind != Sym::Instance) {
    s.cx.diag
        .error(name.range, ErrorKind::TypeMismatch,
               fmt::format("'{}' is {}, not a block instance", name.text, with_article(sym->kind)))
        .note(sym->range, fmt::format("'{}' declared here", name.text));
    return nullptr;
  }
  if (sym->index < 0) return nullptr;  // its block has an error
  return &s.chart->out.instances[static_cast<std::size_t>(sym->index)];
}

/// The member `member` of `inst` with the role `role` (In: set, Out: read), as its var in the
/// holder; none after reporting why not, with the nearest member of that role.
model::VarId find_member(const model::Instance &inst, const ast::Name &member, model::VarRole role, ExprScope &s) {
  const model::Block &b = s.cx.model.blocks[inst.block];
  const char *wanted = role == model::VarRole::In ? "input" : "output";
  for (std::size_t k = 0; k < b.vars.size(); ++k) {
    const model::Var &v = b.vars[k];
    if (v.name != member.text) continue;
    if (v.role != role) {
      const char *is = v.role == model::VarRole::In    ? "an input"
                       : v.role == model::VarRole::Out ? "an output"
                                                       : "internal";
      s.cx.diag
          .error(member.range, ErrorKind::TypeMismatch,
                 fmt::format("'{}' is {} of block '{}', not an {}", member.text, is, b.name, wanted))
          .note(v.range, fmt::format("'{}' declared here", member.text));
      return {};
    }
    return model::VarId(inst.first.index() + k);
  }
  auto &d = s.cx.diag.error(member.range, ErrorKind::UnknownName,
                            fmt::format("block '{}' has no {} '{}'", b.name, wanted, member.text));
  NearestName nearest(member.text, typo_limit(member.text.size()));
  const model::Var *best = nullptr;
  for (const model::Var &v : b.vars)
    if (v.role == role && nearest.offer(v.name)) best = &v;
  if (best) d.fix(member.range, best->name).note(best->range, fmt::format("did you mean '{}'?", best->name));
  return {};
}

/// `e` assigned to member `var` of the holder (a block's input), or none after reporting.
std::optional<model::Stmt> assign_member(model::VarId var, const ast::Name &shown, const ast::Expr *value_expr,
                                         SourceRange range, ExprScope &s) {
  auto value = lower_expr(value_expr, s);
  if (!value || !var.valid()) return std::nullopt;
  const model::Var &target = s.chart->out.vars[var];
  if (!assignable_value(*value, target.type, s)) return std::nullopt;
  if (!assignable(target.type, value->type)) {
    s.cx.diag.error(value->range, ErrorKind::TypeMismatch,
                    fmt::format("incompatible types when assigning to '{}' of type {} from type {}", shown.text,
                                quoted(target.type), quoted(value->type)));
    return std::nullopt;
  }
  model::Stmt out;
  out.kind = model::Stmt::Kind::Assign;
  out.range = range;
  out.var = var;
  out.expr = std::move(*value);
  return out;
}

}  // namespace

void collect_blocks(Context &cx) {
  for (auto &file : cx.program.files) {
    if (!file) continue;
    for (ast::BlockDecl &decl : file->blocks) {
      const model::BlockId id = cx.model.blocks.next_id();
      model::Block b;
      b.name = decl.name.text;
      b.standard = decl.standard;
      b.range = decl.range;
      b.name_range = decl.name.range;
      cx.model.blocks.push_back(std::move(b));
      cx.block_sources.push_back({&decl, BlockSource::State::Pending});
      if (cx.blocks.declare(decl.name, Sym::Block, id, cx.diag)) check_reserved(decl.name, Sym::Block, cx.diag);
    }
  }
}

void validate_unused_blocks(Context &cx) {
  for (model::BlockId id : cx.model.blocks.ids())
    if (!cx.model.blocks[id].standard) ensure_block(cx, id, cx.model.blocks[id].name_range);
}

namespace {

/// `var TONN t;`: a type that is no type but near a block's name is a misspelt block: reported
/// with the block, and the instance declared (with an error) so its uses stay quiet.
bool misspelt_block(Context &cx, ChartScope &s, const ast::ValueDecl &v) {
  for (const char *scalar : {"bool", "int", "float", "double", "void", "string", "object"})
    if (v.type.text == scalar) return false;
  if (v.type.text.empty() || v.type.text.size() > kMaxSuggestedLength) return false;
  NearestName nearest(v.type.text, typo_limit(v.type.text.size()));
  std::string best;
  for (const Symbol *b : cx.blocks.of({Sym::Block}))
    if (nearest.offer(b->name())) best = b->name();
  for (std::string_view n : standard_block_names())
    if (nearest.offer(n)) best = n;
  if (best.empty()) return false;
  cx.diag.error(v.type.range, ErrorKind::UnknownType, fmt::format("unknown type name '{}'", v.type.text))
      .fix(v.type.range, best)
      .note(fmt::format("did you mean the block '{}'?", best));
  s.names.declare(v.name, Sym::Instance, -1, cx.diag);
  return true;
}

}  // namespace

bool declare_instance(Context &cx, ChartScope &s, const ast::ValueDecl &v) {
  if (v.is_const) return false;
  if (!cx.blocks.find(v.type.text)) return misspelt_block(cx, s, v);
  const Symbol *sym = cx.blocks.resolve(ast::Name{v.type.text, v.type.range});
  if (v.role != ast::VarRole::Local)
    cx.diag.error(v.range, ErrorKind::ChartIo,
                  fmt::format("block instance '{}' is declared 'var', not '{}'", v.name.text,
                              model::role_keyword(static_cast<model::VarRole>(v.role))));
  if (v.init)
    cx.diag.error(v.init->range, ErrorKind::TypeMismatch,
                  fmt::format("block instance '{}' takes no initial value: its members start as block '{}' says",
                              v.name.text, v.type.text));
  int index = -1;
  const model::BlockId block = sym->id<model::BlockId>();
  if (ensure_block(cx, block, v.type.range)) {
    model::Block &b = cx.model.blocks[block];
    b.used = true;
    if (b.clock) {
      // The block reads the time of the tick: its holder's period (docs/language.md §15).
      ExprScope scope{cx, &s, false};
      if (s.index.valid()) require_period(scope, v.type.range, fmt::format("block '{}' (it reads now())", b.name));
      s.out.clock = true;
    }
    model::Instance inst;
    inst.name = v.name.text;
    inst.block = block;
    inst.first = s.out.vars.next_id();
    inst.count = static_cast<std::uint32_t>(b.vars.size());
    inst.range = v.range;
    for (const model::Var &m : b.vars) {
      model::Var copy = m;
      copy.name = fmt::format("{}.{}", v.name.text, m.name);
      copy.role = model::VarRole::Local;  // the instance's inputs and outputs are not the holder's
      s.out.vars.push_back(std::move(copy));
    }
    for (const model::Instance &inner : b.instances) {
      model::Instance nested = inner;
      nested.name = fmt::format("{}.{}", v.name.text, inner.name);
      nested.first = model::VarId(inst.first.index() + inner.first.index());
      s.out.instances.push_back(std::move(nested));
    }
    index = static_cast<int>(s.out.instances.size());
    s.out.instances.push_back(std::move(inst));
  }
  s.names.declare(v.name, Sym::Instance, index, cx.diag);
  return true;
}

bool names_instance(const ast::Name &name, ExprScope &s) {
  if (!s.chart) return false;
  const Symbol *sym = s.chart->names.find(name.text);
  return sym && sym->kind == Sym::Instance;
}

std::optional<model::Expr> lower_member(const ast::Expr &path, ExprScope &s) {
  if (path.args.size() != 2 || !path.args[0] || !path.args[1] || !s.chart ||
      (s.chart->names.find(path.args[0]->name.text) && !names_instance(path.args[0]->name, s))) {
    s.cx.diag.error(path.range, ErrorKind::Syntax,
                    "a path to a sub-chart's place is only read through 'active(...)'; 'a.b' reads output b of "
                    "block instance a");
    return std::nullopt;
  }
  const model::Instance *inst = find_instance(path.args[0]->name, s);
  if (!inst) return std::nullopt;
  if (s.constant) {
    s.cx.diag.error(path.range, ErrorKind::NotConstant, "a constant expression cannot read a block's output");
    return std::nullopt;
  }
  model::VarId var = find_member(*inst, path.args[1]->name, model::VarRole::Out, s);
  if (!var.valid()) return std::nullopt;
  model::Expr e;
  e.kind = model::Expr::Kind::Var;
  e.type = s.chart->out.vars[var].type;
  e.range = path.range;
  e.refer_to(var);
  return e;
}

std::optional<model::Stmt> lower_member_assign(const ast::Stmt &st, ExprScope &s) {
  const ast::Name &target = *st.target;
  const std::size_t dot = target.text.find('.');
  const ast::Name inst_name{
      target.text.substr(0, dot),
      {target.range.file, target.range.begin, target.range.begin + static_cast<std::uint32_t>(dot)}};
  const ast::Name member{target.text.substr(dot + 1),
                         {target.range.file,
                          target.range.end - static_cast<std::uint32_t>(target.text.size() - dot - 1),
                          target.range.end}};
  const model::Instance *inst = find_instance(inst_name, s);
  if (!inst) {
    lower_expr(st.value.get(), s);  // its own errors
    return std::nullopt;
  }
  if (st.assign_op != AssignOp::Set) {
    s.cx.diag.error(target.range, ErrorKind::NotAssignable,
                    fmt::format("an input of a block instance is set with '=', not '{}'", spelling(st.assign_op)));
    return std::nullopt;
  }
  return assign_member(find_member(*inst, member, model::VarRole::In, s), target, st.value.get(), st.range, s);
}

std::optional<model::Stmt> lower_invoke(const ast::Stmt &st, ExprScope &s) {
  const bool plain_call = st.kind == ast::Stmt::Kind::Call;
  const ast::Name &name = plain_call ? st.call->name : *st.target;
  const model::Instance *inst = find_instance(name, s);
  if (plain_call && !st.call->args.empty()) {
    s.cx.diag.error(st.call->range, ErrorKind::TypeMismatch,
                    fmt::format("a block's arguments are named: '{}(input = value, ...)'", name.text));
    return std::nullopt;
  }
  std::vector<model::Stmt> args;
  std::set<std::string_view> given;
  bool ok = inst != nullptr;
  // An IEC non-formal call (`CU_T(CU);`, read from structured text only) binds its arguments to
  // the block's inputs in declaration order, and may not mix with named ones.
  std::vector<const model::Var *> inputs;
  if (inst)
    for (const model::Var &v : s.cx.model.blocks[inst->block].vars)
      if (v.role == model::VarRole::In) inputs.push_back(&v);
  std::size_t positional = 0;
  const bool mixed =
      std::any_of(st.then_block.begin(), st.then_block.end(),
                  [](const ast::Stmt &a) { return a.target.has_value(); }) &&
      std::any_of(st.then_block.begin(), st.then_block.end(), [](const ast::Stmt &a) { return !a.target; });
  for (const ast::Stmt &a : st.then_block) {
    if (!inst) {
      lower_expr(a.value.get(), s);
      continue;
    }
    if (!a.target && (mixed || positional == inputs.size())) {
      const model::Block &b = s.cx.model.blocks[inst->block];
      if (mixed)
        s.cx.diag.error(a.range, ErrorKind::TypeMismatch,
                        fmt::format("the call of '{}' names some arguments and not others: name them all "
                                    "('input := value')",
                                    name.text));
      else
        s.cx.diag
            .error(a.range, ErrorKind::TypeMismatch,
                   fmt::format("too many arguments in the call of '{}': block '{}' has {} input{}", name.text, b.name,
                               inputs.size(), inputs.size() == 1 ? "" : "s"))
            .note(b.name_range, fmt::format("block '{}' declared here", b.name));
      ok = false;
      break;
    }
    const ast::Name member = a.target ? *a.target : ast::Name{inputs[positional++]->name, a.range};
    if (!given.insert(member.text).second) {
      s.cx.diag.error(member.range, ErrorKind::DuplicateName, fmt::format("input '{}' given twice", member.text));
      ok = false;
      continue;
    }
    auto assign = assign_member(find_member(*inst, member, model::VarRole::In, s), member, a.value.get(), a.range, s);
    if (assign) args.push_back(std::move(*assign));
    else ok = false;
  }
  if (!ok) return std::nullopt;
  const model::Block &b = s.cx.model.blocks[inst->block];
  model::Stmt out;
  out.kind = model::Stmt::Kind::Invoke;
  out.range = st.range;
  out.var = inst->first;
  out.code_begin = static_cast<std::uint32_t>(args.size());
  for (const model::Stmt &body : b.body) {
    args.push_back(body);
    shift(args.back(), inst->first.index());
  }
  out.then_block = std::move(args);
  s.chart->functions.insert(b.functions.begin(), b.functions.end());
  s.chart->consts.insert(b.consts.begin(), b.consts.end());
  return out;
}

}  // namespace gfec::validation
