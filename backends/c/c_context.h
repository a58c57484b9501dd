// What every part of the C back end shares while it writes one chart's engine: the chart, the
// options, the C name chosen for each element, and the facts about the chart that decide which
// parts of the engine exist at all (an engine pays only for what its chart uses).
#pragma once

#include "backend.h"
#include "c_context_type.h"
#include "c_engine_options.h"
#include "c_layout.h"
#include "model.h"
#include "naming/naming.h"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace gfec::c_backend {

class FormWriter;

/// The engine being written: its chart and options, the names chosen, the layout.
struct EngineContext {
  EngineContext(const model::Model &m, const model::Chart &ch, const EmitOptions &o)
      : model(m), chart(ch), options(o), engine_options(backend_options<CEngineOptions>(o)),
        context_type(engine_options.context_type) {}

  const model::Model &model;
  const model::Chart &chart;
  const EmitOptions &options;
  const CEngineOptions &engine_options;  ///< the C engine's own options (--context, --names)
  ContextType context_type;              ///< --context-type, read once
  bool fsm = false;
  Layout layout;  ///< readable, sequential or sparse (c_layout.h)
  /// The writer of what depends on the engine's form (c_form.h): the fsm's, or the layout's.
  const FormWriter &form() const;
  /// The readable form's counter type: as narrow as the proven bound allows, else 32 bits (GFE's
  /// unsigned, which is 16 bits on an AVR).
  const char *readable_counter() const {
    return layout.activation.bounded ? uint_type(layout.counter_bits) : "uint32_t";
  }

  // ------------------------------------------------------------ names in the generated code
  std::string type;         ///< the prefix of every global name: the chart's name, or for a
                            ///< sub-chart instance its path (`Patrol_Search`, docs/c-engine.md)
  std::string struct_type;  ///< the state's C type: `Patrol`, or an instance's `struct Patrol_Search`
  std::string linkage;      ///< "" for the root's API, "static " for an instance's functions
  std::string init_fn;      ///< X_init
  std::string run_fn;       ///< X_run
  std::string stop_fn;      ///< an instance's X_stop (exits of its active places, innermost first)
  std::string source_file;  ///< engine.c as #line names it (the output path as the user gave it)
  std::string header_file;  ///< engine.h, as engine.c includes it (base name)
  std::string guard;        ///< the header's include guard (free of every name the file uses)
  /// The header's fingerprint (docs/c-engine.md "Header and engine together"): 8 hex digits of a
  /// hash of the header's text; empty until c_backend.cc has rendered the header.
  std::string fingerprint;
  /// X_init and X_run as the linker sees them: the names with the fingerprint, so that code
  /// compiled against another version of the header does not link.
  std::string stamped(const std::string &fn) const { return fn + std::string(naming::kFingerprintInfix) + fingerprint; }
  /// Defined by the header: the engine refuses to compile against any other version of it.
  std::string layout_macro() const { return guard + "_LAYOUT_" + fingerprint; }
  std::string hooks_macro;       ///< X_HOOKS: define it to get the observation hooks
  std::string checks_macro;      ///< X_CHECKS: define it to assert the postconditions of an fsm
  std::string assert_macro;      ///< X_ASSERT(cond): the checks' handler; the user's, else assert
  std::string assert_off_macro;  ///< X_ASSERT_OFF: set when X_ASSERT is assert under NDEBUG
  /// The root's macros (the guard, X_HOOKS, X_CHECKS, X_ASSERT, X_ASSERT_OFF): a macro replaces
  /// a name wherever it stands, so no field, parameter or other name of the file has one's name.
  std::vector<std::string> macros;
  std::string activated_fn;                                  ///< X_activated
  std::string enabled_fn;                                    ///< X_enabled
  std::string place_count;                                   ///< X_PLACE_COUNT
  std::string place_type;                                    ///< X_place: the enum type of the places (states)
  std::string transition_type;                               ///< X_transition: the enum type of the transitions
  std::string transition_count;                              ///< X_TRANSITION_COUNT
  IdMap<model::PlaceId, std::string> place_const;            ///< X_<place>
  IdMap<model::TransitionId, std::string> transition_const;  ///< X_<transition>
  // The scalable form's file-local helpers (named after the enumerations, so that a place
  // called `lowest` keeps its constant X_lowest and the helper gives way).
  std::string lowest_fn;         ///< the number of the lowest bit of a word
  std::string next_fn;           ///< the next member of a set with summary levels
  std::string insert_fn;         ///< adds a member
  std::string erase_fn;          ///< removes a member
  std::string sort_fn;           ///< sorts a short list of place numbers
  std::string watched_fn;        ///< whether a place runs exit/entry code or resets a timer
  std::string active_levels;     ///< where the levels of the active set begin
  std::string candidate_levels;  ///< where the levels of the candidate set begin
  /// The split sequential form (Layout::part_places): part `k` of the switch `kind` (one of
  /// kPartKinds) is the function `<part_base>_<kind>_<k>`, and the table of a switch's parts is
  /// `<part_base>_<kind>_parts`; part_base is the type, moved aside if a name is taken.
  std::string part_base;
  static constexpr const char *kPartKinds[] = {"time", "update", "exit", "enter", "hook", "act"};
  std::size_t part_count() const { return (chart.places.size() + layout.part_places - 1) / layout.part_places; }
  std::string part_fn(const char *kind, std::size_t k) const {
    return part_base + "_" + kind + "_" + std::to_string(k);
  }
  std::string part_table(const char *kind) const { return part_base + "_" + kind + "_parts"; }
  /// The table of the place each place moves to when its one transition fires (`<part_base>_moves`).
  std::string part_next() const { return part_base + "_moves"; }

