#include "runnable_chart.h"

#include "diagnostic_report.h"
#include "driver.h"

namespace gfec {

RunnableChart load_runnable_chart(const Options &options, const std::string &input, const std::string &chart_name,
                                  const char *verb, DiagnosticReport &report) {
  RunnableChart r;
  pipeline::FrontEndOptions f = front_end_options(options);
  f.analyze = false;
  r.compilation = std::make_unique<pipeline::Compilation>(f);
  pipeline::Compilation &c = *r.compilation;
  c.front_end(input);
  if (c.unreadable()) {
    report.tool_error(input, c.cannot_read_main(input), false);
    r.exit_code = kExitUsageOrIo;
    return r;
  }
  report.add(input, c.diag, c.sources);
  if (c.diag.has_errors()) {
    r.exit_code = kExitInputError;
    return r;
  }
  pipeline::SelectionRequest request;
  request.name = chart_name;
  request.among = pipeline::kSfc | pipeline::kFsm;
  request.verb = verb;
  const pipeline::Selection target = pipeline::choose(c.model, request);
  if (!target.chosen()) {
    report.tool_error(input, target.error, true);
    r.exit_code = kExitUsageOrIo;
    return r;
  }
  r.chart = target.chart;
  return r;
}

}  // namespace gfec
