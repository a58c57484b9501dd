// Which floating types an engine computes with at run time. The language's float is IEEE
// binary32 and its double binary64 on every target (docs/targets.md); an engine that needs one
// refuses, with #error, to compile where the C compiler's type is anything else (avr-gcc's
// double is 32 bits), and one that does floating arithmetic pins contraction off so that no
// compiler fuses `a * b + c` into one rounding.
#pragma once

#include "c_context.h"

namespace gfec::c_backend {

struct FloatingUse {
  bool float_type = false;   ///< a float is stored, passed or computed
  bool double_type = false;  ///< a double is stored, passed or computed at run time
  bool arithmetic = false;   ///< + - * / or unary minus on floating operands at run time
  bool rounding = false;     ///< a conversion of a floating value to an integer at run time (gfec_round)
};

/// What the engine of `root` (and of every sub-chart instance it holds) needs. Constants do not
/// count where the engine writes them as float or int literals (a `double` constant converted
/// to a float parameter is written as the float it becomes).
FloatingUse floating_use(const EngineContext &root);

}  // namespace gfec::c_backend
