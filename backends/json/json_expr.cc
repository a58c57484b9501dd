#include "json_expr.h"

#include "chart_expr.h"
#include "code_writer.h"
#include "operators.h"

namespace gfec::json_backend {

namespace {

using model::Expr;

const char *kind_name(Expr::Kind k) {
  switch (k) {
  case Expr::Kind::Bool: return "bool";
  case Expr::Kind::Int: return "int";
  case Expr::Kind::Float: return "float";
  case Expr::Kind::String: return "string";
  case Expr::Kind::Ticks: return "duration";
  case Expr::Kind::Var: return "var";
  case Expr::Kind::Const: return "const";
  case Expr::Kind::Config: return "config";
  case Expr::Kind::Call: return "call";
  case Expr::Kind::Elapsed: return "elapsed";
  case Expr::Kind::Unary: return "unary";
  case Expr::Kind::Binary: return "binary";
  case Expr::Kind::Paren: return "paren";
  case Expr::Kind::Active: return "active";
  case Expr::Kind::Succeeded: return "succeeded";
  case Expr::Kind::Failed: return "failed";
  case Expr::Kind::TeamCount: return "team";
  case Expr::Kind::Agent: return "agent";
  case Expr::Kind::ActionQ: return "active";
  case Expr::Kind::ActionA: return "running";
  case Expr::Kind::Now: return "now";
  case Expr::Kind::Convert: return "convert";
  case Expr::Kind::Builtin: return "builtin";
  default: break;
  }
  return "?";
}

template <typename IdT, typename T> std::string name_at(const Table<IdT, T> &table, IdT id) {
  if (!table.contains(id)) return "?";
  return std::string(table[id].name);
}

/// A statement's "text": as written, or (ALICA) as --emit=chart writes it, lines joined by '\n'.
std::string statement_text(const model::Model &m, const Scope &scope, const model::Stmt &s) {
  if (in_chart_text(m, s.range) || !scope.chart) return source_text(m, s.range);
  CodeWriter w("", false);
  chart_text::statements(w, m, m.charts.id_of(*scope.chart), {s});
  std::string out = w.take();
  while (!out.empty() && out.back() == '\n') out.pop_back();
  return out;
}

}  // namespace

Json location(const model::Model &m, const SourceRange &range) {
  if (!m.sources().knows(range.file)) return nullptr;
  const SourceFile &file = m.sources().file(range.file);
  LineCol begin = file.line_col(range.begin), end = file.line_col(range.end);
  return {{"file", file.path()},
          {"line", begin.line},
          {"column", begin.col},
          {"end_line", end.line},
          {"end_column", end.col}};
}

Json expression_tree(const model::Model &m, const Scope &scope, const Expr &e) {
  Json j = {{"kind", kind_name(e.kind)}, {"type", model::type_name(e.type)}};
  auto args = [&] {
    Json a = Json::array();
    for (const auto &arg : e.args) a.push_back(expression_tree(m, scope, arg));
    return a;
  };
  switch (e.kind) {
  case Expr::Kind::Bool: j["value"] = e.bool_value; break;
  // The values the validator parsed from the spellings (a literal's value as C reads it).
  case Expr::Kind::Int:  // an integer of e.type, or a time in milliseconds
    if (e.type == model::Type::UInt64) j["value"] = static_cast<std::uint64_t>(e.int_value);
    else j["value"] = e.int_value;
    break;
  case Expr::Kind::Float: j["value"] = e.float_value; break;
  case Expr::Kind::String: j["value"] = e.text; break;
  case Expr::Kind::Ticks:
    j["ms"] = e.float_value;
    j["ticks"] = e.ticks;
    break;
  case Expr::Kind::Var: j["name"] = scope.chart ? name_at(scope.chart->vars, e.var()) : "?"; break;
  case Expr::Kind::Const: j["name"] = name_at(m.consts, e.constant()); break;
  case Expr::Kind::Config: j["name"] = scope.plan ? name_at(scope.plan->config, e.config()) : "?"; break;
  case Expr::Kind::Call:
    j["function"] = name_at(m.functions, e.function());
    j["args"] = args();
    break;
  case Expr::Kind::Elapsed: j["place"] = scope.chart ? name_at(scope.chart->places, e.place()) : "?"; break;
  case Expr::Kind::Unary:
    j["op"] = spelling(e.unary_op);
    j["args"] = args();
    break;
  case Expr::Kind::Binary:
    j["op"] = spelling(e.binary_op);
    j["args"] = args();
    break;
  case Expr::Kind::Paren:
  case Expr::Kind::Convert: j["args"] = args(); break;  // a conversion: to `type`
  case Expr::Kind::Builtin:                             // a standard function: "abs", "min", ...
    j["function"] = model::builtin_name(e.builtin);
    j["args"] = args();
    break;
  case Expr::Kind::Active: {
    // The names along the path, each a place or state of the chart the previous one runs.
    Json path = Json::array();
    const model::Chart *chart = scope.chart;
    for (model::PlaceId p : e.path) {
      path.push_back(chart ? name_at(chart->places, p) : "?");
      model::ChartId runs = chart && chart->places.contains(p) ? chart->places[p].runs : model::ChartId();
      chart = runs ? &m.charts.at(runs) : nullptr;
    }
    j["path"] = std::move(path);
    break;
  }
  case Expr::Kind::Succeeded:
  case Expr::Kind::Failed:
  case Expr::Kind::TeamCount: j["place"] = scope.chart ? name_at(scope.chart->places, e.place()) : "?"; break;
  case Expr::Kind::ActionQ:
  case Expr::Kind::ActionA: j["action"] = scope.chart ? name_at(scope.chart->actions, e.action()) : "?"; break;
  default: break;
  }
  return j;
}

std::string expression_text(const model::Model &m, const Scope &scope, const Expr &e) {
  if (in_chart_text(m, e.range) || !scope.chart) return source_text(m, e.range);
  return chart_text::expr(m, m.charts.id_of(*scope.chart), e);
}

Json expression(const model::Model &m, const Scope &scope, const Expr &e) {
  return {{"text", expression_text(m, scope, e)},
          {"type", model::type_name(e.type)},
          {"tree", expression_tree(m, scope, e)}};
}

Json statements(const model::Model &m, const Scope &scope, const std::vector<model::Stmt> &block) {
  Json out = Json::array();
  for (const auto &s : block) {
    Json j = {{"text", statement_text(m, scope, s)}};
    switch (s.kind) {
    case model::Stmt::Kind::Call:
      j["kind"] = "call";
      j["call"] = expression_tree(m, scope, s.expr);
      break;
    case model::Stmt::Kind::Assign:
      j["kind"] = "assign";
      j["var"] = scope.chart ? name_at(scope.chart->vars, s.var) : "?";
      j["op"] = spelling(s.op);
      j["value"] = expression_tree(m, scope, s.expr);
      break;
    case model::Stmt::Kind::Verbatim:
      j["kind"] = "verbatim";
      j["code"] = *s.verbatim;
      break;
    case model::Stmt::Kind::Break: j["kind"] = "break"; break;
    case model::Stmt::Kind::Return: j["kind"] = "return"; break;
    case model::Stmt::Kind::While:
    case model::Stmt::Kind::DoWhile:
      j["kind"] = s.kind == model::Stmt::Kind::While ? "while" : "do_while";
      j["condition"] = expression_tree(m, scope, s.expr);
      j["body"] = statements(m, scope, s.then_block);
      break;
    case model::Stmt::Kind::For:
      j["kind"] = "for";
      j["init"] = statements(m, scope, {s.else_block.front()})[0];
      j["condition"] = expression_tree(m, scope, s.expr);
      j["step"] = statements(m, scope, {s.else_block.back()})[0];
      j["body"] = statements(m, scope, s.then_block);
      break;
    case model::Stmt::Kind::Invoke: {
      // A block call: the instance, its arguments; the inlined body is the block's (blocks[]).
      j["kind"] = "invoke";
      std::string instance = "?";
      if (scope.chart)
        for (const model::Instance &i : scope.chart->instances)
          if (i.first == s.var) instance = i.name;
      j["instance"] = instance;
      j["args"] =
          statements(m, scope, std::vector<model::Stmt>(s.then_block.begin(), s.then_block.begin() + s.code_begin));
      break;
    }
    case model::Stmt::Kind::If:
      j["kind"] = "if";
      j["condition"] = expression_tree(m, scope, s.expr);
      j["then"] = statements(m, scope, s.then_block);
      j["else"] = statements(m, scope, s.else_block);
      j["else_if"] = s.else_if;
      break;
    }
    j["location"] = location(m, s.range);
    out.push_back(std::move(j));
  }
  return out;
}

}  // namespace gfec::json_backend
