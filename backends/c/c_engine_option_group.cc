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
    app.add_flag("--trace", options_->trace,
                 "C engine: after each tick, one frame of the activation through X_trace_write(), the user's, for "
                 "'gfec monitor' (docs/live.md)");
    full_every_option_ =
        app.add_option(
               "--trace-full-every", full_every_,
               "C engine, --trace: a full frame at least every N ticks, the others carry changes (default 32; 1: "
               "every frame full)")
            ->type_name("N");
  }

  std::string check() override {
    if (full_every_option_ != nullptr && full_every_option_->count() > 0) {
      if (!options_->trace) return "--trace-full-every needs --trace";
      if (full_every_ < 1 || full_every_ > 65535)
        return fmt::format("--trace-full-every {}: the number of ticks must be 1 ... 65535", full_every_);
      options_->trace_full_every = static_cast<unsigned>(full_every_);
    }
    if (type_.empty() && !context_) return {};
    if (type_.empty()) type_ = "void *";
    naming::CTypeName type;
    if (std::string why = naming::read_c_type_name(type_, type); !why.empty())
      return fmt::format("--context-type '{}': {}", type_, why);
    options_->context_type = type.spelling;
    return {};
  }

  std::string given() const override {
    return !options_->context_type.empty() ? "--context"
           : options_->names               ? "--names"
           : options_->trace               ? "--trace"
                                           : "";
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
  long long full_every_ = 0;
  CLI::Option *full_every_option_ = nullptr;
  std::shared_ptr<CEngineOptions> options_ = std::make_shared<CEngineOptions>();
};

}  // namespace

std::unique_ptr<BackendOptionGroup> make_c_engine_option_group() { return std::make_unique<CEngineOptionGroup>(); }

}  // namespace gfec::c_backend
