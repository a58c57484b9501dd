// Interfaces (§3): the C prototypes of the robot's functions, and file-level constants (§4).
#include "validate/families.h"
#include "validate/fold.h"
#include "validate/types.h"

#include "naming/naming.h"
#include "roots.h"

#include <fmt/format.h>

namespace gfec::validation {

namespace {

/// Lowers one prototype; false if a type in it is wrong (calls of it are then not checked).
bool lower_prototype(const ast::FunctionDecl &f, model::Function &out, Diagnostics &diag) {
  bool ok = true;
  if (auto t = lower_type(f.result, kScalar | kVoid, "a function result", diag)) out.result = *t;
  else ok = false;
  Namespace params;
  for (const ast::Param &p : f.params) {
    model::Param mp;
    if (auto t = lower_type(p.type, kScalar, "a parameter", diag)) mp.type = *t;
    else ok = false;
    if (p.name) {
      mp.name = p.name->text;
      params.declare(*p.name, Sym::Param, -1, diag);
    }
    out.params.push_back(std::move(mp));
  }
  return ok;
}

/// The C library function gcc or clang know (they warn about a declaration of it with another
/// prototype) that `fn` is named after, or null; `same` tells whether `fn` has its prototype.
const naming::CFunction *builtin_library_function(const model::Function &fn, bool &same) {
  const naming::CFunction *lib = naming::c_library_function(fn.name);
  if (!lib || !lib->builtin) return nullptr;
  std::vector<std::string_view> params;
  for (const model::Param &p : fn.params) params.emplace_back(model::type_name(p.type));
  same = naming::matches(*lib, model::type_name(fn.result), params);
  return lib;
}

/// gcc and clang know many C library functions (compiler/naming/c_library.def): an interface
/// function of that name with another prototype makes them warn about the engine's header,
/// where the prototype is written (docs/language.md "Reserved words").
void check_library_function(Context &cx, const ast::FunctionDecl &f, const model::Function &out) {
  bool same = false;
  const naming::CFunction *lib = builtin_library_function(out, same);
  if (!lib || same) return;
  std::string known = lib->type.empty() ? "a function of the C library"
                                        : fmt::format("the C library's '{}'", naming::c_declaration(*lib));
  auto &d = cx.diag.warning(Warning::LibraryFunction, f.name.range,
                            fmt::format("'{}' is {}, which gcc or clang know: this prototype differs, and they warn "
                                        "about it in the engine's header",
                                        f.name.text, known));
  const std::string_view proto = lib->prototype;
  const std::size_t paren = proto.find('(');
  if (proto.empty())  // no prototype of gfec's types is the library's (printf's, malloc's)
    d.note(fmt::format("rename the function, or build the engine with -fno-builtin-{}", lib->name));
  else if (proto.substr(paren) == "()")  // isnan: a result, and parameters C does not promote
    d.note(fmt::format("declare it with a result of type {} and parameters of type int or double, rename it, or "
                       "build the engine with -fno-builtin-{}",
                       proto.substr(0, paren), lib->name));
  else
    d.note(fmt::format("declare it as the library's '{} {}{}', rename it, or build the engine with -fno-builtin-{}",
                       proto.substr(0, paren), lib->name, proto.substr(paren), lib->name));
}

}  // namespace

void declare_interface(Context &cx, const ast::Interface &iface) {
  cx.declare_global(cx.interfaces, iface.name, Sym::Interface);
  for (const ast::FunctionDecl &f : iface.functions) {
    model::Function out;
    out.name = f.name.text;
    out.interface_name = iface.name.text;
    out.range = f.range;
    bool ok = lower_prototype(f, out, cx.diag);
    if (ok) check_library_function(cx, f, out);
    const model::FunctionId index = cx.model.functions.next_id();
    cx.model.functions.push_back(std::move(out));
    cx.function_ok.push_back(ok);
    cx.declare_global(cx.c_names, f.name, Sym::Function, index);
  }
}

void check_engine_names(Context &cx) {
  // `P_init` is a chart P's engine's (naming::engine_names), whatever chart is compiled: the
  // engine's names are the contract and never move, so the function would clash in the header.
  for (const Context::GlobalName &g : cx.global_names) {
    if (g.kind != Sym::Function) continue;
    const std::string_view name = g.name->text;
    for (std::size_t bar = name.find('_'); bar != std::string_view::npos; bar = name.find('_', bar + 1)) {
      const Symbol *chart = cx.c_names.find(name.substr(0, bar));
      if (!chart || chart->kind != Sym::Chart || !naming::engine_name(chart->name(), name)) continue;
      cx.diag
          .error(g.name->range, ErrorKind::ReservedName,
                 fmt::format("'{}' is a name the C engine of chart '{}' defines (docs/c-engine.md) and cannot name "
                             "a function",
                             name, chart->name()))
          .note(chart->range, fmt::format("chart '{}' declared here", chart->name()));
      break;
    }
  }
}

void declare_file_const(Context &cx, const ast::ValueDecl &decl) {
  model::Const c;
  c.name = decl.name.text;
  c.range = decl.range;
  auto type = lower_type(decl.type, kScalar | kString, "a constant", cx.diag);
  c.type = type.value_or(model::Type::Int);
  const model::ConstId index = cx.model.consts.next_id();
  cx.model.consts.push_back(std::move(c));
  cx.consts.push_back({&decl, type ? ConstSource::State::Pending : ConstSource::State::Failed});
  cx.declare_global(cx.c_names, decl.name, Sym::Const, index);
}

void fold_file_consts(Context &cx) {
  // Every constant is folded, used or not, so each bad one is reported where it is declared.
  for (model::ConstId c : cx.consts.ids()) fold_const(cx, c);
}

}  // namespace gfec::validation

namespace gfec {

void check_context_prototypes(const model::Model &model, model::ChartId chart, Diagnostics &diag) {
  // The functions of the chart and of every chart it runs, each once, in declaration order.
  const IdMap<model::ChartId, bool> tree = charts_in_tree(model, chart);
  IdMap<model::FunctionId, bool> called(model.functions.size(), false);
  for (model::ChartId c : tree.ids())
    if (tree[c])
      for (model::FunctionId f : model.charts[c].functions) called[f] = true;
  for (model::FunctionId f : model.functions.ids()) {
    if (!called[f]) continue;
    const model::Function &fn = model.functions[f];
    bool same = false;
    const naming::CFunction *lib = validation::builtin_library_function(fn, same);
    if (!lib || !same) continue;  // another prototype was warned about already (check_library_function)
    diag.warning(Warning::LibraryFunction, fn.range,
                 fmt::format("with --context '{}' takes the context first, so it is no longer the C library's "
                             "'{}', which gcc or clang know: they warn about it in the engine's header",
                             fn.name, naming::c_declaration(*lib)))
        .note(fmt::format("rename the function, or build the engine with -fno-builtin-{}", fn.name));
  }
}

}  // namespace gfec
