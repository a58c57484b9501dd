// --trace (docs/live.md): the parts of the engine that write each tick's frame. Present only
// with the option: without it the engine is what it was, byte for byte.
#pragma once

#include "c_context.h"
#include "c_form.h"
#include "code_writer.h"

namespace gfec::c_backend {

/// engine.h: the prototype of X_trace_write, which the user defines.
void trace_prototype(CodeWriter &w, const EngineContext &c);
/// The root's struct: the tick count, the frames before the next full one, the last values.
void trace_fields(const EngineContext &c, FieldRows &rows);
/// X_init's part: the count and the last values zero (so the first frame is a full one).
void trace_init(CodeWriter &w, const EngineContext &c);
/// engine.c, after the accessors: the frame's writer and X_run, which ticks and then writes it.
void emit_trace(CodeWriter &w, const EngineContext &c);

}  // namespace gfec::c_backend
