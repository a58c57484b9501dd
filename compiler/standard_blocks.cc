#include "standard_blocks.h"

#include "parser.h"

#include <algorithm>
#include <set>
#include <string_view>

namespace gfec {

namespace {

// Written as the standard writes them (IEC 61131-3, 2nd edition, 2.5.2.3): a counter counts
// while its value is inside its type's range, which MatIEC replaces with PV and 0 (docs/iec.md
// "Where MatIEC differs"). PV and CV are INT, the chart language's int16. The
// timers are MatIEC's (lib/timer.txt), which write the standard's timing diagrams out: a timer
// reads the time of the tick when it is called (`now()`).
constexpr const char *kText = R"(block R_TRIG {
  in bool CLK;
  out bool Q;
  var bool M;
  Q = CLK && !M;
  M = CLK;
}

block F_TRIG {
  in bool CLK;
  out bool Q;
  var bool M;
  Q = !CLK && !M;
  M = !CLK;
}

block SR {
  in bool S1;
  in bool R;
  out bool Q1;
  Q1 = S1 || (!R && Q1);
}

block RS {
  in bool S;
  in bool R1;
  out bool Q1;
  Q1 = !R1 && (S || Q1);
}

block CTU {
  in bool CU;
  in bool R;
  in int16 PV;
  out bool Q;
  out int16 CV;
  var R_TRIG CU_T;
  CU_T(CLK = CU);
  if (R) {
    CV = 0;
  } else if (CU_T.Q && CV < 32767) {
    CV = CV + 1;
  }
  Q = CV >= PV;
}

block CTD {
  in bool CD;
  in bool LD;
  in int16 PV;
  out bool Q;
  out int16 CV;
  var R_TRIG CD_T;
  CD_T(CLK = CD);
  if (LD) {
    CV = PV;
  } else if (CD_T.Q && CV > -32767 - 1) {
    CV = CV - 1;
  }
  Q = CV <= 0;
}

block CTUD {
  in bool CU;
  in bool CD;
  in bool R;
  in bool LD;
  in int16 PV;
  out bool QU;
  out bool QD;
  out int16 CV;
  var R_TRIG CD_T;
  var R_TRIG CU_T;
  CD_T(CLK = CD);
  CU_T(CLK = CU);
  if (R) {
    CV = 0;
  } else if (LD) {
    CV = PV;
  } else if (!(CU_T.Q && CD_T.Q)) {
    if (CU_T.Q && CV < 32767) {
      CV = CV + 1;
    } else if (CD_T.Q && CV > -32767 - 1) {
      CV = CV - 1;
    }
  }
  QU = CV >= PV;
  QD = CV <= 0;
}

block TP {
  in bool IN;
  in time PT;
  out bool Q;
  out time ET;
  var int STATE;
  var bool PREV_IN;
  var time START_TIME;
  if (STATE == 0 && !PREV_IN && IN) {
    STATE = 1;
    Q = true;
    START_TIME = now();
  } else if (STATE == 1) {
    if (START_TIME + PT <= now()) {
      STATE = 2;
      Q = false;
      ET = PT;
    } else {
      ET = now() - START_TIME;
    }
  }
  if (STATE == 2 && !IN) {
    ET = 0ms;
    STATE = 0;
  }
  PREV_IN = IN;
}

block TON {
  in bool IN;
  in time PT;
  out bool Q;
  out time ET;
  var int STATE;
  var bool PREV_IN;
  var time START_TIME;
  if (STATE == 0 && !PREV_IN && IN) {
    STATE = 1;
    Q = false;
    START_TIME = now();
  } else if (!IN) {
    ET = 0ms;
    Q = false;
    STATE = 0;
  } else if (STATE == 1) {
    if (START_TIME + PT <= now()) {
      STATE = 2;
      Q = true;
      ET = PT;
    } else {
      ET = now() - START_TIME;
    }
  }
  PREV_IN = IN;
}

block TOF {
  in bool IN;
  in time PT;
  out bool Q;
  out time ET;
  var int STATE;
  var bool PREV_IN;
  var time START_TIME;
  if (STATE == 0 && PREV_IN && !IN) {
    STATE = 1;
    START_TIME = now();
  } else if (IN) {
    ET = 0ms;
    STATE = 0;
  } else if (STATE == 1) {
    if (START_TIME + PT <= now()) {
      STATE = 2;
      ET = PT;
    } else {
      ET = now() - START_TIME;
    }
  }
  Q = IN || STATE == 1;
  PREV_IN = IN;
}
)";

constexpr std::string_view kNames[] = {"R_TRIG", "F_TRIG", "SR", "RS", "CTU", "CTD", "CTUD", "TP", "TON", "TOF"};

bool standard_name(std::string_view name) {
  for (std::string_view n : kNames)
    if (n == name) return true;
  return false;
}

}  // namespace

const char *standard_blocks_text() { return kText; }

bool is_standard_block(std::string_view name) { return standard_name(name); }

std::vector<std::string_view> standard_block_names() { return {std::begin(kNames), std::end(kNames)}; }

void add_standard_blocks(ast::Program &program, SourceManager &sources, Diagnostics &diag) {
  std::set<std::string_view> declared;
  bool wanted = false;
  for (const auto &file : program.files) {
    if (!file) continue;
    for (const ast::BlockDecl &b : file->blocks) declared.insert(b.name.text);
  }
  auto want = [&](const std::vector<ast::ValueDecl> &values) {
    for (const ast::ValueDecl &v : values)
      if (!v.is_const && standard_name(v.type.text) && !declared.count(v.type.text)) wanted = true;
  };
  for (const auto &file : program.files) {
    if (!file) continue;
    for (const ast::Chart &c : file->charts) want(c.values);
    for (const ast::BlockDecl &b : file->blocks) want(b.values);
  }
  if (!wanted) return;
  const FileId id = sources.add("<standard blocks>", kText);
  auto file = parse_file(sources, id, diag);
  for (ast::BlockDecl &b : file->blocks) b.standard = !declared.count(b.name.text);
  // A user's block of a standard name replaces the standard one.
  auto &blocks = file->blocks;
  blocks.erase(std::remove_if(blocks.begin(), blocks.end(), [](const ast::BlockDecl &b) { return !b.standard; }),
               blocks.end());
  program.files.push_back(std::move(file));
}

}  // namespace gfec
