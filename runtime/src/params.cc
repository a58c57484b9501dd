#include "afp/params.h"

namespace afp {

Formula entry(std::string name) {
  return [name = std::move(name)](const ConfigView& config) { return config.value(name); };
}

}  // namespace afp
