#include "c_backend.h"

#include "c_context.h"
#include "c_emit.h"

#include <stdexcept>

namespace gfec {

namespace {

class CBackend : public Backend {
public:
  void emit(const model::Model &model, const EmitOptions &options, OutputSink &sink) const override {
    // The pipeline chose the chart (pipeline/compilation.h); none is a bug of the caller.
    if (!model.charts.contains(options.chart)) throw std::invalid_argument("c back end: no chart chosen to compile");
    auto c = c_backend::make_context(model, model.charts[options.chart], options);
    // The header first, in memory: both files carry its fingerprint.
    const std::string body = c_backend::header_body(*c);
    c->fingerprint = c_backend::fingerprint_of(body);
    // engine.c first (the primary output), then engine.h beside it.
    c_backend::emit_source(*c, sink.open(options.output_path));
    c_backend::emit_header(*c, body, sink.open(replace_extension(options.output_path, ".h")));
  }
};

}  // namespace

std::unique_ptr<Backend> make_c_backend() { return std::make_unique<CBackend>(); }

}  // namespace gfec
