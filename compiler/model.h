// The model: the checked, resolved form of a program. Back ends and the interpreter read only
// this. Everything refers by typed id into the tables here (compiler/id.h: a PlaceId indexes
// Chart::places and nothing else, and "none" is an id's own state); every element keeps its SourceRange
// (for #line and for tools), and `sources` resolves ranges to file names and lines.
// A chart may have a million places: members are ordered and enums sized so that the elements
// stay small (docs/performance.md, "(a) The compiler").
#pragma once

#include "compact_string.h"
#include "compact_vector.h"
#include "heap_optional.h"
#include "heap_vector.h"
#include "id.h"
#include "id_groups.h"
#include "operators.h"
#include "small_list.h"
#include "source.h"

#include <cassert>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace gfec::model {

// The kinds of id, one per table.
using FunctionId = Id<struct FunctionTag>;      ///< Model::functions
using ConstId = Id<struct ConstTag>;            ///< Model::consts
using ChartId = Id<struct ChartTag>;            ///< Model::charts
using PlaceId = Id<struct PlaceTag>;            ///< Chart::places (of the chart that holds the reference)
using TransitionId = Id<struct TransitionTag>;  ///< Chart::transitions
using VarId = Id<struct VarTag>;                ///< Chart::vars
using ActionId = Id<struct ActionTag>;          ///< Chart::actions
using TemplateId = Id<struct TemplateTag>;      ///< Model::templates
using ToolboxId = Id<struct ToolboxTag>;        ///< Model::toolboxes
using PlanId = Id<struct PlanTag>;              ///< Model::plans
using ActorId = Id<struct ActorTag>;            ///< Plan::actors
using ConfigId = Id<struct ConfigTag>;          ///< Plan::config
using BlockId = Id<struct BlockTag>;            ///< Model::blocks

/// `Duration` is a duration literal or `elapsed(P)` where whole ticks are meant (§5.3); `Time`
/// is the language's `time`: a signed 64-bit count of milliseconds (docs/language.md §4). The
/// sized integers (docs/targets.md "Sized integers") are appended: a value's type never changes
/// its number.
enum class Type : std::uint8_t {
  Void,
  Bool,
  Int,
  Float,
  Double,
  String,
  Object,
  Duration,
  Time,
  Int8,
  Int16,
  Int64,
  UInt8,
  UInt16,
  UInt32,
  UInt64,
};

/// The type as the language (and C, for the numeric ones) spells it: "bool", "float", ...
const char *type_name(Type t);
/// An integer type: `int` or a sized one.
inline bool is_integer(Type t) { return t == Type::Int || (t >= Type::Int8 && t <= Type::UInt64); }
inline bool is_numeric(Type t) { return is_integer(t) || t == Type::Float || t == Type::Double; }
/// A sized integer type (not `int`).
inline bool is_sized(Type t) { return t >= Type::Int8 && t <= Type::UInt64; }
inline bool is_unsigned(Type t) { return t >= Type::UInt8 && t <= Type::UInt64; }
/// The bits of an integer type (Time: 64).
int integer_bits(Type t);
/// The C type of a value of `t` in an engine: "int32_t", "int64_t", "uint8_t", ...; null for
/// types that are not integers or time.
const char *c_integer_type(Type t);

// ---------------------------------------------------------------- expressions and statements

