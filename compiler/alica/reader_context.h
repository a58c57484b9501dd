// The ALICA reader's state while it turns one plan, and every plan it runs, into the syntax tree.
// Internal to compiler/alica/; the loader calls the entry points in alica_reader.h.
//
// The reader has three jobs, each in a file of its own, and this header is what they share:
//   plan_files.{h,cc}  finding files and resolving references ("File.ext#id") into them;
//   plans.cc           converting plans: a plan becomes an fsm (an sfc of fsms with several
//                      entry points), a state that runs a plan runs its chart;
//   states.cc          converting states and transitions, with the behaviours and conditions
//                      they name becoming the functions of the robot library;
//   alica_reader.cc    the entry points: reads the main plan, then checks and cleans what the
//                      others reported.
// A state runs plans and a plan holds states, so plans.cc and states.cc call each other: they are
// one class over two files (as a compiler's semantic analysis spans files per construct) rather
// than two classes passing each other around. Finding files is a class of its own (PlanFiles):
// it keeps state of its own and needs nothing of the conversion.
#pragma once

#include "alica/identifiers.h"
#include "alica/json_tree.h"
#include "alica/plan_files.h"
#include "ast.h"
#include "diagnostics.h"
#include "import_result.h"

#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace gfec::alica {

/// Plans nest at most this deep through the states that run them, as imports do (docs/security.md):
/// reading a plan takes a few stack frames, so a chain of thousands would overflow the stack.
constexpr int kMaxPlanDepth = 200;

/// Whether a member holds anything: not null, no empty array, object or string.
inline bool non_empty(const JsonValue *v) {
  if (!v || v->is_null()) return false;
  if (v->is_array()) return !v->items.empty();
  if (v->is_object()) return !v->members.empty();
  if (v->is_string()) return !v->text.empty();
  return true;
}

/// A plan's states by id, and the index of the state a reference to one ("inState", an entry
/// point's "state") names, if the plan has it.
using StateIndex = std::map<std::string, std::size_t>;
inline std::optional<std::size_t> state_named(const StateIndex &index, const JsonValue *v) {
  auto id = id_of(v);
  if (!id) return std::nullopt;
  auto it = index.find(*id);
  if (it == index.end()) return std::nullopt;
  return it->second;
}

/// One fsm a plan becomes: the states one entry point reaches.
struct Machine {
  ast::Chart chart;
  NameScope states, transitions;
  std::string entry_state;  ///< id of its initial state
};

class Reader {
public:
  Reader(const LoadOptions &options, const FileSystem &fs, SourceManager &sources, Diagnostics &diag,
         LoadResult &result)
      : files_(options, fs, sources, diag, result), sources_(sources), diag_(diag), result_(result) {}

  /// Reads the plan in `path` and everything it runs (alica_reader.cc).
  void read_main(const std::string &path, std::string text);

private:
  // ---------------------------------------------------------- alica_reader.cc: the main plan
  void read_plan(const std::string &path, std::string text);
  void duplicate_members();
  void duplicate_members(const Doc &doc, const JsonValue &v);

  // ---------------------------------------------------------- shared by plans.cc and states.cc
  /// An id that is there but is no integer: reported, true (alica_reader.cc).
  bool not_an_id(const Doc &doc, const JsonValue *v, const std::string &what);
  /// Records an element read, so that diagnostics about it can name it (loader.h).
  void element(const Doc &d, const JsonValue &v, std::string description) {
    result_.elements.push_back({range(d, v), std::move(description)});
  }
  /// A warning that something in the file is ignored, and why.
  void ignored(const Doc &d, const JsonValue &v, std::string message) { ignored(range(d, v), std::move(message)); }
  void ignored(const SourceRange &at, std::string message) {
    diag_.warning(Warning::AlicaIgnored, at, std::move(message));
  }
  /// A made-up name kept for the tree's names to view (ast.h: names own no text).
  std::string_view keep(std::string text) { return main_->strings.emplace_back(std::move(text)); }
  /// A chart's or function's name: charts and functions share C's namespace.
  std::string global_name(const std::string &text, const std::string &id, const std::string &fallback) {
    return globals_.take(identifier(text, fallback + id), id);
  }

  // ---------------------------------------------------------- plans.cc: plans
  std::string plan_chart(Doc &doc, const JsonValue &plan, const SourceRange &at);
  std::string plan_type_chart(const Resolved &t, const SourceRange &at);
  void plan_warnings(Doc &doc, const JsonValue &plan, const std::string &what);
  std::string entry_label(Doc &doc, const JsonValue &ep);
  void convert_plan(Doc &doc, const JsonValue &plan, const std::string &name);
  void entry_warnings(Doc &doc, const JsonValue &ep, const std::string &label, const std::string &id, bool several);
  std::size_t file_index(const Doc &doc) const;

  // ---------------------------------------------------------- states.cc: states and transitions
  std::vector<std::pair<std::string, SourceRange>> references(const Doc &doc, const JsonValue &state,
                                                              const std::string &what);
  ast::Place convert_state(Doc &doc, const JsonValue &state, Machine &m, const std::string &plan_what,
                           std::string &gfec_name);
  ast::ExprPtr child_outcome(const JsonValue &cond, const ast::Place *source, const SourceRange &at);
  void child_outcome_unobserved(const JsonValue &cond, const ast::Place *source, const SourceRange &at,
                                const std::string &what);
  void convert_transition(Doc &doc, const JsonValue &t, std::vector<Machine> &machines, const std::vector<int> &owner,
                          const std::vector<std::string> &state_names, const StateIndex &state_index,
                          const std::string &plan_what);
  // The functions of the robot library that behaviours and conditions become.
  void declare(const std::string &name, const char *result, const SourceRange &at);
  std::string behaviour(const Resolved &t);
  std::string condition(Doc &doc, const JsonValue &cond, const std::string &fallback);
  void condition_warnings(const Doc &doc, const JsonValue &cond, const std::string &why);
  ast::ExprPtr call(const std::string &name, const SourceRange &at);

  PlanFiles files_;
  SourceManager &sources_;
  Diagnostics &diag_;
  LoadResult &result_;
  ast::File *main_ = nullptr;                       ///< the main plan's file: holds the interface
  std::set<const JsonValue *> plan_type_warned_;    ///< a plan type used by several states warns once
  std::map<std::string, std::string> plan_charts_;  ///< "path#id" -> chart name ("": not converted)
  int plan_depth_ = 0;                              ///< plans being converted, the compiled one first
  std::map<std::string, bool> fsm_charts_;          ///< chart name -> it is an fsm (one entry point)
  std::map<std::string, std::string> functions_;    ///< "path#id" of a behaviour or condition -> function
  NameScope globals_;                               ///< charts and functions share C's namespace
};

}  // namespace gfec::alica