  // Struct fields: chart variables keep their own names; the engine's own fields give way
  // (take a trailing `_`) if a variable already has their name.
  IdMap<model::VarId, std::string> var_field;
  /// "" for a place without a timer; no entries at all when no place has one.
  IdMap<model::PlaceId, std::string> timer_field;
  std::string av;          ///< sfc: activation counters
  std::string state;       ///< fsm: the current state
  std::string status;      ///< fsm: 0 running, 1 succeeded, -1 failed
  std::string started;     ///< set by the first tick, when an initial place has an entry block
  std::string clock;       ///< the ticks run, when now() is read (model::Chart::clock)
  std::string current;     ///< sequential form: the number of the one active place
  std::string active;      ///< sparse form: the active places as bits with summary levels
  std::string candidates;  ///< sparse form, not place-driven: the transitions to try this tick
  // Action control (docs/iec.md "Action control"): the state each back end keeps for itself.
  // Tables only when the chart has named actions; "" for an action (place) that needs no field.
  IdMap<model::ActionId, std::string> action_q;  ///< the action's Q of the previous tick (its final run)
  /// When the chart reads action flags (`running(A)`): the action's body runs at the latest
  /// action control; all controls then come before all bodies (docs/iec.md "Action flags").
  IdMap<model::ActionId, std::string> action_a;
  /// Set by S, DS, SD 0 and an SL beyond the timers' range (one flag: each is only set, and one R
  /// clears them all), cleared by R.
  IdMap<model::ActionId, std::string> action_stored;
  /// SD and SL with a duration the timers reach: the flag and the ticks since its set.
  IdMap<model::ActionId, std::string> action_sd, action_sd_timer, action_sl, action_sl_timer;
  /// Places holding an action with P, P1 or P0: active at the previous tick's action control.
  IdMap<model::PlaceId, std::string> was_active;
  /// Set by the first tick's action control, when an initial place holds an action with P0: till
  /// then that place counts as active before for P0 (left in tick 1, it falls in tick 1).
  std::string acted;
  // A team machine's (docs/c-engine.md "Team machines"); empty for a machine that is no team.
  std::string agent;         ///< this engine's agent number
  std::string reports;       ///< by agent, the state it last reported (-1: none)
  std::string set_agent_fn;  ///< X_set_agent
  std::string report_fn;     ///< X_report
  std::string team_size;     ///< X_TEAM_SIZE, the number of agents
  std::string team_fn;       ///< X_team: how many other agents last reported a state
  // The instance context (--context, docs/c-engine.md "Instance context"); empty without it.
  std::string ctx_field;       ///< the struct member holding it, in the root and every instance
  std::string ctx_param;       ///< X_set_context's parameter, and the prototypes' first one
  std::string set_context_fn;  ///< X_set_context
  std::string context_fn;      ///< X_context
  // Sub-chart instances, for the caller (docs/c-engine.md "Sub-charts"); empty without any.
  std::string instance_type;           ///< the root's X_instance: the instances' numbers
  std::string instance_count;          ///< the root's X_INSTANCE_COUNT
  std::string instance_activation_fn;  ///< the root's X_instance_activation
  std::string instance_const;          ///< an instance's number in X_instance: `Patrol_Search_INSTANCE`
  // --trace (docs/live.md), the root's only; empty without it.
  std::string trace_write_fn;  ///< X_trace_write, the user's: where each frame goes
  std::string trace_frame_fn;  ///< the file-local writer of one tick's frame
  std::string trace_put_fn;    ///< the file-local writer of one number (7 bits a byte)
  std::string step_fn;         ///< the file-local tick that X_run runs before the frame
  std::string trace_tick;      ///< field: the ticks run since _init
  std::string trace_left;      ///< field: delta frames before the next full one
  std::string trace_prev;      ///< field: the values of the last frame
  bool traced() const { return root && engine_options.trace; }
  // --trace=calls: every interface call goes through a file-local wrapper that records it; the
  // root and every instance share the root's wrappers. Empty without the option.
  IdMap<model::FunctionId, std::string> call_wrapper;  ///< by function, "" for one no chart calls
  std::string calls_buffer, calls_count, calls_cut;    ///< the tick's recorded calls
  std::string call_record_fn;                          ///< records a number
  std::string call_bytes_fn;                           ///< records a float's or double's bytes
  std::string zigzag_fn;                               ///< an int32_t as an unsigned number
  std::string place_name_fn;                           ///< X_place_name (--names)
  std::string transition_name_fn;                      ///< X_transition_name (--names)
  /// Every interface call passes the context first.
  bool has_context() const { return !context_type.spelling.empty(); }
  /// `void *ctx`, `struct motor *ctx`: the context as a parameter called `name`.
  std::string context_param(const std::string &name) const { return context_type.param(name); }

