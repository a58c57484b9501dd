// The parts of the engine that depend on its form: the fsm, or an sfc's readable, sequential or
// sparse form (c_layout.h). The forms hold the activation each its own way (a state, the number
// of the one active place, counters with or without a bitset of the active places); one
// FormWriter per form (c_forms.cc) writes every piece of the engine that reads or sets it, so
// that the header and the engine file (c_header.cc, c_source.cc) ask EngineContext::form() instead of
// testing the form in each place. The run function has a writer of its own per form
// (c_run_writer.h): the form only calls it.
#pragma once

#include "c_context.h"
#include "code_writer.h"

#include <string>
#include <utility>
#include <vector>

namespace gfec::c_backend {

/// The state struct's fields as rows of a declaration (`uint8_t av[X_PLACE_COUNT];`) and its
/// comment; the header aligns the comments.
using FieldRows = std::vector<std::pair<std::string, std::string>>;

/// How the accessors read the activation of the int `place`: X_activation returns
/// `(test) ? value : 0u`, and X_instance_activation sets `value` under `if (test)` (MISRA C:2012
/// rule 10.6 forbids the conditional there), so both read every form alike.
struct ActivationRead {
  std::string test;   ///< unbracketed; keeps `place` in range wherever `value` indexes with it
  std::string value;  ///< an unsigned expression
};

class FormWriter {
public:
  virtual ~FormWriter() = default;

  /// The struct's fields that hold the activation (an fsm's status too), first in the struct.
  virtual void fields(const EngineContext &c, FieldRows &rows) const = 0;
  /// X_init's lines that set the initial activation (and an fsm's status).
  virtual void init(CodeWriter &w, const EngineContext &c) const = 0;
  /// The file-local functions that X_init and X_run call, written before X_init, each followed
  /// by a blank line. Only the sparse form has any.
  virtual void helpers(CodeWriter &, const EngineContext &) const {}
  /// `void X_run(X *m) { ... }`, by the form's run writer.
  virtual void run(CodeWriter &w, const EngineContext &c) const = 0;

  /// The activation of the place numbered `place` in the state `obj` (as EngineContext::member() takes it).
  virtual ActivationRead activation(const EngineContext &c, const std::string &obj) const = 0;
  /// EngineContext::active_test, which says what it returns.
  virtual std::string active_test(const EngineContext &c, const std::string &obj, model::PlaceId p,
                                  bool at_start) const = 0;
  /// At most one place is active at a time (an fsm's state, the sequential form's place): a
  /// transition is tried only while its input place is the active one.
  virtual bool one_active() const = 0;

  /// engine.h: the prototypes of X_activation and of the form's own accessors (an fsm's X_state
  /// and X_status), each with its comment.
  virtual void accessor_prototypes(CodeWriter &w, const EngineContext &c) const = 0;
  /// engine.c: the form's own accessors, after X_activation (and X_instance_activation), each
  /// after a blank line.
  virtual void accessors(CodeWriter &, const EngineContext &) const {}
};

}  // namespace gfec::c_backend
