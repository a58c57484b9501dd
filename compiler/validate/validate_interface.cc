// Interfaces (§3): the C prototypes of the robot's functions, and file-level constants (§4).
#include "validate/families.h"
#include "validate/fold.h"
#include "validate/types.h"

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

}  // namespace

void declare_interface(Context &cx, const ast::Interface &iface) {
  cx.declare_global(cx.interfaces, iface.name, Sym::Interface);
  for (const ast::FunctionDecl &f : iface.functions) {
    model::Function out;
    out.name = f.name.text;
    out.interface_name = iface.name.text;
    out.range = f.range;
    bool ok = lower_prototype(f, out, cx.diag);
    for (const char *builtin : {"elapsed", "active", "succeeded", "failed", "agent"})
      if (f.name.text == builtin)
        cx.diag.error(f.name.range, ErrorKind::ReservedName,
                      fmt::format("'{}' is built into the chart language and cannot name a function", builtin));
    const model::FunctionId index = cx.model.functions.next_id();
    cx.model.functions.push_back(std::move(out));
    cx.function_ok.push_back(ok);
    cx.declare_global(cx.c_names, f.name, Sym::Function, index);
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
