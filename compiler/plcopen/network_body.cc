// FBD and LD networks as the structured text they mean, which the ST parser then reads: Beremiz
// hands MatIEC its graphical bodies the same way. The text is built piece by piece with each
// piece located at the element it came from (LocatedText's breaks), so that an error in it —
// an unknown variable behind a contact, a type error at a block — points into the XML file.
// docs/iec.md "FBD and LD bodies" has the rules; the graph, as for SFC bodies, is read from
// localId/refLocalId alone.
#include "escape.h"
#include "iec/iec_text.h"
#include "plcopen/reader_context.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>
#include <map>
#include <set>

namespace gfec::plcopen {

namespace {

/// An FBD/LD data path deeper than this is not a network a person draws; the bound keeps a
/// hostile file from exhausting the stack.
constexpr int kMaxDepth = 200;
/// A function's output read by several inputs is written out at each: a network of outputs
/// that fan out again and again would double its text at each level. Past this size, a network
/// is reported rather than written.
constexpr std::size_t kMaxText = 1 << 20;

bool attribute_true(const pugi::xml_node &n, const char *name) {
  std::string_view v = n.attribute(name).value();
  return v == "true" || v == "1";
}

/// How a standard function gfec reads as an ST operator is written: its ST operator, whether it
/// takes any number of inputs (ADD, AND …) and whether a chain of comparisons (GT(a, b, c) is
/// a > b AND b > c).
struct Operator {
  const char *name;
  const char *st;
  bool extensible;
  bool comparison;
};

constexpr Operator kOperators[] = {
    {"ADD", "+", true, false},    {"MUL", "*", true, false},   {"SUB", "-", false, false}, {"DIV", "/", false, false},
    {"MOD", "MOD", false, false}, {"AND", "AND", true, false}, {"OR", "OR", true, false},  {"XOR", "XOR", true, false},
    {"GT", ">", true, true},      {"GE", ">=", true, true},    {"EQ", "=", true, true},    {"LT", "<", true, true},
    {"LE", "<=", true, true},     {"NE", "<>", false, true},
};

/// Whether an expression's text is one name or literal (blanks round it aside), which needs no
/// brackets where it is used.
bool is_atom(std::string_view text) {
  const std::size_t first = text.find_first_not_of(" \t\r\n");
  if (first == std::string_view::npos) return false;
  const std::size_t last = text.find_last_not_of(" \t\r\n");
  return text.substr(first, last - first + 1).find_first_of("+-*/<>=&|:,()^ \t") == std::string_view::npos;
}

const Operator *operator_of(const std::string &type) {
  for (const Operator &o : kOperators)
    if (type == o.name) return &o;
  return nullptr;
}

}  // namespace

/// One FBD or LD body (or the FBD/LD elements of an SFC body) by localId, and the ST text its
/// values and statements are.
class Network {
public:
  Network(Reader &r, const pugi::xml_node &body) : r_(r) {
    for (pugi::xml_node n : body.children()) {
      if (n.type() != pugi::node_element) continue;
      if (auto id = n.attribute("localId")) by_id_.emplace(id.value(), n);
      if (local_name(n) == "connector") connectors_.emplace(iec::upper(n.attribute("name").value()), n);
      elements_.push_back(n);
    }
  }

  /// Appends the value flowing into `point` (a connectionPointIn) to `out`; false after
  /// reporting why it cannot.
  /// `owner` is the element the point belongs to, where a missing link is reported.
  bool value(const pugi::xml_node &owner, const pugi::xml_node &point, LocatedText &out, int depth) {
    if (depth > kMaxDepth) return fail(owner, "the network is deeper than gfec reads");
    if (out.text.size() > kMaxText)
      return fail(owner, fmt::format("the value of {} is more than gfec writes as one expression: outputs that "
                                     "feed several inputs, level after level, multiply its size",
                                     r_.describe(owner)));
    std::vector<pugi::xml_node> links;
    for (pugi::xml_node c : point.children())
      if (local_name(c) == "connection") links.push_back(c);
    if (links.empty()) return broken(owner, fmt::format("{} has an input connected to nothing", r_.describe(owner)));
    // Several wires into one point: LD's parallel branches, an OR of the power flows.
    if (links.size() > 1) piece(out, "(", point);
    for (std::size_t i = 0; i < links.size(); ++i) {
      if (i > 0) piece(out, " OR ", point);
      if (!source(links[i], out, depth + 1)) return false;
    }
    if (links.size() > 1) piece(out, ")", point);
    return true;
  }

