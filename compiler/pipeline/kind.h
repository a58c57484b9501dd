// What can be compiled, as bits: the one enum for "which kind of thing". A Selection holds one
// bit (pipeline/compilation.h); a SelectionRequest chooses among a set, and a back end accepts a
// set (backends/backend_registry.h).
#pragma once

#include <string>

namespace gfec::pipeline {

enum Kind : unsigned { kSfc = 1, kFsm = 2, kPlan = 4, kToolbox = 8 };
/// A chart file's charts: what the C engine, `gfec run` and `gfec test` take.
constexpr unsigned kCharts = kSfc | kFsm;

/// "sfc", "fsm", "plan" or "toolbox": the name of one Kind bit, for messages.
const char *kind_name(unsigned kind);
/// "sfc, fsm and plan" (`last` = "and") or "sfc or fsm" (`last` = "or"): the kinds of a set.
std::string kinds_text(unsigned kinds, const char *last);

}  // namespace gfec::pipeline
