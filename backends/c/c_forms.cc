// The four engine forms (c_form.h), and EngineContext::form(), the one place that picks among them.
#include "c_emit.h"
#include "c_form.h"

#include <fmt/format.h>

namespace gfec::c_backend {

namespace {

using model::PlaceId;

/// docs/language.md §7: the state is one field, the status another.
class FsmForm final : public FormWriter {
public:
  void fields(const EngineContext &c, FieldRows &rows) const override {
    rows.emplace_back(fmt::format("{} {};", c.place_type, c.state),
                      fmt::format("the current state, a {}_<state>", c.type));
    rows.emplace_back(fmt::format("int {};", c.status), "0 running, 1 succeeded, -1 failed");
  }

  void init(CodeWriter &w, const EngineContext &c) const override {
    for (PlaceId p : c.chart.places.ids())
      if (c.place(p).initial) {
        w.line("{} = {};", c.field(c.state), c.place_const[p]);
        auto terminal = c.place(p).terminal;
        w.line("{} = {};", c.field(c.status),
               terminal == model::Terminal::Success   ? 1
               : terminal == model::Terminal::Failure ? -1
                                                      : 0);
      }
  }

  void run(CodeWriter &w, const EngineContext &c) const override { emit_fsm_run(w, c); }

  ActivationRead activation(const EngineContext &c, const std::string &obj) const override {
    return {fmt::format("(int){} == place", c.member(obj, c.state)), "1u"};
  }

  std::string active_test(const EngineContext &c, const std::string &obj, PlaceId p, bool) const override {
    return fmt::format("{} == {}", c.member(obj, c.state), c.place_const.at(p));
  }

  bool one_active() const override { return true; }

  void accessor_prototypes(CodeWriter &w, const EngineContext &c) const override {
    const std::string &t = c.type;
    w.line("/* 1 if `place` is the current state, else 0. */");
    w.line("uint32_t {0}_activation(const {0} *m, int place);", t);
    w.line("/* The current state's number, a {}_<state> (an int, as the language's C API has it). */", t);
    w.line("int {0}_state(const {0} *m);", t);
    w.line("/* 0 while running, 1 once in a success state, -1 once in a failure state. */");
    w.line("int {0}_status(const {0} *m);", t);
  }

  void accessors(CodeWriter &w, const EngineContext &c) const override {
    const std::string &t = c.type, &m = c.self;
    w.blank();
    w.line("int {0}_state(const {0} *{1})", t, m);
    {
      auto body = w.block("{");
      w.line("return (int){};", c.field(c.state));
    }
    w.blank();
    w.line("int {0}_status(const {0} *{1})", t, m);
    auto body = w.block("{");
    w.line("return {};", c.field(c.status));
  }
};

/// What the sfc forms share: X_activation is the place's activation counter in every one (0 or 1
/// in the sequential form), as GFE's API has it.
class SfcForm : public FormWriter {
public:
  void accessor_prototypes(CodeWriter &w, const EngineContext &c) const override {
    const std::string &t = c.type;
    w.line("/* The activation counter of a place (a {}_<place>); 0 for a number out of range. */", t);
    w.line("uint32_t {0}_activation(const {0} *m, int place);", t);
  }

protected:
  /// `place` numbers a place of `c`.
  static std::string in_range(const EngineContext &c) {
    return fmt::format("(place >= 0) && (place < (int){})", c.place_count);
  }
};

/// The scalable form of a chart whose one place is always active: its number is the state.
class SequentialForm final : public SfcForm {
public:
  void fields(const EngineContext &c, FieldRows &rows) const override {
    rows.emplace_back(fmt::format("{} {};", uint_type(c.layout.index_bits), c.current),
                      fmt::format("the one active place, a {}_<place>", c.type));
  }

  void init(CodeWriter &w, const EngineContext &c) const override {
    for (PlaceId p : c.chart.places.ids())
      if (c.place(p).initial) w.line("{} = {};", c.field(c.current), c.place_const[p]);
  }

  void run(CodeWriter &w, const EngineContext &c) const override { emit_sequential_run(w, c); }

  ActivationRead activation(const EngineContext &c, const std::string &obj) const override {
    return {fmt::format("{} && ((int){} == place)", in_range(c), c.member(obj, c.current)), "1u"};
  }

  std::string active_test(const EngineContext &c, const std::string &obj, PlaceId p, bool) const override {
    return fmt::format("{} == {}", c.member(obj, c.current), c.place_const.at(p));
  }

  bool one_active() const override { return true; }
};

/// The forms with an activation counter per place (the readable and the sparse form).
class CounterForm : public SfcForm {
public:
  ActivationRead activation(const EngineContext &c, const std::string &obj) const override {
    return {in_range(c), c.member(obj, c.av) + "[place]"};
  }