  // Locals of the run function. They must not hide an interface function that chart code calls.
  std::string self;    ///< the engine parameter, `m`
  std::string add;     ///< sfc: activation produced in this tick
  std::string before;  ///< sfc: the activation vector at the start of the tick
  std::string from;    ///< fsm: the state at the start of the tick
  std::string to;      ///< fsm: the state entered, while the old one's exit blocks run
  std::string index;   ///< a loop index
  std::string q;       ///< a named action's Q in this tick
  std::string names;   ///< --names: the table in X_place_name and X_transition_name
  // Locals of the scalable form's run function.
  std::string add_n, lost, lost_n, gained, gained_n, word, bits, i, t;
  /// The split sequential form: an update part's result, the active place's one transition fired.
  std::string fire;
  /// The temporaries that keep calls in order are this and a number: `gfec_t0` (c_expr.h).
  std::string temp_prefix;

  // ------------------------------------------------------------ sub-charts (docs/language.md, "Sub-charts")
  bool root = true;   ///< the compiled chart; false for an instance embedded in a parent
  std::string owner;  ///< an instance: "place Search of Patrol", for comments
  /// By place: the context of the instance the place runs (null if it runs nothing), and the
  /// parent struct's field that holds it.
  IdMap<model::PlaceId, std::unique_ptr<EngineContext>> sub;
  IdMap<model::PlaceId, std::string> sub_field;  ///< like timer_field: no entries when no place runs a chart
  bool stoppable = false;                        ///< an instance whose place (or an enclosing one) can lose activation
  bool stop_code = false;                        ///< stopping the instance runs code: some exit block, at any depth
  /// The stop function exists (and is called): it can be stopped and stopping runs code.
  bool has_stop() const { return stoppable && stop_code; }
  /// Some transition condition reads, through active()/succeeded()/failed(), a place whose
  /// counter the transitions decrease: the sfc forms keep the start of the tick for them.
  bool reads_start = false;
  /// An fsm whose exit blocks read activation: the state left is current while they run
  /// (docs/language.md: the new state becomes current after the old one's exit).
  bool exits_read_activity = false;
  /// The root: every interface function any instance calls, for the header.
  std::vector<model::FunctionId> functions;
  const EngineContext *sub_of(model::PlaceId place) const { return sub.at(place).get(); }
  /// The observation hooks are the root's only (docs/c-engine.md).
  bool hooks() const { return root; }
  /// The size of the per-place arrays as the header writes it: X_PLACE_COUNT (an instance's
  /// enumerations are in the header too, before its struct).
  std::string count_text() const;
  /// `obj.name`, or `m->name` for obj "" (the engine's own state).
  std::string member(const std::string &obj, const std::string &name) const;
  /// A C test (unbracketed, not a bool operand yet) that place `p` of the state `obj` (see
  /// member()) is active now; `at_start`: in a transition condition of this chart, where the
  /// start of the tick counts (docs/language.md, "Sub-charts").
  std::string active_test(const std::string &obj, model::PlaceId p, bool at_start = false) const;
  /// The engine code that starts, ticks or stops the instance place `p` runs (`Patrol_Search_run(
  /// &m->Search);`), as lines; none where the place runs nothing (or stopping runs no code).
  std::vector<std::string> start_call(model::PlaceId p) const;
  std::vector<std::string> tick_call(model::PlaceId p) const;
  std::vector<std::string> stop_call(model::PlaceId p) const;
  /// Place `p` has something to do in the actions step: an action block or an instance to tick.
  bool has_sub() const {
    for (const auto &s : sub)
      if (s) return true;
    return false;
  }
  bool acts(model::PlaceId p) const { return !place(p).action.empty() || sub_of(p); }
  /// Calls `f(instance, member)` for every instance below this context, depth first in declaration
  /// order (parents first: the numbering of X_instance), `member` how its struct is reached from
  /// `prefix` (`m->` gives `m->Search`, then `m->Search.Grab`).
  void each_instance(const std::string &prefix,
                     const std::function<void(const EngineContext &, const std::string &)> &f) const {
    for (model::PlaceId p : sub.ids()) {
      if (!sub[p]) continue;
      const std::string member = prefix + sub_field[p];
      f(*sub[p], member);
      sub[p]->each_instance(member + ".", f);
    }
  }

