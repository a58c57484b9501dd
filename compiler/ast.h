// The syntax tree: mirrors the text, one struct per construct, every node with its SourceRange.
// Nothing here is resolved or checked; the validator turns it into the model (model.h).
// A chart may have a million places: members are ordered and enums sized so that nodes stay
// small, and spellings point into the source text, which outlives the tree (docs/performance.md).
#pragma once

#include "ast_expr_list.h"
#include "compact_vector.h"
#include "heap_optional.h"
#include "heap_vector.h"
#include "operators.h"
#include "source.h"

#include <deque>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace gfec::ast {

/// A name as written. The text is a view into the source text or, for a name a reader made up
/// (ALICA plans), into File::strings; both outlive the tree, so no name owns a copy.
struct Name {
  std::string_view text;
  SourceRange range;
};

// ---------------------------------------------------------------- expressions

struct Expr;
using ExprPtr = std::unique_ptr<Expr>;

struct Expr {
  enum class Kind : std::uint8_t {
    Bool,      ///< `true` / `false`: bool_value
    Int,       ///< `42`: text() is the spelling
    Float,     ///< `0.5`, `1e-3`: text() is the spelling
    String,    ///< `"..."`: text() is the decoded value (File::strings)
    Duration,  ///< `10ms`, `1.5s`: milliseconds in duration_ms, text() is the spelling
    Name,      ///< a variable, constant or config entry: name
    Call,      ///< `f(a, b)` (also `elapsed(P)`): name + args
    Unary,     ///< unary_op + args[0]
    Binary,    ///< binary_op + args[0], args[1]
    Paren,     ///< `( e )`: args[0]; kept so formulas and generated code keep the user's brackets
    Path,      ///< `P.Q.R` (only as the argument of `active(...)`, docs/language.md "Sub-charts"):
               ///< args, one Expr of Kind::Name per name between the dots, outermost first
  };
  Kind kind;
  UnaryOp unary_op = UnaryOp::Not;
  BinaryOp binary_op = BinaryOp::Add;
  bool bool_value = false;
  SourceRange range;
  double duration_ms = 0;
  /// Name, Call: the name. Int, Float, Duration: the spelling (text()); String: the decoded value
  /// (text()). One field for both, as no expression has a name and a spelling: a chart may hold
  /// millions of expressions (docs/performance.md). The text points into the source text or into
  /// File::strings, both of which outlive the tree: no node owns a copy.
  /// Unary, Binary: name.range is where the operator is written (op_range()) and name.text is
  /// empty; an operator has no name, so its range costs the node no byte.
  Name name;
  ExprList args;

  /// A literal's spelling (Int, Float, Duration) or a String's decoded value.
  std::string_view text() const { return name.text; }
  /// Unary, Binary: where the operator is written, so that a message can quote what the user
  /// wrote (a language that spells `&&` as `AND`); empty for a node a reader made up.
  const SourceRange &op_range() const { return name.range; }
  void set_op_range(const SourceRange &r) { name.range = r; }
};

// ---------------------------------------------------------------- statements

struct Stmt {
  /// While, DoWhile, For, Break, Return: docs/language.md §10 "Loops".
  /// Invoke: `inst(a = e, b = f);`, a call of a block instance (docs/language.md "Blocks"):
  /// target is the instance, then_block holds one Assign per argument (its target the input).
  enum class Kind : std::uint8_t { Call, Assign, Verbatim, If, While, DoWhile, For, Break, Return, Invoke };
  Kind kind;
  AssignOp assign_op = AssignOp::Set;
  bool has_else = false;  ///< Kind::If: `else` was written
  bool else_if = false;   ///< Kind::If: else_block is exactly the `if` of an `else if`
  SourceRange range;
  ExprPtr call;   ///< Kind::Call: an Expr of Kind::Call
  ExprPtr value;  ///< Kind::Assign; Kind::If, While, DoWhile, For: the condition
  // What only one kind of statement has lives on the heap, a pointer wide when absent: a chart
  // may hold a million statements (docs/performance.md).
  HeapOptional<Name> target;           ///< Kind::Assign; Kind::Invoke: the instance
  HeapOptional<std::string> verbatim;  ///< Kind::Verbatim: the text between %{ and %}
  HeapVector<Stmt> then_block;         ///< Kind::If; While, DoWhile, For: the loop's body
  HeapVector<Stmt> else_block;         ///< Kind::If: empty without `else`; `else if` is one If in it;
                                       ///< Kind::For: the header's two assignments, first and third
};

using Block = std::vector<Stmt>;

// ---------------------------------------------------------------- declarations

/// A type written as an identifier: bool int float double void string object.
struct TypeName {
  std::string text;
  SourceRange range;
};

struct Param {
  TypeName type;
  std::optional<Name> name;  ///< C prototypes may leave parameters unnamed
  SourceRange range;
};

/// `bool Left_IR_Black();` inside an interface.
struct FunctionDecl {
  TypeName result;
  Name name;
  std::vector<Param> params;
  SourceRange range;
};

struct Interface {
  Name name;
  std::vector<FunctionDecl> functions;
  SourceRange range;
};

