// An IEC 61131-3 SFC that is not a program's own body: the body of an ACTION, or of a
// FUNCTION_BLOCK. Something other than its transitions starts it, runs it and stops it (the
// action's control, an instance's call), which the chart language's places cannot say; so the
// lowering compiles such an SFC into statements, one scan of it, over variables of its holder
// (its steps as BOOL variables, their `.T` as TIME ones). Its holder's engines, interpreter and
// chart text then run it as any statements: docs/iec.md "SFC inside actions and function blocks".
#pragma once

#include "ast.h"
#include "diagnostics.h"
#include "iec/iec_model.h"
#include "iec/spellings.h"

#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace gfec::iec {

/// What compiling a POU's inner SFCs adds to its chart or block.
struct InnerSfcs {
  std::vector<ast::ValueDecl> variables;  ///< the generated state, `var`s of the holder, in order
  /// The actions (upper case) that now run inside an SFC's scan: the holder does not declare them.
  std::set<std::string> inner;
  /// What `Step.X`, `Step.T`, `A.Q` and `A.A` of an inner step or action read (upper case ->
  /// the generated variable): rewrite_inner_reads makes each read one of a variable.
  std::map<std::string, std::string_view> x, t, q, a;
  bool period_reported = false;  ///< an SFC's timers asked for the period the program lacks
};

/// Compiles the SFC of every ACTION of `pou` that has one, in place: such an action's body
/// becomes its SFC's scan (and the bodies of the actions its steps hold, inlined into it). For
/// a FUNCTION_BLOCK whose body is an SFC (`function_block`), pou.steps/transitions are that SFC
/// and its scan becomes pou.body. `names` holds every name of the POU (inner steps too), with
/// which expressions were respelled; the generated names are declared in it. `period_ms`: the
/// program's period, which an action's SFC counts its step timers in (a function block's reads
/// now() instead).
InnerSfcs compile_inner_sfcs(Pou &pou, bool function_block, Spellings &names, ast::File &file, Diagnostics &diag,
                             std::optional<double> period_ms);

/// `active(S)`, `elapsed(S)`, `active(A)`, `running(A)` of an inner step S or action A: reads of
/// the variables that hold them.
void rewrite_inner_reads(ast::Expr &e, const InnerSfcs &sfcs);
void rewrite_inner_reads(std::vector<ast::Stmt> &block, const InnerSfcs &sfcs);

}  // namespace gfec::iec
