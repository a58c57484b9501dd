// An SFC body as the IEC program model: steps, transitions between the steps they link, and the
// associations of action blocks; a program's, a function block's or an action's body alike. The
// graph is read from localId/refLocalId alone; positions say nothing (CODESYS and TwinCAT write
// every one as 0,0). docs/iec.md "PLCopen XML" has the rules.
#include "escape.h"
#include "iec/iec_text.h"
#include "plcopen/iec_duration.h"
#include "plcopen/reader_context.h"

#include <fmt/format.h>

#include <cctype>
#include <map>
#include <set>

namespace gfec::plcopen {

namespace {

enum class Kind {
  Step,
  Transition,
  SelectionDivergence,
  SelectionConvergence,
  SimultaneousDivergence,
  SimultaneousConvergence,
  JumpStep,
  MacroStep,
  ActionBlock,
  InVariable,  ///< FBD: an expression, read when a transition's condition comes from one
  Other,       ///< an LD or FBD element gfec does not read
};

struct Link {
  std::string ref;         ///< refLocalId
  pugi::xml_node element;  ///< the <connection>
};

struct Node {
  pugi::xml_node xml;
  Kind kind = Kind::Other;
  std::vector<Link> ins;          ///< its connectionPointIn connections, in file order
  std::vector<std::size_t> outs;  ///< the nodes with a connection to it, in file order
  std::size_t step = 0;           ///< Kind::Step: index in Pou::steps
  bool used = false;              ///< an InVariable read as a condition
  bool entry = false;             ///< Kind::Step in a macro step's body, marked initialStep
  std::size_t macro = SIZE_MAX;   ///< the macro step whose body holds it, or SIZE_MAX
  std::string prefix;             ///< what qualifies the localIds of its body ("" or "3/")
  /// Kind::MacroStep: the steps of its body the links into it activate (those marked initial),
  /// and those the links out of it wait for (the steps no transition of the body leaves).
  std::vector<std::size_t> entries, exits;
};

using iec::upper;

/// Graphs deeper than this (a divergence inside a divergence inside ...) are not SFCs a person
/// draws; the bound keeps a hostile file from exhausting the stack.
constexpr int kMaxDepth = 64;

class SfcGraph {
public:
  SfcGraph(const XmlFile &xml, Diagnostics &diag, const std::vector<iec::Step> &steps)
      : xml_(xml), diag_(diag), steps_(steps) {}

  std::vector<Node> nodes;
  std::map<std::string, std::size_t> by_id;
  std::map<std::string, std::size_t> step_by_name;  ///< upper-case name -> step index

  const Node *target(const Link &l) const {
    auto it = by_id.find(l.ref);
    return it == by_id.end() ? nullptr : &nodes[it->second];
  }

  std::string describe(const Node &n) const {
    std::string out = std::string(local_name(n.xml));
    if (n.kind == Kind::Step || n.kind == Kind::MacroStep) out += fmt::format(" '{}'", n.xml.attribute("name").value());
    if (n.kind == Kind::JumpStep) out += fmt::format(" to '{}'", n.xml.attribute("targetName").value());
    out += fmt::format(" (localId {})", n.xml.attribute("localId").value());
    return text::printable(out);
  }

  ast::Name step_name(std::size_t step) const { return steps_[step].name; }

  /// The steps a transition's input link leads back to.
  bool steps_before(const Node &n, const Link &via, const Node &transition, std::vector<ast::Name> &out, int depth) {
    if (depth > kMaxDepth) return fail(via, "the SFC nests divergences deeper than gfec reads");
    if (!seen_.insert(&n).second) return true;  // reached before: a diamond, or a cycle, walked once
    switch (n.kind) {
    case Kind::Step: out.push_back(step_name(n.step)); return true;
    case Kind::SelectionDivergence:
    case Kind::SimultaneousConvergence: {
      if (n.ins.empty()) return fail(at(n), fmt::format("{} has no input connection", describe(n)));
      bool ok = true;
      for (const Link &l : n.ins) {
        const Node *t = target(l);
        ok = t && steps_before(*t, l, transition, out, depth + 1) && ok;
      }
      return ok;
    }
    case Kind::MacroStep:  // leaving a macro step is leaving the exit steps of its body
      for (std::size_t e : n.exits) out.push_back(step_name(nodes[e].step));
      return !n.exits.empty();
    default:
      return fail(via, fmt::format("{} is preceded by {}: a transition follows a step, a selection divergence or a "
                                   "simultaneous convergence",
                                   describe(transition), describe(n)));
    }
  }