struct Expr {
  enum class Kind : std::uint8_t {
    Bool,    ///< bool_value
    Int,     ///< text: the spelling, e.g. "42"; int_value: its value
    Float,   ///< text: the spelling, e.g. "0.5", "1e-3"; float_value: its value as a double
    String,  ///< text: the decoded value
    Ticks,  ///< a duration in an sfc/fsm, converted to whole ticks (rounded up): ticks; float_value keeps the milliseconds
    Var,      ///< var()
    Const,    ///< constant()
    Config,   ///< config()
    Call,     ///< function(); args
    Elapsed,  ///< `elapsed(P)`: place() is P; type Duration, counted in ticks
    Unary,    ///< unary_op, args[0]
    Binary,   ///< binary_op, args[0], args[1]
    Paren,    ///< args[0], brackets the user wrote
    // Sub-charts (docs/language.md "Sub-charts"): place() is a place/state of the chart the
    // expression belongs to (always read at the moment of evaluation, see the docs).
    Active,     ///< `active(P)` / `active(P.Q.R)`: path = places, path[0] in this chart,
                ///< path[k+1] in the chart that path[k] runs. Type Bool.
    Succeeded,  ///< `succeeded(P)`: place() = P (which runs an fsm). Type Bool.
    Failed,     ///< `failed(P)`: place() = P (which runs an fsm). Type Bool.
    // Team machines (docs/language.md "Teams").
    TeamCount,  ///< `team(S)`: place() = state S of this chart. Type Int.
    Agent,      ///< `agent()`. Type Int.
    // Named actions (docs/language.md §14): action() is the action, of this chart. Type Bool,
    // the value of the latest action control (docs/iec.md "Action flags").
    ActionQ,  ///< `active(A)`: the action's Q (IEC's `A.Q`)
    ActionA,  ///< `running(A)`: the action's body runs (IEC's `A.A`: Q, its final run, an edge)
    Now,      ///< `now()`: the time of this tick, its number times the period (docs/language.md §15). Type Time.
    /// A conversion `T(x)` (docs/language.md §4), args[0] = x, type T: between integer types
    /// and to and from `time` exact (a value that does not fit is an error), a floating value to
    /// an integer rounded to nearest, ties away from zero (IEC's REAL_TO_INT).
    Convert,
    /// A standard function (docs/language.md §4, "Standard functions"): builtin says which,
    /// args its operands in order; type the common type of the values it chooses among.
    Builtin,
  };
  /// The standard functions of Kind::Builtin, IEC 61131-3's ABS, MIN, MAX, LIMIT, SEL and MUX.
  enum class Builtin : std::uint8_t { Abs, Min, Max, Limit, Sel, Mux };
  Kind kind = Kind::Bool;
  Type type = Type::Bool;
  UnaryOp unary_op = UnaryOp::Not;
  BinaryOp binary_op = BinaryOp::Add;
  Builtin builtin = Builtin::Abs;  ///< Kind::Builtin
  bool bool_value = false;
  // Values computed once by the validator with the one evaluator (compiler/constant.h), so that
  // no later stage parses a spelling or folds again. A literal (Int, Float) always has its value
  // here; any other expression whose value is known at compile time has `folded` set and its
  // value in bool_value (Bool), int_value (Int) or float_value (Float, Double).
  bool folded = false;
  SourceRange range;

private:
  // Here, not below: it fills the padding after `range` (a model::Expr stays 80 bytes).
  std::uint32_t ref_ = UINT32_MAX;

public:
  union {
    /// Int (of any integer type, or Time: milliseconds), and folded integer or time values: the
    /// value; an unsigned 64-bit value is kept as its bit pattern.
    std::int64_t int_value = 0;
    unsigned long ticks;  ///< Kind::Ticks of type Duration only
  };
  /// The value as a double; converted to `type` it is the expression's value. Kind::Ticks: the
  /// duration as written, in milliseconds (no Ticks expression has a float value of its own).
  double float_value = 0;
  // Sixteen bytes each where std::string and std::vector take 32 and 24: expressions are most
  // of a large chart's model (docs/performance.md).
  CompactString text;
  CompactVector<Expr> args;
  HeapVector<PlaceId> path;  ///< Kind::Active (on the heap: only `active(P.Q)` has one)