  /// The body's statements: the assignments of its output variables and coils and the calls of
  /// its function-block instances, in execution order.
  bool statements(LocatedText &out) {
    std::vector<pugi::xml_node> order;
    bool numbered = false;
    for (const pugi::xml_node &n : elements_) {
      std::string_view k = local_name(n);
      if (k == "outVariable" || k == "inOutVariable" || k == "coil" ||
          (k == "block" && *n.attribute("instanceName").value()))
        order.push_back(n);
      numbered = numbered || std::strtol(n.attribute("executionOrderId").value(), nullptr, 10) > 0;
    }
    // Beremiz numbers the elements of an FBD body; LD rungs and unnumbered files run in the
    // file's order, which is the order they are drawn in.
    if (numbered)
      std::stable_sort(order.begin(), order.end(), [](const pugi::xml_node &a, const pugi::xml_node &b) {
        return std::strtol(a.attribute("executionOrderId").value(), nullptr, 10) <
               std::strtol(b.attribute("executionOrderId").value(), nullptr, 10);
      });
    bool ok = true;
    for (const pugi::xml_node &n : order) ok = statement(n, out) && ok;
    for (const pugi::xml_node &n : elements_) ok = known(n) && ok;
    return ok;
  }

private:
  bool statement(const pugi::xml_node &n, LocatedText &out) {
    std::string_view k = local_name(n);
    if (k == "block") return call(n, out);
    pugi::xml_node in = child(n, "connectionPointIn");
    if (!in || !child(in, "connection")) return true;  // an unconnected output writes nothing
    LocatedText target;
    if (k == "coil") {
      target = r_.xml_.text_below(child(n, "variable"));
      if (std::string_view edge = n.attribute("edge").value(); !edge.empty() && edge != "none")
        return fail(n,
                    fmt::format("{}: an edge coil ('{}') is not supported yet", r_.describe(n), text::printable(edge)));
    } else {
      target = r_.xml_.text_below(child(n, "expression"));
    }
    if (target.blank()) return broken(n, fmt::format("{} names no variable", r_.describe(n)));
    std::string_view storage = n.attribute("storage").value();
    if (k == "coil" && (storage == "set" || storage == "reset")) {
      // A set coil sets its variable while power flows and leaves it otherwise (reset: clears).
      piece(out, "IF ", n);
      if (!value(n, in, out, 0)) return false;
      piece(out, " THEN ", n);
      append(out, target);
      piece(out, storage == "set" ? " := TRUE; END_IF;\n" : " := FALSE; END_IF;\n", n);
      return true;
    }
    append(out, target);
    piece(out, " := ", n);
    const bool negated = attribute_true(n, "negated") || attribute_true(in, "negated");
    if (negated) piece(out, "NOT (", n);
    if (!value(n, in, out, 0)) return false;
    piece(out, negated ? ");\n" : ";\n", n);
    return true;
  }

  /// A function-block instance's call, its inputs as formal parameters.
  bool call(const pugi::xml_node &block, LocatedText &out) {
    piece(out, block.attribute("instanceName").value(), block);
    piece(out, "(", block);
    bool first = true;
    for (pugi::xml_node v : child(block, "inputVariables").children()) {
      if (local_name(v) != "variable") continue;
      pugi::xml_node in = child(v, "connectionPointIn");
      if (!in || !child(in, "connection")) continue;  // IEC: an input not given keeps its value
      if (iec::upper(v.attribute("formalParameter").value()) == "EN")
        return fail(v, fmt::format("{}: a connected EN input is not supported yet", r_.describe(block)));
      if (!first) piece(out, ", ", v);
      first = false;
      piece(out, v.attribute("formalParameter").value(), v);
      piece(out, " := ", v);
      const bool negated = attribute_true(v, "negated");
      if (negated) piece(out, "NOT (", v);
      if (!value(v, in, out, 0)) return false;
      if (negated) piece(out, ")", v);
    }
    piece(out, ");\n", block);
    return true;
  }

  /// The value at the other end of one `<connection>`.
  bool source(const pugi::xml_node &connection, LocatedText &out, int depth) {
    const std::string ref = connection.attribute("refLocalId").value();
    auto it = by_id_.find(ref);
    if (it == by_id_.end())
      return broken(connection,
                    fmt::format("a connection to localId {}, which the body does not have", text::printable(ref)));
    const pugi::xml_node n = it->second;
    if (!on_path_.insert(ref).second)
      return fail(n, fmt::format("{} feeds itself: a network loop without a function-block instance in it has "
                                 "no value",
                                 r_.describe(n)));
    bool ok = source_of(n, connection, out, depth);
    on_path_.erase(ref);
    return ok;
  }