  std::string active_test(const EngineContext &c, const std::string &obj, PlaceId p, bool at_start) const override {
    // In a condition the counters serve as `avail` and decrease: a place some transition consumes
    // is read from the snapshot of the start of the tick.
    const std::string &k = c.place_const.at(p);
    if (at_start && obj.empty() && c.is_input.at(p)) return at_start_test(c, k);
    return fmt::format("{}[{}] != 0u", c.member(obj, c.av), k);
  }

  bool one_active() const override { return false; }

protected:
  /// Place `k` (its constant) was active at the start of the tick, as the run function keeps it.
  virtual std::string at_start_test(const EngineContext &c, const std::string &k) const {
    return fmt::format("{}[{}] != 0u", c.before, k);
  }
};

/// GFE's form: every tick visits every place and transition.
class ReadableForm final : public CounterForm {
public:
  void fields(const EngineContext &c, FieldRows &rows) const override {
    rows.emplace_back(fmt::format("{} {}[{}];", c.readable_counter(), c.av, c.count_text()),
                      c.layout.activation.bounded
                          ? fmt::format("activation counter of each place (never above {})", c.layout.activation.place)
                          : "activation counter of each place");
  }

  void init(CodeWriter &w, const EngineContext &c) const override {
    for (PlaceId p : c.chart.places.ids()) w.line("{} = {};", c.av_of(p), c.place(p).initial ? 1 : 0);
  }

  void run(CodeWriter &w, const EngineContext &c) const override { emit_sfc_run(w, c); }
};

/// The scalable form of any other chart: counters, and the active places as bits with summary
/// levels, which file-local helpers search and change.
class SparseForm final : public CounterForm {
public:
  void fields(const EngineContext &c, FieldRows &rows) const override {
    const Layout &l = c.layout;
    rows.emplace_back(fmt::format("{} {}[{}];", uint_type(l.counter_bits), c.av, c.count_text()),
                      l.activation.bounded
                          ? fmt::format("activation counter of each place (never above {})", l.activation.place)
                          : "activation counter of each place (saturates)");
    rows.emplace_back(fmt::format("uint32_t {}[{}];", c.active, l.active.words()),
                      "the active places: bits, and summary levels of them");
    if (!l.place_driven)
      rows.emplace_back(fmt::format("uint32_t {}[{}];", c.candidates, l.candidates.words()),
                        "the transitions to try in a tick (empty between ticks)");
  }

  void init(CodeWriter &w, const EngineContext &c) const override {
    // Loops rather than a line per place: a large chart has few initial places.
    w.line("uint32_t {};", c.index);
    {
      auto each = w.block(fmt::format("for ({0} = 0; {0} < (uint32_t){1}; ++{0}) {{", c.index, c.place_count));
      w.line("{}[{}] = 0;", c.field(c.av), c.index);
    }
    auto clear = [&](const std::string &field, std::uint32_t words) {
      auto each = w.block(fmt::format("for ({0} = 0; {0} < {1}u; ++{0}) {{", c.index, words));
      w.line("{}[{}] = 0u;", c.field(field), c.index);
    };
    clear(c.active, c.layout.active.words());
    if (!c.layout.place_driven) clear(c.candidates, c.layout.candidates.words());
    for (PlaceId p : c.chart.places.ids())
      if (c.place(p).initial) {
        w.line("{} = 1;", c.av_of(p));
        w.line("{}({}, {}, {}u, {});", c.insert_fn, c.field(c.active), c.active_levels, c.layout.active.levels(),
               c.place_const[p]);
      }
  }

  void helpers(CodeWriter &w, const EngineContext &c) const override {
    emit_sparse_helpers(w, c);
    w.blank();
  }

  void run(CodeWriter &w, const EngineContext &c) const override { emit_sparse_run(w, c); }

protected:
  /// The snapshot is a bitset here: the constant as a number in the bit arithmetic (MISRA C:2012
  /// rule 10.1).
  std::string at_start_test(const EngineContext &c, const std::string &k) const override {
    return fmt::format("(({0}[(uint32_t){1} >> 5] >> ((uint32_t){1} & 31u)) & 1u) != 0u", c.before, k);
  }
};

}  // namespace

const FormWriter &EngineContext::form() const {
  static const FsmForm fsm_form;
  static const ReadableForm readable_form;
  static const SequentialForm sequential_form;
  static const SparseForm sparse_form;
  if (fsm) return fsm_form;
  switch (layout.form) {
  case Layout::Form::Sequential: return sequential_form;
  case Layout::Form::Sparse: return sparse_form;
  case Layout::Form::Readable: break;
  }
  return readable_form;
}

}  // namespace gfec::c_backend