  // What the expression names; which table that is, its kind says (the accessor of another
  // kind is a mistake, and asserts).
  VarId var() const { return ref<VarId>(kind == Kind::Var); }
  ConstId constant() const { return ref<ConstId>(kind == Kind::Const); }
  ConfigId config() const { return ref<ConfigId>(kind == Kind::Config); }
  FunctionId function() const { return ref<FunctionId>(kind == Kind::Call); }
  /// Elapsed, Succeeded, Failed, TeamCount: the place or state named.
  PlaceId place() const {
    return ref<PlaceId>(kind == Kind::Elapsed || kind == Kind::Succeeded || kind == Kind::Failed ||
                        kind == Kind::TeamCount);
  }
  ActionId action() const { return ref<ActionId>(kind == Kind::ActionQ || kind == Kind::ActionA); }
  /// Makes the expression name `id`, of the table its kind reads.
  template <typename Tag> void refer_to(Id<Tag> id) {
    ref_ = id.valid() ? static_cast<std::uint32_t>(id.index()) : kNoRef;
  }

private:
  static constexpr std::uint32_t kNoRef = UINT32_MAX;
  template <typename IdT> IdT ref(bool right_kind) const {
    assert(right_kind);
    (void)right_kind;
    return ref_ == kNoRef ? IdT() : IdT(ref_);
  }
};

/// A standard function's name as chart text spells it: "abs", "min", ...
inline const char *builtin_name(Expr::Builtin f) {
  static const char *const kNames[] = {"abs", "min", "max", "limit", "sel", "mux"};
  return kNames[static_cast<int>(f)];
}

struct Stmt {
  /// While, DoWhile, For, Break, Return: docs/language.md §10 "Loops".
  /// Invoke: a call of a block instance (docs/language.md "Blocks"), already inlined: var is
  /// the instance's first member (Instance::first), then_block its first code_begin statements
  /// the arguments (Assigns of inputs, as written) and then the block's body for this instance.
  enum class Kind : std::uint8_t { Call, Assign, Verbatim, If, While, DoWhile, For, Break, Return, Invoke };
  Kind kind = Kind::Call;
  AssignOp op = AssignOp::Set;
  bool else_if = false;  ///< Kind::If: else_block is one If written as `else if`
  SourceRange range;
  VarId var;                     ///< Kind::Assign; Kind::Invoke: the instance's first member
  std::uint32_t code_begin = 0;  ///< Kind::Verbatim: where `verbatim` starts in range.file (after `%{`); 0: unknown
                                 ///< Kind::Invoke: how many arguments then_block begins with
  /// Kind::Call: the call (an Expr of Kind::Call; its result, if any, is discarded);
  /// Kind::Assign: the value; Kind::If, While, DoWhile, For: the condition (Bool). One expression per statement:
  /// a chart may hold a million statements (docs/performance.md).
  Expr expr;
  // What only some kinds of statement have lives on the heap, a pointer wide when absent: a
  // place's action is one statement of a million in a large chart (docs/performance.md).
  HeapOptional<std::string> verbatim;  ///< Kind::Verbatim
  HeapVector<Stmt> then_block;         ///< Kind::If; While, DoWhile, For: the loop's body
  /// Kind::If: empty when there is no `else`. Kind::For: the header's assignments, exactly two:
  /// the first part (run once) and the third (run after each pass of the body), so every walk
  /// over statements sees them.
  HeapVector<Stmt> else_block;
};

// ---------------------------------------------------------------- interface

struct Param {
  Type type = Type::Int;
  std::string name;  ///< may be empty: C prototypes may leave it out
};

/// A function of the robot's interface, as declared in C prototype syntax.
struct Function {
  std::string name;
  Type result = Type::Void;
  std::vector<Param> params;
  std::string interface_name;
  SourceRange range;
};

/// A constant, folded by the validator: `value` is a literal (Bool, Int, Float) or a String.
struct Const {
  std::string name;
  Type type = Type::Int;
  Expr value;
  ChartId chart;  ///< the chart that declares it, or none at file level
  SourceRange range;
};

// ---------------------------------------------------------------- sfc and fsm

/// What a var is to the chart's caller (docs/language.md §14): the chart's own state, an input the
/// caller sets before a tick, an output the caller reads after one, or both (an input the chart
/// may assign). The same order as ast::VarRole.
enum class VarRole : std::uint8_t { Local, In, Out, InOut };

