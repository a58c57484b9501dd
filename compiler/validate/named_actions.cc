// Named actions and the associations that hold them (docs/language.md §14, docs/iec.md "Action
// control"): every name resolved, every qualifier with or without its duration as it must be,
// every body checked, and one duration per action for SD and for SL, whose timer is the action's.
#include "did_you_mean.h"
#include "validate/expr.h"
#include "validate/families.h"

#include <fmt/format.h>

#include <map>
#include <optional>
#include <string_view>
#include <utility>

namespace gfec::validation {

namespace {

/// The qualifiers that take a duration (docs/iec.md).
bool timed(std::string_view q) {
  std::optional<model::Qualifier> named = model::qualifier_named(q);
  return named && model::is_timed(*named);
}

}  // namespace

void check_named_actions(Context &cx, ChartScope &s) {
  std::map<std::string_view, const ast::ActionDecl *> actions;
  for (const ast::ActionDecl &a : s.ast.actions) {
    auto [at, fresh] = actions.emplace(a.name.text, &a);
    if (!fresh)
      cx.diag.error(a.name.range, ErrorKind::DuplicateName, fmt::format("action '{}' declared twice", a.name.text))
          .note(at->second->name.range, "the first declaration is here");
  }
  std::map<std::pair<std::string_view, model::Qualifier>, const ast::Association *> timer_durations;
  for (const ast::Place &p : s.ast.places) {
    if (!p.extras) continue;
    for (const ast::Association &as : p.extras->associations) {
      if (!actions.count(as.action.text)) {
        auto &d =
            cx.diag.error(as.action.range, ErrorKind::UnknownName, fmt::format("unknown action '{}'", as.action.text));
        NearestName nearest(as.action.text, as.action.text.size() / 3 + 1);
        std::string_view best;
        for (const auto &[name, decl] : actions)
          if (nearest.offer(name)) best = name;
        if (nearest.found()) d.note(actions.at(best)->name.range, fmt::format("did you mean '{}'?", best));
      }
      const bool needs = timed(as.qualifier.text);
      if (needs && !as.duration_ms)
        cx.diag.error(as.range, ErrorKind::QualifierTime,
                      fmt::format("qualifier '{}' needs a duration: '{} {} 2s;'", as.qualifier.text, as.qualifier.text,
                                  as.action.text));
      if (needs && as.duration_ms && !s.is_fsm()) {
        ExprScope at{cx, &s, false};
        require_period(at, as.duration_range, fmt::format("qualifier '{}'", as.qualifier.text));
      }
      if (!needs && as.duration_ms)
        cx.diag.error(as.duration_range, ErrorKind::QualifierTime,
                      fmt::format("qualifier '{}' takes no duration; only L, D, SD, DS and SL do", as.qualifier.text));
      if (s.is_fsm())
        cx.diag.error(as.range, ErrorKind::NotSupported,
                      "an fsm state holds no named actions; they are an sfc's (IEC 61131-3 steps)");
      // SD and SL time the action's own flag from its set: one timer per action and qualifier,
      // so one duration (docs/iec.md "Action control").
      std::optional<model::Qualifier> q = model::qualifier_named(as.qualifier.text);
      if (q && (*q == model::Qualifier::SD || *q == model::Qualifier::SL) && as.duration_ms) {
        auto [first, fresh] = timer_durations.emplace(std::make_pair(as.action.text, *q), &as);
        if (!fresh && *first->second->duration_ms != *as.duration_ms)
          cx.diag
              .error(as.duration_range, ErrorKind::QualifierTime,
                     fmt::format("action '{}' is held under {} for {}ms here and for {}ms before; its {} timer is the "
                                 "action's, so every {} association of it takes one duration",
                                 as.action.text, as.qualifier.text, *as.duration_ms, *first->second->duration_ms,
                                 as.qualifier.text, as.qualifier.text))
              .note(first->second->duration_range, "the other duration is here");
      }
    }
  }
  // The model's actions table: each action once (a duplicate is an error above), with every
  // association that holds it, in place order, for the back ends' action control.
  ExprScope scope{cx, &s, false};
  std::map<std::string_view, model::ActionId> ids;
  for (ast::ActionDecl &a : s.ast.actions) {
    std::vector<model::Stmt> body = lower_block(a.body, scope);  // its errors, as a place's body would have them
    if (ids.emplace(a.name.text, model::ActionId(s.out.actions.size())).second) {
      model::Action out;
      out.name = a.name.text;
      out.body = std::move(body);
      out.range = a.range;
      out.name_range = a.name.range;
      s.out.actions.push_back(std::move(out));
    }
  }
  for (std::size_t i = 0; i < s.ast.places.size(); ++i) {
    const ast::Place &p = s.ast.places[i];
    if (!p.extras) continue;
    for (const ast::Association &as : p.extras->associations) {
      auto id = ids.find(as.action.text);
      std::optional<model::Qualifier> q = model::qualifier_named(as.qualifier.text);
      if (id == ids.end() || !q) continue;
      model::Association out;
      out.place = model::PlaceId(i);
      out.qualifier = *q;
      out.duration_ms = as.duration_ms.value_or(0);
      out.ticks = as.duration_ms ? to_ticks(*as.duration_ms, s.out.period_ms) : 0;
      out.range = as.range;
      // L, D and DS read the place's timer, as elapsed() does.
      if (*q == model::Qualifier::L || *q == model::Qualifier::D || *q == model::Qualifier::DS)
        s.out.places[out.place].timed = true;
      s.out.actions[id->second].associations.push_back(out);
    }
  }
  // An action no place holds never runs (its flags stay false): most likely a forgotten
  // association, as an unused chart is a forgotten `runs`.
  for (const model::Action &a : s.out.actions)
    if (a.associations.empty())
      cx.diag.warning(Warning::UnusedAction, a.name_range,
                      fmt::format("action '{}' is held by no place: its body never runs", a.name));
}

}  // namespace gfec::validation
