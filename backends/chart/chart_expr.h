// Expressions and statements of the model, spelled as chart text (docs/language.md).
#pragma once

#include "code_writer.h"
#include "model.h"

#include <string>
#include <vector>

namespace gfec::chart_text {

/// A name as chart text writes it: `` `place` `` when it is spelled as a keyword (an imported IEC
/// name), else as it is.
std::string name(std::string_view n);
/// `e`, read in chart `chart` (its places, variables and the charts its places run).
std::string expr(const model::Model &m, model::ChartId chart, const model::Expr &e);
/// The statements of a block, one per line, at the writer's indentation.
void statements(CodeWriter &w, const model::Model &m, model::ChartId chart, const std::vector<model::Stmt> &block);

}  // namespace gfec::chart_text