/// The caller sets it before each tick: `in` and `inout`.
inline bool set_by_caller(VarRole r) { return r == VarRole::In || r == VarRole::InOut; }
/// The caller reads it after each tick: `out` and `inout`.
inline bool read_by_caller(VarRole r) { return r == VarRole::Out || r == VarRole::InOut; }
/// The keyword that declares it: `var`, `in`, `out`, `inout`.
inline const char *role_keyword(VarRole r) {
  return r == VarRole::In ? "in" : r == VarRole::Out ? "out" : r == VarRole::InOut ? "inout" : "var";
}

struct Var {
  std::string name;
  Type type = Type::Int;
  VarRole role = VarRole::Local;
  std::optional<Expr> init;  ///< absent: zero
  SourceRange range;
  std::string address;  ///< an imported IEC located variable's direct address (`%IX0.0`), or empty
};

/// `var TON t1;`: an instance of a block (docs/language.md "Blocks"). Its state is the block's
/// vars, copied into the chart (or the block) that declares it as vars[first, first + count),
/// named `t1.IN`, `t1.Q`, ... in the block's order; the members of an instance inside it follow
/// as `t1.inner.Q`. Each is a Local var of the holder: the instance's inputs are not the chart's.
struct Instance {
  std::string name;
  BlockId block;
  VarId first;
  std::uint32_t count = 0;
  SourceRange range;
};

enum class Terminal : std::uint8_t { None, Success, Failure };

using PlaceList = SmallList<PlaceId>;

/// A place of an sfc or a state of an fsm.
struct Place {
  CompactString name;
  std::vector<Stmt> action;
  HeapOptional<std::vector<Stmt>> entry;  ///< on the heap, like post: most places have none
  HeapOptional<std::vector<Stmt>> exit;
  HeapOptional<Expr> post;  ///< a terminal state's postcondition (on the heap: most places have none)
  SourceRange range;
  SourceRange name_range;  ///< the name where it is declared
  ChartId runs;            ///< the sub-chart it runs, or none
  bool initial = false;
  Terminal terminal = Terminal::None;  ///< fsm only
  bool timed = false;                  ///< some `elapsed()` reads this place's timer
};

struct Transition {
  CompactString name;  ///< the user's name, or T<position> among all transitions
  PlaceList inputs;    ///< each place once (two kept inline: small_list.h)
  PlaceList outputs;
  /// absent: `when true`. On the heap, so that the transitions table of a large chart is
  /// small while the validator fills it in (docs/performance.md).
  HeapOptional<Expr> condition;
  SourceRange range;
  SourceRange name_range;  ///< the user's name, or the whole transition when it has none
  bool named = false;      ///< the user gave the name
  bool otherwise = false;  ///< written `else`: the earlier transitions sharing an input come first by intent
};

/// The qualifiers of IEC 61131-3's action control (docs/iec.md "Action control").
enum class Qualifier : std::uint8_t { N, R, S, L, D, P, P0, P1, SD, DS, SL };

/// The qualifier as written: "N", "SD", ...
const char *qualifier_name(Qualifier q);
/// The qualifier spelled `word`, if it is one.
std::optional<Qualifier> qualifier_named(std::string_view word);
/// L, D, SD, DS and SL take a duration; the others none.
inline bool is_timed(Qualifier q) {
  return q == Qualifier::L || q == Qualifier::D || q == Qualifier::SD || q == Qualifier::DS || q == Qualifier::SL;
}

/// `N Fill;` in place P: P holds the action under a qualifier.
struct Association {
  PlaceId place;
  Qualifier qualifier = Qualifier::N;
  double duration_ms = 0;   ///< as written, for the timed qualifiers
  unsigned long ticks = 0;  ///< the duration in whole ticks, rounded up (§5.3)
  SourceRange range;
};

