// What the validator's tests share: an interface and a toolbox their charts import, and a run of
// the front end and validator over in-memory files.
#pragma once

#include "support.h"
#include "validate.h"

#include <initializer_list>
#include <string>
#include <utility>

namespace gfec::test {

/// Imported as "bot.iface": a function of every kind the charts call.
inline const char *const kBot = R"--(interface Bot {
  bool Black();
  bool White();
  void Go();
  void Stop();
  void Motor(int side, float speed);
  void Lamp(bool on);
  float Distance();
  int Count();
}
)--";

/// Imported as "carbot.toolbox" by the plans: every kind of template and parameter.
inline const char *const kToolbox = R"--(toolbox Carbot {
  actor Forward(in float distance) -> FORWARD_OK;
  actor Turn(in float angle) -> TURN_OK;
  actor SearchWall(out float angle) -> WALL_FOUND | NO_WALL_FOUND;
  actor Say(in string text, in bool loud) -> SAID;
  computation CountDown(in int n, out int rest) -> AGAIN | DONE;
  supervisor CheckTouch() events TOUCHED;
  supervisor CheckLane(in float dist) events LANE_NOT_FREE period 10ms;
}
)--";

/// Loads in-memory files (the first is the main file) and validates them.
struct Validated {
  FrontEnd fe;
  model::Model model;

  Validated(std::initializer_list<std::pair<std::string, std::string>> files, WarningOptions w = {}) : fe(files, w) {
    model = validate(fe.loaded.program, fe.sources, fe.diag);
  }
  std::string text() const { return fe.text(); }
};

}  // namespace gfec::test
