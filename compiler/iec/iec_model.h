// The IEC 61131-3 program model: what the structured-text reader (st_reader.h) and the PLCopen
// XML reader both fill, and what one lowering (lower.h) turns into the chart syntax tree.
// docs/iec.md says what each element means and how it maps onto the chart language.
//
// Names and expressions are those of the chart syntax tree (ast.h): ST expressions and
// statements are parsed straight into ast::Expr and ast::Stmt by st_fragment.h, with operator
// ranges on what the user wrote (`AND`, `<>`), so messages quote the IEC spelling. As in the
// tree, names own no text: they view the source text or a string the reader keeps
// (ast::File::strings), which outlive the model and the tree made from it.
#pragma once

#include "ast.h"
#include "source.h"

#include <algorithm>
#include <cstdint>
#include <optional>
#include <vector>

namespace gfec::iec {

/// A variable section. The readers report the others (VAR_IN_OUT, VAR_TEMP, a POU's VAR_GLOBAL,
/// ...) as located "not supported yet" errors. External is a POU's VAR_EXTERNAL, which names a
/// Global: a VAR_GLOBAL of a CONFIGURATION or RESOURCE (docs/iec.md "Global variables").
enum class Section : std::uint8_t { Input, Output, Local, External, Global, InOut };

/// `Start : BOOL;`, `Count : DINT := 3;` in one of the sections.
struct Variable {
  Section section = Section::Local;
  ast::Name name;
  /// The type as written (`BOOL`, `dint`, `TON`, `ARRAY` ...): the lowering maps BOOL, DINT, REAL,
  /// LREAL and reports every other as not supported yet, at this range.
  ast::Name type;
  ast::ExprPtr init;  ///< the initial value (an ST expression), or null
  /// `AT %IX0.0` was written (a located variable): its range, else empty. The lowering makes a
  /// %I variable an input, %Q an output and %M a local variable (docs/iec.md "Located variables").
  std::optional<SourceRange> located;
  std::string_view address;  ///< the direct address as written (`%IX0.0`), when located
  bool constant = false;     ///< in a `VAR CONSTANT` (`VAR_GLOBAL CONSTANT`, ...) section
  SourceRange range;
};

/// A step. Its associations are those of the chart language (ast::Association): the qualifier
/// as written (N R S L D P P0 P1 SD DS SL, any case), the action, the duration in milliseconds.
struct Step {
  ast::Name name;
  bool initial = false;
  std::vector<ast::Association> associations;
  SourceRange range;
};

/// `TRANSITION [name] [(PRIORITY := n)] FROM s TO t := condition; END_TRANSITION`, or a PLCopen
/// transition between the steps it links.
struct Transition {
  std::optional<ast::Name> name;
  std::optional<long long> priority;  ///< lower first within a selection divergence (docs/iec.md)
  SourceRange priority_range;
  std::vector<ast::Name> from, to;  ///< the preceding and succeeding steps
  bool parenthesised_from = false, parenthesised_to = false;
  ast::ExprPtr condition;  ///< a BOOL ST expression; never null in a transition the reader kept
  SourceRange range;
};

/// Puts `transitions` in the order the scan tries them: within a selection divergence a PRIORITY
/// orders them, lower first, and those without one keep their order after those with one
/// (docs/iec.md). Transitions of different divergences never compete, so one stable order over
/// all of them says the same.
inline void order_by_priority(std::vector<Transition> &transitions) {
  std::stable_sort(transitions.begin(), transitions.end(), [](const Transition &a, const Transition &b) {
    if (!a.priority || !b.priority) return a.priority.has_value() && !b.priority.has_value();
    return *a.priority < *b.priority;
  });
}

/// `ACTION name: <ST statements> END_ACTION`, or an action whose body is an SFC: `ACTION name:
/// INITIAL_STEP ... END_ACTION`, a PLCopen action whose body is `<SFC>` (docs/iec.md "SFC inside
/// actions and function blocks"). The actions its steps hold are the POU's, in Pou::actions.
struct Action {
  ast::Name name;
  ast::Block body;                      ///< an ST body; empty when the body is an SFC
  std::vector<Step> steps;              ///< an SFC body's steps, in declaration order; else empty
  std::vector<Transition> transitions;  ///< an SFC body's transitions
  bool sfc() const { return !steps.empty() || !transitions.empty(); }
  SourceRange range;
};

enum class PouKind : std::uint8_t { Program, FunctionBlock, Function };

/// A program organisation unit: a PROGRAM (what gfec compiles), or a FUNCTION_BLOCK or
/// FUNCTION a reader met (the lowering reports those as not supported yet).
struct Pou {
  PouKind kind = PouKind::Program;
  ast::Name name;
  std::vector<Variable> variables;  ///< in declaration order, all sections together
  std::vector<Step> steps;          ///< in declaration order
  std::vector<Transition> transitions;
  std::vector<Action> actions;  ///< in declaration order: the order their bodies run in
  /// The POU's body when it is statements, not an SFC: ST as written, or an FBD or LD network
  /// read as the ST it means. A program so is a chart of one step that runs them every scan; a
  /// FUNCTION_BLOCK's statements are its block's body.
  std::optional<ast::Block> body;
  SourceRange body_range;  ///< where the body's first statement is, when the reader knows
  /// The POU has a body that is not an SFC (plain ST statements, LD, FBD, IL): where, to report
  /// it as not supported yet. Empty range when the body is an SFC or there is none.
  std::optional<SourceRange> other_body;
  SourceRange range;
};

/// `TASK name (INTERVAL := T#10ms, PRIORITY := 1);` and the program instances it runs
/// (`PROGRAM inst WITH name : Pou;`).
struct Task {
  ast::Name name;
  std::optional<double> interval_ms;
  SourceRange interval_range;
  std::vector<ast::Name> programs;  ///< the POU (type) names of the instances it runs
  SourceRange range;
};

/// `TYPE Level : INT; END_TYPE`, or a PLCopen `<dataType>` whose `<baseType>` is an elementary
/// type or another alias: another name of a type (docs/iec.md "Type aliases").
struct TypeAlias {
  ast::Name name;
  ast::Name base;  ///< as written: `INT`, `HMI_INT`
  SourceRange range;
};

/// Everything one file declares: its POUs in order, and the tasks of its CONFIGURATION /
/// RESOURCE (the period of a program is the INTERVAL of the task that runs it).
struct Project {
  std::vector<Pou> pous;
  std::vector<Task> tasks;
  /// The VAR_GLOBALs of its CONFIGURATIONs and RESOURCEs, in declaration order (Section::Global):
  /// one scope for the whole file, which the lowering checks for a name declared twice.
  std::vector<Variable> globals;
  std::vector<TypeAlias> aliases;  ///< the file's type aliases, in declaration order
};

}  // namespace gfec::iec