  bool source_of(const pugi::xml_node &n, const pugi::xml_node &connection, LocatedText &out, int depth) {
    std::string_view k = local_name(n);
    if (k == "inVariable" || k == "inOutVariable") {
      LocatedText e = r_.xml_.text_below(child(n, "expression"));
      if (e.blank()) return broken(n, fmt::format("{} has no expression", r_.describe(n)));
      const bool negated = attribute_true(n, k == "inVariable" ? "negated" : "negatedOut");
      // Brackets only round what is more than a name or a literal: the chart text stays readable.
      const bool atom = is_atom(e.text);
      if (negated) piece(out, "NOT ", n);
      if (!atom) piece(out, "(", n);
      append(out, e);
      if (!atom) piece(out, ")", n);
      return true;
    }
    if (k == "leftPowerRail") {
      piece(out, "TRUE", n);
      return true;
    }
    if (k == "contact") {
      if (std::string_view edge = n.attribute("edge").value(); !edge.empty() && edge != "none")
        return fail(
            n, fmt::format("{}: an edge contact ('{}') is not supported yet", r_.describe(n), text::printable(edge)));
      LocatedText var = r_.xml_.text_below(child(n, "variable"));
      if (var.blank()) return broken(n, fmt::format("{} names no variable", r_.describe(n)));
      // A contact on the power rail is its variable; one further along, the power AND it.
      pugi::xml_node in = child(n, "connectionPointIn");
      const bool on_rail = on_left_rail(in);
      if (!on_rail) {
        piece(out, "(", n);
        if (!value(n, in, out, depth)) return false;
        piece(out, " AND ", n);
      }
      if (attribute_true(n, "negated")) piece(out, "NOT ", n);
      append(out, var);
      if (!on_rail) piece(out, ")", n);
      return true;
    }
    if (k == "coil") return value(n, child(n, "connectionPointIn"), out, depth);  // power passes through
    if (k == "continuation") {
      auto c = connectors_.find(iec::upper(n.attribute("name").value()));
      if (c == connectors_.end())
        return broken(n, fmt::format("{} continues no connector of that name", r_.describe(n)));
      return value(c->second, child(c->second, "connectionPointIn"), out, depth);
    }
    if (k == "block") return block_output(n, connection, out, depth);
    return fail(n, fmt::format("{} as the source of a value is not supported yet", r_.describe(n)));
  }

  /// A block's output: a function's value, or an instance's output variable.
  bool block_output(const pugi::xml_node &block, const pugi::xml_node &connection, LocatedText &out, int depth) {
    const std::string type = iec::upper(block.attribute("typeName").value());
    std::string pin = connection.attribute("formalParameter").value();
    if (*block.attribute("instanceName").value()) {
      if (pin.empty())
        return broken(connection, fmt::format("a connection from {} names no output", r_.describe(block)));
      piece(out, block.attribute("instanceName").value(), block);
      piece(out, ".", block);
      piece(out, pin, block);
      return true;
    }
    if (iec::upper(pin) == "ENO")
      return fail(connection, fmt::format("{}: ENO is not supported yet", r_.describe(block)));
    std::vector<pugi::xml_node> inputs;
    for (pugi::xml_node v : child(block, "inputVariables").children()) {
      if (local_name(v) != "variable") continue;
      if (iec::upper(v.attribute("formalParameter").value()) == "EN") {
        if (pugi::xml_node in = child(v, "connectionPointIn"); in && child(in, "connection"))
          return fail(v, fmt::format("{}: a connected EN input is not supported yet", r_.describe(block)));
        continue;
      }
      inputs.push_back(v);
    }
    // Every value is a name, a literal or bracketed, so an input needs no brackets of its own.
    auto input = [&](std::size_t i) {
      if (attribute_true(inputs[i], "negated")) piece(out, "NOT ", inputs[i]);
      return value(inputs[i], child(inputs[i], "connectionPointIn"), out, depth);
    };
    const Operator *op = operator_of(type);
    if (type == "NOT" || type == "MOVE") {
      if (inputs.size() != 1)
        return broken(block, fmt::format("{} has {} inputs, not one", r_.describe(block), inputs.size()));
      piece(out, type == "NOT" ? "(NOT " : "(", block);
      if (!input(0)) return false;
      piece(out, ")", block);
      return true;
    }
    if (op) {
      if (inputs.size() < 2 || (!op->extensible && inputs.size() != 2))
        return broken(block,
                      fmt::format("{} has {} input{}; {} takes {}", r_.describe(block), inputs.size(),
                                  inputs.size() == 1 ? "" : "s", op->name, op->extensible ? "two or more" : "two"));
      piece(out, "(", block);
      for (std::size_t i = 0; i + 1 < inputs.size(); ++i) {
        if (op->comparison) {
          // GT(a, b, c) is a > b AND b > c: each input but the ends is read twice, which is
          // the same as once, as a network's values have no side effects.
          if (i > 0) piece(out, " AND ", block);
          if (!input(i)) return false;
        } else if (i == 0) {
          if (!input(0)) return false;
        }
        piece(out, fmt::format(" {} ", op->st), block);
        if (!input(i + 1)) return false;
      }
      piece(out, ")", block);
      return true;
    }
    // Any other function is written as its ST call, inputs in their order: the ST reader says
    // which it reads.
    piece(out, block.attribute("typeName").value(), block);
    piece(out, "(", block);
    for (std::size_t i = 0; i < inputs.size(); ++i) {
      if (i > 0) piece(out, ", ", block);
      if (!input(i)) return false;
    }
    piece(out, ")", block);
    return true;
  }