  /// The steps that a link out of a transition leads to.
  bool steps_after(const Node &n, const Node &transition, std::vector<ast::Name> &out, int depth) {
    if (depth > kMaxDepth) return fail(at(n), "the SFC nests divergences deeper than gfec reads");
    if (n.kind != Kind::JumpStep && !seen_.insert(&n).second) return true;
    switch (n.kind) {
    case Kind::Step: out.push_back(step_name(n.step)); return true;
    case Kind::JumpStep: {
      SourceRange r = xml_.attribute_range(n.xml, "targetName");
      auto it = step_by_name.end();
      if (n.macro != SIZE_MAX)  // in a macro step's body, its own steps first
        it = step_by_name.find(upper(
            fmt::format("{}_{}", nodes[n.macro].xml.attribute("name").value(), n.xml.attribute("targetName").value())));
      if (it == step_by_name.end()) it = step_by_name.find(upper(n.xml.attribute("targetName").value()));
      if (it == step_by_name.end())
        return fail(r, fmt::format("{} jumps to a step the SFC does not have", describe(n)));
      ast::Name name = step_name(it->second);
      name.range = r;
      out.push_back(name);
      return true;
    }
    case Kind::SelectionConvergence:
    case Kind::SimultaneousDivergence: {
      if (n.outs.empty()) return fail(at(n), fmt::format("{} leads nowhere: nothing connects to it", describe(n)));
      bool ok = true;
      for (std::size_t o : n.outs) ok = steps_after(nodes[o], transition, out, depth + 1) && ok;
      return ok;
    }
    case Kind::MacroStep:  // entering a macro step is entering the entry steps of its body
      for (std::size_t e : n.entries) out.push_back(step_name(nodes[e].step));
      return !n.entries.empty();
    case Kind::ActionBlock:  // an action block hangs off a step, reported where it is read
      return true;
    default:
      return fail(at(n), fmt::format("{} follows {}: a transition leads to a step, a jump, a selection convergence or "
                                     "a simultaneous divergence",
                                     describe(n), describe(transition)));
    }
  }

  /// Starts a walk from one transition: each element is visited once per walk, so links that
  /// meet again (or loop) cost nothing more.
  void new_walk() { seen_.clear(); }