/// A named action (docs/language.md §14): its body and every association that holds it, in
/// place declaration order and then in the order written in the place. Its control's state
/// (stored flags, timers, the previous tick's Q) belongs to each back end.
struct Action {
  CompactString name;
  std::vector<Stmt> body;
  std::vector<Association> associations;
  SourceRange range;
  SourceRange name_range;
};

/// A structural bound on a chart's activation, proven once after validation by the analyses
/// (compiler/analysis/activation_bounds.h) for the back ends to read: the C engine sizes its
/// activation counters and lists by it (docs/c-engine.md). Sixteen bytes per chart, none per place.
struct ActivationBound {
  std::uint64_t total = 0;  ///< bounded: the activation of all places together never exceeds this
  std::uint32_t place = 0;  ///< bounded: no place's activation ever exceeds this
  bool bounded = false;     ///< proven; false also for a chart not analysed: assume no bound
};

struct Chart {
  enum class Kind { Sfc, Fsm };
  Kind kind = Kind::Sfc;
  std::string name;
  double period_ms = 0;  ///< 0: no `period` given
  Table<PlaceId, Place> places;
  Table<TransitionId, Transition> transitions;  ///< declaration order: the order of §5.1 and §7
  Table<VarId, Var> vars;
  Table<ActionId, Action> actions;    ///< named actions in declaration order: the order they run in
  std::vector<Instance> instances;    ///< block instances, in declaration order (their vars are in vars)
  std::vector<FunctionId> functions;  ///< interface functions the chart calls, in declaration order
  std::vector<ConstId> consts;        ///< constants the chart reads, in declaration order
  int team = 0;                       ///< fsm `team N;`: N (>= 2); 0 for a machine that is no team
  ActivationBound activation;         ///< recorded by analysis::record_activation_bounds
  bool in_main_file = false;          ///< declared in the file being compiled, not an import
  /// Some expression reads an action's flags (`active(A)`, `running(A)`): the action control
  /// then runs for every action before any body (docs/iec.md "Action flags").
  bool reads_action_flags = false;
  bool clock = false;  ///< `now()` is read (by the chart or a block it calls): the engine counts ticks
  SourceRange range;
  SourceRange name_range;  ///< the chart's name where it is declared
};

/// A block (docs/language.md "Blocks"): its vars (the in, out and var members in declaration
/// order, and the members of its own instances), and its body over them. A call of an instance
/// inlines the body with every var moved to the instance's (Stmt::Kind::Invoke).
struct Block {
  std::string name;
  std::vector<Var> vars;  ///< roles: In, Out, Local, as declared
  std::vector<Instance> instances;
  std::vector<Stmt> body;
  std::vector<FunctionId> functions;  ///< interface functions the body calls
  std::vector<ConstId> consts;        ///< constants the body reads
  bool standard = false;              ///< predefined by gfec (TON, CTU, ...: docs/iec.md)
  bool used = false;                  ///< some chart of the program has an instance of it
  bool clock = false;                 ///< its body (or an instance inside it) reads `now()`
  SourceRange range;
  SourceRange name_range;
};

// ---------------------------------------------------------------- toolbox and plan

enum class ParamDir { In, Out };

struct TemplateParam {
  ParamDir dir = ParamDir::In;
  Type type = Type::Float;
  std::string name;
};

/// An actor, computation or supervisor template of a toolbox.
struct Template {
  enum class Kind { Actor, Computation, Supervisor };
  Kind kind = Kind::Actor;
  std::string name;
  ToolboxId toolbox;
  std::vector<TemplateParam> params;
  std::vector<std::string> outcomes;  ///< result states, or a supervisor's events
  double period_ms = 0;               ///< supervisors: 0 means every executor step
  SourceRange range;
};

struct Toolbox {
  std::string name;
  std::vector<TemplateId> templates;
  SourceRange range;
};

struct ConfigEntry {
  std::string name;
  Type type = Type::Float;
  std::optional<Expr> init;  ///< folded to a literal
  SourceRange range;
  SourceRange name_range;  ///< the entry's name where it is declared
};

