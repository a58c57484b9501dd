#include "afp/context.h"

#include "services.h"

namespace afp {

ConfigView Context::config() const { return ConfigView(services_->config()); }

Duration Context::now() const { return services_->now(); }

void Context::write(std::string_view entry, const Value& value) {
  // Converting now (not at commit) makes a bad output fail the component that wrote it.
  shadow_->write(entry, convert(value, services_->config().type_of(entry)));
}

}  // namespace afp