  /// Whether `point`'s one connection comes straight from a left power rail.
  bool on_left_rail(const pugi::xml_node &point) const {
    pugi::xml_node c = child(point, "connection");
    if (!c || c.next_sibling("connection")) return false;
    auto it = by_id_.find(c.attribute("refLocalId").value());
    return it != by_id_.end() && local_name(it->second) == "leftPowerRail";
  }

  /// Whether gfec reads element `n` of a network body; reports it otherwise.
  bool known(const pugi::xml_node &n) {
    static const char *const kRead[] = {"inVariable", "outVariable",   "inOutVariable",  "block",     "contact",
                                        "coil",       "leftPowerRail", "rightPowerRail", "connector", "continuation",
                                        "comment",    "documentation", "addData"};
    std::string_view k = local_name(n);
    for (const char *x : kRead)
      if (k == x) return true;
    return fail(n, fmt::format("{} in an FBD or LD body is not supported yet", r_.describe(n)));
  }

  /// Appends generated text located at `at`'s start tag: every character of it, so that a token
  /// made of it points at the element and never past it.
  void piece(LocatedText &out, std::string_view text, const pugi::xml_node &at) {
    const std::uint32_t where = r_.at(at).begin;
    for (char c : text) {
      out.breaks.emplace_back(static_cast<std::uint32_t>(out.text.size()), where);
      out.text += c;
    }
  }

  /// Appends text of the file, keeping where each of its characters is.
  static void append(LocatedText &out, const LocatedText &t) {
    const auto base = static_cast<std::uint32_t>(out.text.size());
    for (const auto &b : t.breaks) out.breaks.emplace_back(base + b.first, b.second);
    out.text += t.text;
  }

  /// What gfec does not read (yet), at the element.
  bool fail(const pugi::xml_node &at, const std::string &message) {
    r_.not_supported(at, message);
    return false;
  }
  /// A network that is not one: a dangling or missing link.
  bool broken(const pugi::xml_node &at, const std::string &message) {
    r_.diag_.error(r_.at(at), ErrorKind::Plcopen, message);
    return false;
  }

  Reader &r_;
  std::map<std::string, pugi::xml_node> by_id_;
  std::map<std::string, pugi::xml_node> connectors_;
  std::vector<pugi::xml_node> elements_;
  std::set<std::string> on_path_;  ///< the elements whose value is being written: a loop check
};

std::optional<ast::Block> Reader::read_network(const pugi::xml_node &body) {
  Network net(*this, body);
  LocatedText text;
  if (!net.statements(text)) return std::nullopt;
  if (text.text.empty()) return ast::Block{};
  return statements(text);
}

ast::ExprPtr Reader::network_value(const pugi::xml_node &body, const pugi::xml_node &owner,
                                   const pugi::xml_node &point) {
  Network net(*this, body);
  LocatedText text;
  if (!net.value(owner, point, text, 0)) return nullptr;
  return expression(text);
}

}  // namespace gfec::plcopen
