// The parts of the engine, one writer each: the header (c_header.cc), the engine file around the
// run function (c_source.cc), what of both depends on the engine's form (c_form.h, c_forms.cc),
// and the run function of an sfc (c_sfc_run.cc, or c_sfc_scalable.cc in the scalable form) or an
// fsm (c_fsm_run.cc), on the skeleton they share (c_run_writer.h).
#pragma once

#include "c_context.h"
#include "code_writer.h"

#include <iosfwd>
#include <string>

namespace gfec::c_backend {

/// engine.h after its include guard: the types, the API, the hooks and the interface prototypes.
/// Rendered before either file is written: its hash is the fingerprint both files carry.
std::string header_body(const EngineContext &c);
/// 8 hex digits of a 32-bit FNV-1a hash of the header's body.
std::string fingerprint_of(const std::string &body);
/// engine.h: the banner, the guard, the fingerprint's macros and `body`.
void emit_header(const EngineContext &c, const std::string &body, std::ostream &out);
/// engine.c: includes, file-level verbatim code, _init, _run and the accessors.
void emit_source(const EngineContext &c, std::ostream &out);

/// The enumerations of a chart's places and transitions (the root's in engine.h, an instance's
/// in engine.c).
void places_enum(CodeWriter &w, const EngineContext &c);
void transitions_enum(CodeWriter &w, const EngineContext &c);

/// `void X_run(X *m) { ... }`: one tick, docs/language.md §5.1.
void emit_sfc_run(CodeWriter &w, const EngineContext &c);
/// The scalable forms of an sfc (c_layout.h, c_sfc_scalable.cc): the sparse form's file-local
/// helpers (before _init), and the run function of each, one tick exactly as docs/language.md
/// §5.1 says.
void emit_sparse_helpers(CodeWriter &w, const EngineContext &c);
void emit_sequential_run(CodeWriter &w, const EngineContext &c);
void emit_sparse_run(CodeWriter &w, const EngineContext &c);
/// The scalable form's fixed functions, from the templates of c_set_functions.cc: the sets'
/// lowest, next, insert and erase, and the sort of a tick's watched places (`type`: their C type).
/// At file level (indentation 0).
void emit_set_functions(CodeWriter &w, const EngineContext &c);
void emit_sort_function(CodeWriter &w, const EngineContext &c, const char *type);
/// `void X_run(X *m) { ... }`: one tick, docs/language.md §7.
void emit_fsm_run(CodeWriter &w, const EngineContext &c);

/// "LeftFw -> LeftStop", "(A, B) -> C": a transition as the chart would write it.
std::string transition_label(const EngineContext &c, const model::Transition &t);
/// The generated-file comment: names the tool and the chart, never a date.
std::string banner(const EngineContext &c);
/// A preprocessor line, at column 0 whatever the indentation.
void directive(CodeWriter &w, const std::string &text);

}  // namespace gfec::c_backend