/// What a chart's `var` is to the chart's caller (docs/language.md §14): its own state, an input
/// the caller sets before a tick (`in`), an output the caller reads after one (`out`), or both: an
/// input the chart may assign, which the caller sets before a tick and reads after it (`inout`).
enum class VarRole : std::uint8_t { Local, In, Out, InOut };

/// `const float CRUISE = 0.6;` (file level or in a chart) and `var int laps = 0;`, `in bool Start;`,
/// `out int Count = 0;` (in a chart).
struct ValueDecl {
  bool is_const = false;
  VarRole role = VarRole::Local;  ///< not a const: var, in, out or inout
  TypeName type;
  Name name;
  ExprPtr init;  ///< may be null for `var`
  /// An IEC located variable's direct address (`%IX0.0`), kept for --emit=json and chart text's
  /// comment; empty in chart text, which has no located variables (docs/iec.md).
  std::string_view address;
  SourceRange range;
};

enum class StateKind : std::uint8_t { Normal, Success, Failure };

/// In a place: `N Fill;`, `L Pump 2s;` — the place holds a named action under a qualifier
/// (docs/language.md §14, docs/iec.md "Action control").
struct Association {
  Name qualifier;  ///< as written: one of N R S L D P P0 P1 SD DS SL
  Name action;
  std::optional<double> duration_ms;  ///< the duration, when one is written
  SourceRange duration_range;
  SourceRange range;
};

/// `action Fill { ... }` at chart level: a named action's body.
struct ActionDecl {
  Name name;
  std::vector<Stmt> body;
  SourceRange range;
};

/// What most places lack, kept in one heap block (Place::extras), so that a place without any
/// of it costs a pointer (docs/performance.md).
struct PlaceExtras {
  std::optional<Block> entry;
  std::optional<Block> exit;
  SourceRange entry_range, exit_range;
  ExprPtr post;                           ///< `post EXPR` of a terminal state
  std::optional<Name> runs;               ///< `place P runs C`: the chart C (sub-charts)
  std::vector<Association> associations;  ///< the named actions the place holds
};

/// A place of an sfc or a state of an fsm.
struct Place {
  bool initial = false;
  StateKind terminal = StateKind::Normal;  ///< fsm only
  bool is_state = false;                   ///< written with `state` rather than `place`
  bool has_body = false;
  SourceRange range;
  Name name;
  Block action;
  /// A chart may have a million places: members are ordered to pack, and what most places
  /// lack (entry, exit, post, runs) is one heap block, absent when the place has none of it.
  HeapOptional<PlaceExtras> extras;

  /// The extras, created on first write: for the parser and the readers that build a tree.
  PlaceExtras &extra() {
    if (!extras) extras.emplace();
    return *extras;
  }
  /// Null when the place has no such block, condition or `runs`.
  const Block *entry() const { return extras && extras->entry ? &*extras->entry : nullptr; }
  const Block *exit() const { return extras && extras->exit ? &*extras->exit : nullptr; }
  const Expr *post() const { return extras ? extras->post.get() : nullptr; }
  const Name *runs() const { return extras && extras->runs ? &*extras->runs : nullptr; }
};

/// A read-only run of names: a transition's inputs or outputs.
class NameSpan {
public:
  NameSpan(const Name *first, std::size_t count) : first_(first), count_(count) {}
  std::size_t size() const { return count_; }
  bool empty() const { return count_ == 0; }
  const Name *begin() const { return first_; }
  const Name *end() const { return first_ + count_; }
  const Name &operator[](std::size_t i) const { return first_[i]; }
  const Name &front() const { return *first_; }

private:
  const Name *first_;
  std::size_t count_;
};

struct Transition {
  bool named = false;  ///< `name: inputs -> outputs`; `name` is empty otherwise
  bool parenthesised_inputs = false;
  bool parenthesised_outputs = false;
  /// `A -> C else [when c];`: the chart says the transitions declared before it that share an
  /// input place come first, as declaration order has it anyway (docs/language.md §5.1).
  bool otherwise = false;
  std::uint32_t input_count = 0;  ///< places[0, input_count) are the inputs, the rest the outputs
  SourceRange range;
  Name name;  ///< `named` rather than an std::optional: members ordered to pack (see Place)
  /// The inputs, then the outputs: one heap block for both (a chart may have a million
  /// transitions, docs/performance.md). Set with set_places, read with inputs() and outputs().
  CompactVector<Name> places;
  ExprPtr condition;  ///< null: `when true`

  NameSpan inputs() const { return {places.data(), input_count}; }
  NameSpan outputs() const { return {places.data() + input_count, places.size() - input_count}; }
  void set_places(const std::vector<Name> &inputs, const std::vector<Name> &outputs) {
    input_count = static_cast<std::uint32_t>(inputs.size());
    CompactVector<Name> both;
    both.reserve(inputs.size() + outputs.size());
    for (const Name &n : inputs) both.push_back(n);
    for (const Name &n : outputs) both.push_back(n);
    places = std::move(both);
  }
  /// Frees the names once the validator has resolved them.
  void release_places() {
    places = CompactVector<Name>();
    input_count = 0;
  }
};

