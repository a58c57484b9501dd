#include "diagnostic_kinds.h"

#include <string>

namespace gfec {

namespace {

constexpr DiagnosticKind kKinds[] = {
#define GFEC_ERROR(id, name, summary, help) {name, false, true, summary, help},
#define GFEC_WARNING(id, name, on, summary, help)
#include "diagnostic_kinds.def"
#undef GFEC_ERROR
#undef GFEC_WARNING
#define GFEC_ERROR(id, name, summary, help)
#define GFEC_WARNING(id, name, on, summary, help) {name, true, on, summary, help},
#include "diagnostic_kinds.def"
#undef GFEC_ERROR
#undef GFEC_WARNING
};

constexpr std::size_t kErrors = static_cast<std::size_t>(ErrorKind::Count_);
static_assert(sizeof(kKinds) / sizeof(kKinds[0]) == kErrors + static_cast<std::size_t>(Warning::Count_));

}  // namespace

std::string DiagnosticKind::check() const { return warning ? "-W" + std::string(name) : std::string(name); }

const DiagnosticKind *diagnostic_kinds() { return kKinds; }
std::size_t diagnostic_kind_count() { return sizeof(kKinds) / sizeof(kKinds[0]); }

const DiagnosticKind &kind_info(ErrorKind e) { return kKinds[static_cast<std::size_t>(e)]; }
const DiagnosticKind &kind_info(Warning w) { return kKinds[kErrors + static_cast<std::size_t>(w)]; }

std::optional<Warning> find_warning(std::string_view name) {
  for (std::size_t i = 0; i < static_cast<std::size_t>(Warning::Count_); ++i)
    if (kKinds[kErrors + i].name == name) return static_cast<Warning>(i);
  return std::nullopt;
}

const DiagnosticKind *find_kind(std::string_view name) {
  for (const auto &k : kKinds)
    if (k.name == name) return &k;
  return nullptr;
}

}  // namespace gfec
