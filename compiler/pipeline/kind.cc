#include "pipeline/kind.h"

#include <fmt/format.h>

#include <vector>

namespace gfec::pipeline {

const char *kind_name(unsigned kind) {
  switch (kind) {
  case kSfc: return "sfc";
  case kFsm: return "fsm";
  case kPlan: return "plan";
  default: return "toolbox";
  }
}

std::string kinds_text(unsigned kinds, const char *last) {
  std::vector<const char *> names;
  for (unsigned k : {kSfc, kFsm, kPlan, kToolbox})
    if (kinds & k) names.push_back(kind_name(k));
  std::string s;
  for (std::size_t i = 0; i < names.size(); ++i)
    s += fmt::format("{}{}", i == 0 ? "" : i + 1 == names.size() ? fmt::format(" {} ", last) : ", ", names[i]);
  return s;
}

}  // namespace gfec::pipeline
