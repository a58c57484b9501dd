#include "chart_expr.h"
#include "lexer.h"

#include "constant.h"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <limits>

namespace gfec::chart_text {

namespace {

/// A duration as the language writes it: whole milliseconds as "500ms", others as "1.5ms".
std::string duration(double ms) { return fmt::format("{}ms", ms); }

/// A sized integer's value as chart text reads it back: in decimal below 10^18 (the lexer reads
/// at most 18 digits), else as `T(Q) * 1000000000 + R`, which folds to the value.
std::string sized_literal(const model::Expr &e) {
  const constant::Value v = constant::Value::of_integer(e.type, e.int_value);
  const constant::Wide w = constant::wide(v), limit = static_cast<constant::Wide>(1000000000000000000);
  if (w < limit && w > -limit) return constant::decimal(v);
  const constant::Wide q = w / 1000000000, r = w % 1000000000;  // r has w's sign
  const auto text = [](constant::Wide x) {
    return constant::decimal(constant::Value::of_integer(model::Type::Int64, static_cast<std::int64_t>(x)));
  };
  return fmt::format("({}({}) * 1000000000 {} {})", model::type_name(e.type), text(q), r < 0 ? "-" : "+",
                     text(r < 0 ? -r : r));
}

std::string args_of(const model::Model &m, model::ChartId chart, const CompactVector<model::Expr> &args) {
  std::string out;
  for (const auto &a : args) out += (out.empty() ? "" : ", ") + expr(m, chart, a);
  return out;
}

std::string place_name(const model::Model &m, model::ChartId chart, model::PlaceId place) {
  return name(m.charts[chart].places[place].name.view());
}

}  // namespace

std::string name(std::string_view n) { return is_chart_keyword(n) ? fmt::format("`{}`", n) : std::string(n); }

std::string expr(const model::Model &m, model::ChartId chart, const model::Expr &e) {
  using K = model::Expr::Kind;
  const model::Chart &c = m.charts[chart];
  switch (e.kind) {
  case K::Bool: return e.bool_value ? "true" : "false";
  // INT_MIN has no literal (2147483648 does not fit an int): C's spelling, which reads back.
  case K::Int:
    // A time is written in milliseconds, a sized integer in decimal (its literal takes the type
    // of what it meets, docs/language.md §4).
    if (e.type == model::Type::Time) return constant::decimal(constant::Value::of_time(e.int_value)) + "ms";
    if (model::is_sized(e.type)) return sized_literal(e);
    return e.text.str() == "-2147483648" ? "(-2147483647 - 1)" : e.text.str();
  case K::Float: {
    // A float folded to FLT_MAX is spelled 3.4028235e+38, which as the double it reads back as
    // lies past FLT_MAX and is refused: then the value's own digits, as a double.
    const std::string text = e.text.str();
    const double read_back = std::strtod(text.c_str(), nullptr);
    if (e.type == model::Type::Float && std::fabs(read_back) > std::numeric_limits<float>::max())
      return fmt::format("{}", e.float_value);
    return text;
  }
  case K::String: return c_string_literal(e.text.str());
  case K::Ticks: return duration(e.float_value);
  case K::Var: return name(c.vars[e.var()].name);
  case K::Const: return m.consts[e.constant()].name;
  case K::Config: return m.plans.empty() ? "?" : "?";  // plans are not converted (see chart_backend.cc)
  case K::Call: return fmt::format("{}({})", m.functions[e.function()].name, args_of(m, chart, e.args));
  case K::Elapsed: return fmt::format("elapsed({})", place_name(m, chart, e.place()));
  case K::Unary: {
    std::string operand = expr(m, chart, e.args[0]);
    // "- -x" must not become "--x".
    std::string gap = !operand.empty() && operand[0] == '-' ? " " : "";
    return fmt::format("{}{}{}", spelling(e.unary_op), gap, operand);
  }
  case K::Binary:
    return fmt::format("{} {} {}", expr(m, chart, e.args[0]), spelling(e.binary_op), expr(m, chart, e.args[1]));
  case K::Paren: return fmt::format("({})", expr(m, chart, e.args[0]));
  case K::Active: {
    std::string path;
    model::ChartId in = chart;
    for (model::PlaceId place : e.path) {
      if (!in) break;
      if (!path.empty()) path += '.';
      path += place_name(m, in, place);
      in = m.charts[in].places[place].runs;
    }
    return fmt::format("active({})", path);
  }
  case K::Succeeded: return fmt::format("succeeded({})", place_name(m, chart, e.place()));
  case K::Failed: return fmt::format("failed({})", place_name(m, chart, e.place()));
  case K::TeamCount: return fmt::format("team({})", place_name(m, chart, e.place()));
  case K::Agent: return "agent()";
  case K::ActionQ: return fmt::format("active({})", name(c.actions[e.action()].name.view()));
  case K::ActionA: return fmt::format("running({})", name(c.actions[e.action()].name.view()));
  case K::Now: return "now()";
  case K::Convert: return fmt::format("{}({})", model::type_name(e.type), expr(m, chart, e.args[0]));
  case K::Builtin: return fmt::format("{}({})", model::builtin_name(e.builtin), args_of(m, chart, e.args));
  }
  return "";
}

void statements(CodeWriter &w, const model::Model &m, model::ChartId chart, const std::vector<model::Stmt> &block) {
  const model::Chart &c = m.charts[chart];
  for (const auto &s : block) {
    switch (s.kind) {
    case model::Stmt::Kind::Call: w.line("{};", expr(m, chart, s.expr)); break;
    case model::Stmt::Kind::Assign:
      w.line("{} {} {};", name(c.vars[s.var].name), spelling(s.op), expr(m, chart, s.expr));
      break;
    case model::Stmt::Kind::Verbatim: w.line("%{{{}%}}", *s.verbatim); break;
    case model::Stmt::Kind::Break: w.line("break;"); break;
    case model::Stmt::Kind::Return: w.line("return;"); break;
    case model::Stmt::Kind::While:
    case model::Stmt::Kind::DoWhile:
    case model::Stmt::Kind::For: {
      const std::string condition = expr(m, chart, s.expr);
      if (s.kind == model::Stmt::Kind::While) {
        w.line("while ({}) {{", condition);
      } else if (s.kind == model::Stmt::Kind::DoWhile) {
        w.line("do {");
      } else {
        auto part = [&](const model::Stmt &a) {
          return fmt::format("{} {} {}", c.vars[a.var].name, spelling(a.op), expr(m, chart, a.expr));
        };
        w.line("for ({}; {}; {}) {{", part(s.else_block.front()), condition, part(s.else_block.back()));
      }
      {
        auto body = w.indented();
        statements(w, m, chart, s.then_block);
      }
      if (s.kind == model::Stmt::Kind::DoWhile) w.line("}} while ({});", condition);
      else w.line("}");
      break;
    }
    case model::Stmt::Kind::Invoke: {
      // `inst(a = e, ...)`: the arguments are the first code_begin statements, the rest the
      // block's body, which the block's declaration writes.
      std::string instance = "?";
      for (const model::Instance &i : c.instances)
        if (i.first == s.var) instance = i.name;
      std::string args;
      for (std::uint32_t k = 0; k < s.code_begin; ++k) {
        const model::Stmt &a = s.then_block[k];
        const std::string &member = c.vars[a.var].name;
        args += fmt::format("{}{} = {}", k ? ", " : "", member.substr(member.rfind('.') + 1), expr(m, chart, a.expr));
      }
      w.line("{}({});", instance, args);
      break;
    }
    case model::Stmt::Kind::If: {
      const model::Stmt *at = &s;
      std::string lead = "if";
      for (;;) {
        w.line("{} ({}) {{", lead, expr(m, chart, at->expr));
        {
          auto then = w.indented();
          statements(w, m, chart, at->then_block);
        }
        if (at->else_if && at->else_block.size() == 1) {
          at = &at->else_block.front();
          lead = "} else if";
          continue;
        }
        if (!at->else_block.empty()) {
          w.line("} else {");
          auto otherwise = w.indented();
          statements(w, m, chart, at->else_block);
        }
        w.line("}");
        break;
      }
      break;
    }
    }
  }
}

}  // namespace gfec::chart_text