struct Period {
  double ms = 0;
  SourceRange range;
};

/// An `sfc` or an `fsm`: the two share one shape; the validator holds each to its own rules.
struct Chart {
  enum class Kind { Sfc, Fsm };
  Kind kind;
  Name name;
  std::vector<Period> periods;  ///< more than one is an error the validator reports
  /// `team N;` of an fsm (team machines): the value and range of every one written
  std::vector<std::pair<long long, SourceRange>> teams;
  std::vector<ValueDecl> values;
  std::vector<Place> places;
  std::vector<Transition> transitions;
  std::vector<ActionDecl> actions;  ///< named actions (docs/language.md §14)
  SourceRange range;
};

/// `block NAME { in T a; out T q; var T v; var B inst; statements }` at file level
/// (docs/language.md "Blocks"): a function block, whose body runs once per call of an instance.
struct BlockDecl {
  Name name;
  std::vector<ValueDecl> values;  ///< in, out and var (an instance is a var of a block type)
  Block body;
  bool standard = false;  ///< one of the standard blocks gfec predefines (TON, CTU, ...)
  SourceRange range;
};

// ---------------------------------------------------------------- toolbox and plan

enum class ParamDir { In, Out };

struct TemplateParam {
  ParamDir dir = ParamDir::In;
  TypeName type;
  Name name;
  SourceRange range;
};

/// `actor Forward(in float distance) -> FORWARD_OK;`, a computation, or a supervisor.
struct Template {
  enum class Kind { Actor, Computation, Supervisor };
  Kind kind;
  Name name;
  std::vector<TemplateParam> params;
  std::vector<Name> outcomes;    ///< result states, or a supervisor's events
  std::optional<Period> period;  ///< supervisors only
  SourceRange range;
};

struct Toolbox {
  Name name;
  std::vector<Template> templates;
  SourceRange range;
};

struct ConfigEntry {
  TypeName type;
  Name name;
  ExprPtr init;
  SourceRange range;
};

/// `STATE -> target;` — target is an actor name or the keyword `terminate` / `ignore`.
struct Rule {
  enum class Target { Actor, Terminate, Ignore };
  Name outcome;
  Target target = Target::Actor;
  Name target_name;  ///< the actor, or the keyword's own text and range
  SourceRange range;
};

/// `supervise touch: CheckTouch() { TOUCHED -> backupCollision; }`
struct Supervise {
  Name name;
  Name template_name;
  ExprList args;
  std::vector<Rule> rules;
  SourceRange range;
};

/// `actor followWall: WallForward(walldist, ...) { ...rules and supervisors... }`
struct ActorUse {
  Name name;
  Name template_name;  ///< a toolbox template, or another plan (a sub-plan)
  ExprList args;
  std::vector<Rule> rules;
  std::vector<Supervise> supervisors;
  bool written_as_computation = false;
  SourceRange range;
};

struct Plan {
  Name name;
  std::vector<std::vector<ConfigEntry>> config_blocks;  ///< every `config { }` block, in order
  std::vector<Supervise> global_supervisors;
  std::vector<Name> starts;  ///< every `start X;` (exactly one is required)
  std::vector<ActorUse> actors;
  SourceRange range;
};

// ---------------------------------------------------------------- files

struct Import {
  std::string path;  ///< decoded string
  SourceRange range;
};

struct Verbatim {
  std::string text;
  SourceRange range;
};

// ---------------------------------------------------------------- scenario tests

/// One step of a `test` block (docs/language.md "Scenario tests").
struct TestStep {
  enum class Kind { Tick, Set, Expect };
  Kind kind = Kind::Tick;
  SourceRange range;
  long long count = 1;  ///< Tick: `tick N;` (1 for `tick;`)
  Name function;        ///< Set: the sensing function
  ExprPtr value;        ///< Set: the constant; Expect: the expectation
  /// Written inside `agent K { ... }` (a team machine's agent K), or -1.
  long long agent = -1;
  SourceRange agent_range;  ///< the `agent K` that scopes the step
};

/// `test "NAME" of CHART { STEPS }`
struct Test {
  std::string name;
  SourceRange name_range;
  Name chart;
  /// `of CHART agents N`: how many agents of a team machine run (-1: not written).
  long long agents = -1;
  SourceRange agents_range;
  std::vector<TestStep> steps;
  SourceRange range;
};

struct File {
  FileId id = 0;
  /// The decoded values of string literals (Expr::text() views them; a deque never moves them).
  std::deque<std::string> strings;
  std::vector<Import> imports;
  std::vector<Verbatim> verbatims;
  std::vector<ValueDecl> consts;
  std::vector<Interface> interfaces;
  std::vector<Chart> charts;
  std::vector<BlockDecl> blocks;
  std::vector<Toolbox> toolboxes;
  std::vector<Plan> plans;
  std::vector<Test> tests;
};

/// Every file of a compilation: the main file first, then imports in the order first reached.
struct Program {
  std::vector<std::unique_ptr<File>> files;
};

}  // namespace gfec::ast
