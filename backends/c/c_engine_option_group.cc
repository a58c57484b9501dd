#include "c_engine_options.h"

#include "naming/c_type_name.h"
#include "validate.h"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

namespace gfec::c_backend {

namespace {

class CEngineOptionGroup : public BackendOptionGroup {
public:
  void add_to(CLI::App &app) override {
    app.add_flag("--context", context_,
                 "C engine: every interface function takes the instance's context (void *) as its first argument, "
                 "set by X_set_context (docs/c-engine.md \"Instance context\")");
    app.add_option("--context-type", type_,
                   "C engine: the context's C type, e.g. 'struct motor *' (implies --context; default void *)")
        ->type_name("TYPE");
    app.add_flag("--names", options_->names,
                 "C engine: X_place_name() and X_transition_name(), the declared names for logging and tracing");
  }

  std::string check() override {
    if (type_.empty() && !context_) return {};
    if (type_.empty()) type_ = "void *";
    naming::CTypeName type;
    if (std::string why = naming::read_c_type_name(type_, type); !why.empty())
      return fmt::format("--context-type '{}': {}", type_, why);
    options_->context_type = type.spelling;
    return {};
  }

  std::string given() const override {
    return !options_->context_type.empty() ? "--context" : options_->names ? "--names" : "";
  }

  const char *owner() const override { return "the C engine"; }

  void check_selection(const model::Model &m, const pipeline::Selection &s, Diagnostics &diag) const override {
    // An option that changes the engine's prototypes: a warning the validator cannot give.
    if (!options_->context_type.empty() && (s.kind & pipeline::kCharts)) check_context_prototypes(m, s.chart, diag);
  }

  std::shared_ptr<const BackendOptions> options() const override { return options_; }

private:
  bool context_ = false;
  std::string type_;
  std::shared_ptr<CEngineOptions> options_ = std::make_shared<CEngineOptions>();
};

}  // namespace

std::unique_ptr<BackendOptionGroup> make_c_engine_option_group() { return std::make_unique<CEngineOptionGroup>(); }

}  // namespace gfec::c_backend