  SourceRange at(const Node &n) const { return xml_.range(n.xml); }
  SourceRange at(const Link &l) const { return xml_.attribute_range(l.element, "refLocalId"); }
  bool fail(const Link &l, const std::string &message) { return fail(at(l), message); }
  bool fail(const SourceRange &r, const std::string &message) {
    diag_.error(r, ErrorKind::Plcopen, message);
    return false;
  }

private:
  const XmlFile &xml_;
  Diagnostics &diag_;
  const std::vector<iec::Step> &steps_;  ///< the SFC's steps, which Node::step indexes
  std::set<const Node *> seen_;
};

Kind kind_of(std::string_view name) {
  static const std::map<std::string_view, Kind> kKinds = {
      {"step", Kind::Step},
      {"transition", Kind::Transition},
      {"selectionDivergence", Kind::SelectionDivergence},
      {"selectionConvergence", Kind::SelectionConvergence},
      {"simultaneousDivergence", Kind::SimultaneousDivergence},
      {"simultaneousConvergence", Kind::SimultaneousConvergence},
      {"jumpStep", Kind::JumpStep},
      {"macroStep", Kind::MacroStep},
      {"actionBlock", Kind::ActionBlock},
      {"inVariable", Kind::InVariable},
  };
  auto it = kKinds.find(name);
  return it == kKinds.end() ? Kind::Other : it->second;
}

/// Whether `q` is one of IEC 61131-3's action qualifiers (any case, as IEC reads keywords).
bool qualifier(std::string_view q) {
  static const char *const kQualifiers[] = {"N", "R", "S", "L", "D", "P", "P0", "P1", "SD", "DS", "SL"};
  std::string u = upper(q);
  for (const char *k : kQualifiers)
    if (u == k) return true;
  return false;
}

bool is_true(std::string_view v) { return v == "true" || v == "1"; }

/// `NOT (e)`: a condition the file marks `negated="true"`; the operator's range is the attribute,
/// so a message about it points at what the user wrote.
ast::ExprPtr negated(ast::ExprPtr e, const SourceRange &attribute) {
  if (!e) return e;
  auto wrap = [](ast::Expr::Kind kind, const SourceRange &at) {
    auto x = std::make_unique<ast::Expr>();
    x->kind = kind;
    x->range = at;
    return x;
  };
  const SourceRange at = e->range;
  if (e->kind == ast::Expr::Kind::Binary || e->kind == ast::Expr::Kind::Unary) {
    auto p = wrap(ast::Expr::Kind::Paren, at);
    p->args.push_back(std::move(e));
    e = std::move(p);
  }
  auto n = wrap(ast::Expr::Kind::Unary, at);
  n->unary_op = UnaryOp::Not;
  n->set_op_range(attribute);
  n->args.push_back(std::move(e));
  return n;
}

/// Elements of a graphical body that carry no meaning for the program.
bool meaningless(std::string_view name) {
  return name == "comment" || name == "addData" || name == "documentation" || name == "error";
}

/// `T1 := cond;`, `:= cond;` or `cond`: the condition of a named transition's ST body, as a
/// located text of its own.
LocatedText condition_of_body(const LocatedText &body, std::string_view transition_name) {
  const std::string &t = body.text;
  std::size_t b = t.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return body;
  auto after_assign = [&](std::size_t at) -> std::size_t {
    at = t.find_first_not_of(" \t\r\n", at);
    return at != std::string::npos && t.compare(at, 2, ":=") == 0 ? at + 2 : std::string::npos;
  };
  std::size_t start = b;
  if (upper(t.substr(b, transition_name.size())) == upper(transition_name) && !transition_name.empty()) {
    std::size_t e = b + transition_name.size();
    bool word_end = e >= t.size() || !(std::isalnum(static_cast<unsigned char>(t[e])) || t[e] == '_');
    if (std::size_t a = word_end ? after_assign(e) : std::string::npos; a != std::string::npos) start = a;
  } else if (t.compare(b, 2, ":=") == 0) {
    start = b + 2;
  }
  std::size_t end = t.find_last_not_of(" \t\r\n");
  end = end != std::string::npos && end >= start && t[end] == ';' ? end : t.size();  // the ';' ends it
  LocatedText out;
  out.text = t.substr(start, end - start);
  out.breaks.emplace_back(0, body.file_offset(static_cast<std::uint32_t>(start)));
  for (const auto &br : body.breaks)
    if (br.first > start && br.first < end) out.breaks.emplace_back(br.first - start, br.second);
  return out;
}

/// The `<connection>`s below `e`, a few levels down (a block's are in inputVariables/variable/
/// connectionPointIn).
void connections_below(const pugi::xml_node &e, std::vector<pugi::xml_node> &out, int depth = 0) {
  if (depth > 4) return;
  for (pugi::xml_node c : e.children()) {
    if (c.type() != pugi::node_element) continue;
    if (local_name(c) == "connection") out.push_back(c);
    else connections_below(c, out, depth + 1);
  }
}

/// Marks `from` and every FBD/LD element upstream of it as read: a transition's condition is
/// their network, so they are not reported again as elements gfec does not read.
void mark_network(SfcGraph &g, const Node &from) {
  std::vector<const Node *> todo{&from};
  while (!todo.empty()) {
    Node &n = const_cast<Node &>(*todo.back());
    todo.pop_back();
    if (n.used || (n.kind != Kind::Other && n.kind != Kind::InVariable)) continue;
    n.used = true;
    std::vector<pugi::xml_node> links;
    connections_below(n.xml, links);
    for (const pugi::xml_node &c : links)
      if (const Node *up = g.target({n.prefix + c.attribute("refLocalId").value(), c})) todo.push_back(up);
  }
}

}  // namespace

void Reader::read_sfc(const pugi::xml_node &sfc, const pugi::xml_node &pou_node, SfcInto into) {
  SfcGraph g(xml_, diag_, into.steps);
  // ---- the elements, by localId. A macro step's body is read into the same graph, its
  // localIds qualified by the macro step's ("7/3") and its steps named after it ("Fill_Open"):
  // the macro step is expanded inline (docs/iec.md "PLCopen XML").
  auto elements = [&](auto &self, const pugi::xml_node &body, const std::string &prefix, std::size_t macro,
                      int depth) -> void {
    for (pugi::xml_node e : body.children()) {
      if (e.type() != pugi::node_element || meaningless(local_name(e))) continue;
      Node n;
      n.xml = e;
      n.kind = kind_of(local_name(e));
      n.macro = macro;
      n.prefix = prefix;
      std::string id = e.attribute("localId").value();
      if (id.empty()) {
        diag_.error(at(e), ErrorKind::Plcopen,
                    fmt::format("{} has no localId: SFC elements are linked by it", describe(e)));
        continue;
      }
      for (pugi::xml_node in : e.children()) {
        if (local_name(in) != "connectionPointIn") continue;
        for (pugi::xml_node c : in.children())
          if (local_name(c) == "connection") n.ins.push_back({prefix + c.attribute("refLocalId").value(), c});
      }
      if (n.kind == Kind::Step) {
        iec::Step step;
        step.name = name_of(e, "name");
        const bool initial = is_true(e.attribute("initialStep").value());
        step.range = at(e);
        if (!identifier(step.name, "step")) continue;
        if (macro != SIZE_MAX) {
          // Marked initial in a macro step's body: where the body starts, not an initial step.
          n.entry = initial;
          step.name.text = keep(fmt::format("{}_{}", g.nodes[macro].xml.attribute("name").value(), step.name.text));
        } else {
          step.initial = initial;
        }
        n.step = into.steps.size();
        auto [it, fresh] = g.step_by_name.emplace(upper(step.name.text), n.step);
        (void)it;
        (void)fresh;  // a duplicate name is the validator's to report, at both places
        into.steps.push_back(std::move(step));
      }
      auto [it, fresh] = g.by_id.emplace(prefix + id, g.nodes.size());
      if (!fresh) {
        diag_
            .error(xml_.attribute_range(e, "localId"), ErrorKind::Plcopen,
                   fmt::format("{}: another element of the body has localId {}", describe(e), text::printable(id)))
            .note(at(g.nodes[it->second].xml), "the other one");
        continue;
      }
      const std::size_t index = g.nodes.size();
      g.nodes.push_back(std::move(n));
      if (g.nodes[index].kind != Kind::MacroStep) continue;
      pugi::xml_node inner = child(child(e, "body"), "SFC");
      if (!inner) {
        diag_.error(at(e), ErrorKind::Plcopen,
                    fmt::format("{} has no <body> with an <SFC>: gfec expands a macro step's SFC inline", describe(e)));
      } else if (depth >= kMaxDepth) {
        diag_.error(at(e), ErrorKind::Plcopen, "macro steps nest deeper than gfec reads");
      } else {
        self(self, inner, prefix + id + "/", index, depth + 1);
      }
    }
  };
  elements(elements, sfc, "", SIZE_MAX, 0);
  // ---- links, both ways
  for (std::size_t i = 0; i < g.nodes.size(); ++i) {
    for (const Link &l : g.nodes[i].ins) {
      auto it = g.by_id.find(l.ref);
      if (it == g.by_id.end()) {
        diag_.error(g.at(l), ErrorKind::Plcopen,
                    fmt::format("{} is connected to localId '{}', which no element of the SFC body has",
                                g.describe(g.nodes[i]), text::printable(l.ref)));
        continue;
      }
      g.nodes[it->second].outs.push_back(i);
    }
  }
  auto direct_kind_count = [&](const std::vector<std::size_t> &ids, Kind k) {
    std::size_t c = 0;
    for (std::size_t o : ids) c += g.nodes[o].kind == k;
    return c;
  };
  // ---- each macro step's entry and exit steps
  for (std::size_t i = 0; i < g.nodes.size(); ++i) {
    const Node &n = g.nodes[i];
    if (n.kind != Kind::Step || n.macro == SIZE_MAX) continue;
    Node &m = g.nodes[n.macro];
    if (n.entry) m.entries.push_back(i);
    if (n.outs.size() == direct_kind_count(n.outs, Kind::ActionBlock)) m.exits.push_back(i);
  }
  for (const Node &m : g.nodes) {
    if (m.kind != Kind::MacroStep || !child(child(m.xml, "body"), "SFC")) continue;
    if (m.entries.empty())
      diag_.error(
          at(m.xml), ErrorKind::Plcopen,
          fmt::format("{}: no step of its body is marked initialStep=\"true\", the step it starts at", g.describe(m)));
    if (m.exits.empty())
      diag_.error(
          at(m.xml), ErrorKind::Plcopen,
          fmt::format("{}: every step of its body is followed by a transition, so none ends it", g.describe(m)));
  }
  // ---- transitions, in file order (the order of a divergence's branches: docs/iec.md)
  for (Node &n : g.nodes) {
    if (n.kind != Kind::Transition) continue;
    iec::Transition t;
    t.range = at(n.xml);
    bool ok = true;
    if (n.ins.empty()) ok = g.fail(at(n.xml), fmt::format("{} has no preceding step", g.describe(n)));
    g.new_walk();
    for (const Link &l : n.ins)
      if (const Node *before = g.target(l)) ok = g.steps_before(*before, l, n, t.from, 0) && ok;
      else ok = false;
    if (n.outs.empty())
      ok = g.fail(at(n.xml), fmt::format("{} leads to no step: nothing connects to it", g.describe(n)));
    g.new_walk();
    for (std::size_t o : n.outs) ok = g.steps_after(g.nodes[o], n, t.to, 0) && ok;
    std::size_t direct_steps = 0;
    for (const Link &l : n.ins)
      if (const Node *before = g.target(l); before && before->kind == Kind::Step) ++direct_steps;
    if (ok && direct_steps > 1)
      diag_.warning(Warning::PlcopenInferred, at(n.xml),
                    fmt::format("{} follows {} steps without a simultaneous convergence: read as one, the transition "
                                "waits for all of them",
                                g.describe(n), direct_steps));
    if (ok && n.outs.size() > 1 && direct_kind_count(n.outs, Kind::ActionBlock) == 0)
      diag_.warning(Warning::PlcopenInferred, at(n.xml),
                    fmt::format("{} leads to {} elements without a simultaneous divergence: read as one, the "
                                "transition activates all of them",
                                g.describe(n), n.outs.size()));
    if (auto p = n.xml.attribute("priority")) {
      char *end = nullptr;
      long long v = std::strtoll(p.value(), &end, 10);
      t.priority_range = xml_.attribute_range(n.xml, "priority");
      if (end && *end == '\0' && end != p.value()) t.priority = v;
      else
        ok = g.fail(t.priority_range, fmt::format("{} has the priority '{}', which is no integer", g.describe(n),
                                                  text::printable(p.value())));
    }
    // ---- the condition: never left out, never taken as true
    pugi::xml_node cond = child(n.xml, "condition");
    if (!cond) {
      diag_.error(at(n.xml), ErrorKind::Plcopen, fmt::format("{} has no condition", g.describe(n)));
      continue;
    }
    if (pugi::xml_node in = child(cond, "inline")) {
      if (pugi::xml_node st = child(in, "ST")) {
        t.condition = expression(xml_.text_below(st));
      } else {
        pugi::xml_node what = in;
        for (pugi::xml_node c : in.children())
          if (c.type() == pugi::node_element) {
            what = c;
            break;
          }
        not_supported(what, fmt::format("the condition of {} is written in {}: gfec reads conditions in ST; {} is "
                                        "not supported yet",
                                        g.describe(n), local_name(what), local_name(what)));
      }
    } else if (pugi::xml_node ref = child(cond, "reference")) {
      ast::Name name = name_of(ref, "name");
      pugi::xml_node body_of;
      for (pugi::xml_node ts : pou_node.children())
        if (local_name(ts) == "transitions")
          for (pugi::xml_node nt : ts.children())
            if (local_name(nt) == "transition" && upper(nt.attribute("name").value()) == upper(name.text)) body_of = nt;
      if (!body_of) {
        diag_.error(name.range, ErrorKind::Plcopen,
                    fmt::format("the condition of {} is the transition '{}', which the POU's <transitions> do not "
                                "declare",
                                g.describe(n), text::printable(name.text)));
      } else if (pugi::xml_node st = child(child(body_of, "body"), "ST")) {
        t.condition = expression(condition_of_body(xml_.text_below(st), name.text));
      } else if (pugi::xml_node net = child(child(body_of, "body"), "FBD") ? child(child(body_of, "body"), "FBD")
                                                                           : child(child(body_of, "body"), "LD")) {
        // An FBD or LD network whose one output is the transition's name (Beremiz draws `STOP`
        // := NOT SWITCH_BUTTON so): what it assigns is the condition (network_body.cc).
        if (std::optional<ast::Block> block = read_network(net)) {
          ast::Stmt *assign = nullptr;
          for (ast::Stmt &st : *block)
            if (st.kind == ast::Stmt::Kind::Assign && st.target && upper(st.target->text) == upper(name.text))
              assign = assign ? nullptr : &st;
          if (assign && block->size() == 1) {
            t.condition = std::move(assign->value);
          } else {
            diag_
                .error(at(net), ErrorKind::NotSupported,
                       fmt::format("the {} body of transition '{}' does more than give the transition's value (one "
                                   "output variable '{}'): not supported yet",
                                   local_name(net), text::printable(name.text), text::printable(name.text)))
                .note(name.range, fmt::format("the condition of {}", g.describe(n)));
          }
        }
      } else {
        pugi::xml_node what = child(body_of, "body");
        for (pugi::xml_node c : what.children())
          if (c.type() == pugi::node_element && !meaningless(local_name(c))) {
            what = c;
            break;
          }
        if (!what) what = body_of;
        diag_
            .error(at(what), ErrorKind::NotSupported,
                   fmt::format("the body of transition '{}' is written in {}: gfec reads transition bodies in ST, "
                               "FBD and LD; {} is not supported yet",
                               text::printable(name.text), local_name(what), local_name(what)))
            .note(name.range, fmt::format("the condition of {}", g.describe(n)));
      }
    } else if (pugi::xml_node cin = child(cond, "connectionPointIn")) {
      pugi::xml_node c = child(cin, "connection");
      const Node *from = c ? g.target({n.prefix + c.attribute("refLocalId").value(), c}) : nullptr;
      if (from) {
        // An FBD or LD network drawn in the SFC body (a macro step's, for a transition in one):
        // its value, as ST (network_body.cc).
        mark_network(g, *from);
        t.condition = network_value(n.xml.parent(), n.xml, cin);
      } else {
        diag_.error(c ? g.at(Link{"", c}) : at(cin), ErrorKind::Plcopen,
                    fmt::format("the condition of {} is connected to no element of the SFC body", g.describe(n)));
      }
    } else {
      diag_.error(at(cond), ErrorKind::Plcopen,
                  fmt::format("the condition of {} is neither inline, a reference nor a connection", g.describe(n)));
    }
    // `<condition negated="true">`: the transition clears when the condition does not hold.
    if (is_true(cond.attribute("negated").value()))
      t.condition = negated(std::move(t.condition), xml_.attribute_range(cond, "negated"));
    if (ok && t.condition) into.transitions.push_back(std::move(t));
  }
  // ---- steps: inferred convergences and divergences
  for (const Node &n : g.nodes) {
    if (n.kind != Kind::Step) continue;
    std::size_t from_transitions = 0;
    for (const Link &l : n.ins)
      if (const Node *before = g.target(l); before && before->kind == Kind::Transition) ++from_transitions;
    if (from_transitions > 1)
      diag_.warning(Warning::PlcopenInferred, at(n.xml),
                    fmt::format("{} follows {} transitions without a selection convergence: read as one, any of them "
                                "activates the step",
                                g.describe(n), from_transitions));
    if (std::size_t to = direct_kind_count(n.outs, Kind::Transition); to > 1)
      diag_.warning(Warning::PlcopenInferred, at(n.xml),
                    fmt::format("{} leads to {} transitions without a selection divergence: read as one, the first "
                                "in the file whose condition holds takes the step",
                                g.describe(n), to));
  }
  // ---- action blocks, then what gfec does not read
  for (Node &n : g.nodes) {
    if (n.kind == Kind::ActionBlock) {
      const Node *owner = n.ins.size() == 1 ? g.target(n.ins[0]) : nullptr;
      if (!owner || owner->kind != Kind::Step) {
        diag_.error(at(n.xml), ErrorKind::Plcopen, fmt::format("{} is not connected to one step", g.describe(n)));
        continue;
      }
      iec::Step &step = into.steps[owner->step];
      for (pugi::xml_node a : n.xml.children()) {
        if (local_name(a) != "action") continue;
        ast::Association as;
        as.range = at(a);
        as.qualifier = a.attribute("qualifier") ? name_of(a, "qualifier") : ast::Name{"N", at(a)};
        if (!qualifier(as.qualifier.text)) {
          diag_.error(as.qualifier.range, ErrorKind::Plcopen,
                      fmt::format("'{}' is not an action qualifier: IEC 61131-3's are N, R, S, L, D, P, P0, P1, SD, "
                                  "DS and SL",
                                  text::printable(as.qualifier.text)));
          continue;
        }
        if (a.attribute("duration") && *a.attribute("duration").value()) {
          as.duration_range = xml_.attribute_range(a, "duration");
          as.duration_ms = duration_ms(a.attribute("duration").value());
          if (!as.duration_ms) {
            diag_.error(as.duration_range, ErrorKind::Plcopen,
                        fmt::format("the duration '{}' is no TIME literal (T#2s)",
                                    text::printable(a.attribute("duration").value())));
            continue;
          }
        }
        if (pugi::xml_node ref = child(a, "reference")) {
          as.action = name_of(ref, "name");
        } else if (pugi::xml_node in = child(a, "inline")) {
          pugi::xml_node st = child(in, "ST");
          if (!st) {
            not_supported(in, fmt::format("an inline action of step '{}' not written in ST is not supported yet",
                                          step.name.text));
            continue;
          }
          auto block = statements(xml_.text_below(st));
          if (!block) continue;
          iec::Action action;
          action.name = {keep(fmt::format("{}_inline{}", step.name.text, ++inline_actions_)), at(in)};
          action.range = at(in);
          action.body = std::move(*block);
          as.action = action.name;
          into.actions.push_back(std::move(action));
        } else {
          diag_.error(at(a), ErrorKind::Plcopen,
                      fmt::format("an action of step '{}' names no action and has no inline body", step.name.text));
          continue;
        }
        step.associations.push_back(std::move(as));
      }
    } else if ((n.kind == Kind::Other || n.kind == Kind::InVariable) && !n.used) {
      not_supported(n.xml, fmt::format("{} in an SFC body: LD and FBD elements are not supported yet", g.describe(n)));
    }
  }
}

}  // namespace gfec::plcopen
