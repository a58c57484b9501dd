#include "backend_registry.h"

namespace gfec {

namespace {

struct Entry {
  const char *name;
  std::unique_ptr<Backend> (*make)();
};

// Back ends register here as they land; the driver reports an unknown --emit with this list.
const Entry kBackends[] = {
    {nullptr, nullptr},
};

} // namespace

std::unique_ptr<Backend> make_backend(std::string_view name) {
  for (const auto &e : kBackends)
    if (e.name && name == e.name) return e.make();
  return nullptr;
}

std::vector<std::string> backend_names() {
  std::vector<std::string> names;
  for (const auto &e : kBackends)
    if (e.name) names.emplace_back(e.name);
  return names;
}

} // namespace gfec
