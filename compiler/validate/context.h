// What every family of checks shares while one program is validated: the inputs, the model
// being built, and the global symbol table across files.
#pragma once

#include "ast.h"
#include "diagnostics.h"
#include "model.h"
#include "validate/names.h"

#include <functional>
#include <set>
#include <string>
#include <vector>

namespace gfec::validation {

struct ChartScope;

/// Where a constant comes from, and how far its folding got (folding is lazy: a const may use
/// one declared later, or in a file imported later).
struct ConstSource {
  enum class State { Pending, Busy, Done, Failed };
  const ast::ValueDecl *decl = nullptr;
  State state = State::Pending;
  bool used = false;  ///< an expression, a plan argument or another constant reads it (-Wunused-const)
};

/// A block's declaration and how far its validation got (blocks are validated on first use,
/// as an instance needs its block's vars).
struct BlockSource {
  enum class State { Pending, Busy, Done, Failed };
  ast::BlockDecl *decl = nullptr;
  State state = State::Pending;
};

struct Context {
  Context(ast::Program &p, const SourceManager &s, Diagnostics &d, model::Model &m)
      : program(p), sources(s), diag(d), model(m) {}

  /// Not const: a chart's bodies are released once lowered, unless keep_tree (validate.h).
  ast::Program &program;
  bool keep_tree = false;
  /// ValidateOptions::declaring_files: for the note on an unknown function.
  std::function<std::vector<std::string>(const std::string &)> declaring_files;
  const SourceManager &sources;
  Diagnostics &diag;
  model::Model &model;

  /// Interface functions, file-level constants and charts: generated C puts all three in its
  /// one global namespace (a chart `X` becomes `X_init`, `struct X`, ...).
  Namespace c_names;
  /// Toolbox templates and plans: an actor names either, so they must be told apart.
  Namespace plan_names;
  Namespace interfaces;
  Namespace toolboxes;
  /// Blocks (docs/language.md "Blocks"): a type name in a `var` may name one.
  Namespace blocks;
  Table<model::BlockId, BlockSource> block_sources;
  /// ValidateOptions::name_uses: every namespace made while validating records into it.
  NameUses *uses = nullptr;

  /// Parallel to the model tables: the declaration each element was lowered from.
  Table<model::ConstId, ConstSource> consts;
  Table<model::FunctionId, bool> function_ok;  ///< false: its declaration has an error; calls stay silent
  Table<model::ChartId, ast::Chart *> charts;
  Table<model::TemplateId, const ast::Template *> templates;
  Table<model::TemplateId, bool> template_ok;  ///< false: a parameter type is wrong; arguments stay unchecked
  Table<model::PlanId, const ast::Plan *> plans;

  /// A global name, declared once every file's model entries exist (see collect_symbols).
  struct GlobalName {
    Namespace *ns;
    const ast::Name *name;
    Sym kind;
    int index;
    int file;  ///< position in program.files
  };
  std::vector<GlobalName> global_names;
  int current_file = 0;
  template <typename Tag> void declare_global(Namespace &ns, const ast::Name &name, Sym kind, Id<Tag> index) {
    global_names.push_back({&ns, &name, kind, symbol_index(index), current_file});
  }
  /// A name that is no element of the model (an interface).
  void declare_global(Namespace &ns, const ast::Name &name, Sym kind) {
    global_names.push_back({&ns, &name, kind, -1, current_file});
  }

  /// Sub-charts (subcharts.cc), per chart: for each place the chart it runs (or none), and the
  /// period it takes from the charts that run it when it declares none (0: none to take).
  IdMap<model::ChartId, IdMap<model::PlaceId, model::ChartId>> runs;
  IdMap<model::ChartId, double> inherited_period;

  /// The chart being validated: its constants fold in its scope.
  ChartScope *chart = nullptr;
  /// Constants being folded, one inside the other's initialiser.
  int const_depth = 0;
  /// Unknown names at file level, each reported once.
  std::set<std::string> file_unknown;

  bool in_main_file(const SourceRange &r) const {
    return !program.files.empty() && program.files.front() && r.file == program.files.front()->id;
  }
};

/// Watches for errors from a point on: a chart or plan with errors of its own gets no warnings,
/// which an error (an unknown place, say) would turn into guesses. Warnings that -Werror made
/// errors do not count, and neither does anything once the error limit dropped errors.
class ErrorWatch {
public:
  explicit ErrorWatch(const Diagnostics &diag) : diag_(diag), first_(diag.all().size()) {}
  bool clean() const {
    if (diag_.limit_reached()) return false;
    for (std::size_t i = first_; i < diag_.all().size(); ++i) {
      const Diagnostic &d = diag_.all()[i];
      if (d.severity == Severity::Error && !d.from_warning()) return false;
    }
    return true;
  }

private:
  const Diagnostics &diag_;
  std::size_t first_;
};

/// "'int'": a type as messages quote it.
std::string quoted(model::Type t);

}  // namespace gfec::validation