/// Where a plan rule sends an outcome: an actor, `terminate` or `ignore` (the runtime's afp::Target).
struct RuleTarget {
  enum class Kind { Actor, Terminate, Ignore };
  Kind kind = Kind::Actor;
  ActorId actor;  ///< Kind::Actor
};

/// `OUTCOME -> target`: outcome indexes the template's outcomes (or a sub-plan's OK/INTERRUPTED/ERROR).
struct Rule {
  int outcome = -1;
  RuleTarget target;
  SourceRange range;
};

/// An argument: an `in` formula over config entries, or for an `out` parameter a plain entry.
struct Arg {
  Expr formula;  ///< for out parameters an Expr of Kind::Config
  ParamDir dir = ParamDir::In;
};

struct SupervisorUse {
  std::string name;
  TemplateId templ;
  std::vector<Arg> args;
  std::vector<Rule> rules;  ///< one per event, in declaration order
  SourceRange range;
};

struct ActorUse {
  std::string name;
  TemplateId templ;  ///< none for a sub-plan
  PlanId subplan;    ///< a sub-plan's plan, or none
  std::vector<Arg> args;
  std::vector<Rule> rules;  ///< one per result state, in declaration order
  std::vector<SupervisorUse> supervisors;
  SourceRange range;
  SourceRange name_range;  ///< the actor's name where it is declared
};

/// A sub-plan's fixed result states, in this order.
inline const char *const kSubPlanStates[] = {"OK", "INTERRUPTED", "ERROR"};

struct Plan {
  std::string name;
  Table<ConfigId, ConfigEntry> config;
  std::vector<SupervisorUse> globals;
  ActorId start;
  Table<ActorId, ActorUse> actors;
  std::vector<ToolboxId> toolboxes;  ///< toolboxes whose templates the plan uses
  bool in_main_file = false;
  SourceRange range;
};

// ---------------------------------------------------------------- the whole program

struct Verbatim {
  std::string text;
  SourceRange range;
  std::uint32_t code_begin = 0;  ///< where `text` starts in range.file (after `%{`); 0: unknown
};

struct Model {
  FileId main_file = 0;
  /// LoadResult::default_chart: chosen among several candidates when --chart names none.
  std::string default_chart;
  Table<FunctionId, Function> functions;
  Table<ConstId, Const> consts;
  Table<ChartId, Chart> charts;
  Table<BlockId, Block> blocks;  ///< user blocks in declaration order, then the standard ones used
  Table<TemplateId, Template> templates;
  Table<ToolboxId, Toolbox> toolboxes;
  Table<PlanId, Plan> plans;
  std::vector<Verbatim> verbatims;  ///< file-level %{ %}: imported files first, then the main file

  /// The files the model's ranges point into. The model does not own them: the caller that
  /// validated it does (pipeline::Compilation) and keeps them as long as the model. A model made
  /// by hand has none, and then knows no range's file (no `#line`, no location is written).
  const SourceManager &sources() const { return sources_ ? *sources_ : SourceManager::empty(); }
  void set_sources(const SourceManager &sources) { sources_ = &sources; }

private:
  const SourceManager *sources_ = nullptr;
};

/// The source text of `range` with every run of whitespace folded to one space, for pictures
/// and exports that show a condition or a statement as written ("" if the text is unknown).
std::string source_text(const Model &m, const SourceRange &range);
/// Whether `range` points into chart text, which pictures and exports show as written. The ranges
/// of an ALICA plan point into its JSON (a condition's range is a reference string or a whole JSON
/// object), so those show the model's expression instead, as --emit=chart writes it. A model made
/// by hand has no sources: source_text gives "" for it, as for chart text.
bool in_chart_text(const Model &m, const SourceRange &range);
/// The transitions of `c` by the place or state their first input is (the state an fsm
/// transition leaves), each group in declaration order: built once, in one pass, so that
/// whatever looks at a state's own transitions stays linear in the chart.
IdGroups<PlaceId, TransitionId> transitions_leaving(const Chart &c);

}  // namespace gfec::model