  // ------------------------------------------------------------ what the chart uses
  IdMap<model::PlaceId, bool> is_input;   ///< some transition consumes its activation
  IdMap<model::PlaceId, bool> is_output;  ///< some transition produces activation in it
  bool has_timers = false;                ///< some place has a timer
  bool has_post = false;                  ///< some terminal state has a postcondition
  bool has_terminal = false;              ///< some state is terminal
  bool needs_started = false;             ///< an initial place has a non-empty entry block
  /// Some named action has an association: the run function ends with their action control.
  bool has_named_actions() const {
    for (const auto &a : chart.actions)
      if (!a.associations.empty()) return true;
    return false;
  }
  bool team() const { return chart.team > 0; }
  /// The type of a report: the narrowest signed type that holds every state and -1.
  const char *report_type() const;

  const model::Place &place(model::PlaceId p) const { return chart.places.at(p); }
  /// `m->field`.
  std::string field(const std::string &name) const { return self + "->" + name; }
  /// `m->av[X_P]`.
  std::string av_of(model::PlaceId place) const;
  /// `m->timer_P`.
  std::string timer_of(model::PlaceId place) const;
  /// A place's exit (or entry) block runs only if the place can lose (gain) its activation.
  bool runs_exit(model::PlaceId place) const;
  bool runs_entry(model::PlaceId place) const;
  /// The place's timer is reset when it gains activation after the start.
  bool resets_timer(model::PlaceId place) const;
  /// Some place runs an exit or entry block or resets its timer: the run function compares the
  /// start of the tick with its end (a snapshot of the activation vector, or of the state).
  bool needs_snapshot() const;
  /// The place's exit or entry code runs, or its timer is reset, when its activation changes.
  bool watched(model::PlaceId place) const { return runs_exit(place) || runs_entry(place) || resets_timer(place); }
  /// Some place is watched.
  bool any_watched() const;
};

/// Decides every name and fact for compiling `chart`, and for every sub-chart instance below it.
std::unique_ptr<EngineContext> make_context(const model::Model &model, const model::Chart &chart,
                                            const EmitOptions &options);

/// What the engine's action control does with an association (docs/iec.md "Action control in
/// the C engine"): a term of Q, an edge that runs the body, a set of the stored flag, a reset, a
/// set of the SD or SL flag with its timer, or nothing (`SL 0` is never active, nor is an SD whose
/// duration the timers never reach).
enum class Keep : std::uint8_t { Q, Edge, Set, Reset, Sd, Sl, Nothing };
Keep kept_as(const model::Association &as);

/// The block holds code (an empty `entry { }` is as good as none).
inline bool has_code(const HeapOptional<std::vector<model::Stmt>> &block) { return block && !block->empty(); }

}  // namespace gfec::c_backend
