#include "dot_backend.h"

#include "dot_chart.h"
#include "dot_plan.h"

#include <ostream>
#include <stdexcept>

namespace gfec {

namespace {

class DotBackend : public Backend {
public:
  void emit(const model::Model &m, const EmitOptions &o, OutputSink &sink) const override {
    dot_picture(m, o, sink.open(o.output_path));
  }
};

}  // namespace

void dot_picture(const model::Model &m, const EmitOptions &o, std::ostream &out) {
  if (o.chart) dot::chart_picture(m, m.charts.at(o.chart), out);
  else if (o.plan) out << dot::plan_picture(m, m.plans.at(o.plan));
  else throw std::invalid_argument("dot back end: no chart or plan chosen");
}

std::unique_ptr<Backend> make_dot_backend() { return std::make_unique<DotBackend>(); }

}  // namespace gfec
