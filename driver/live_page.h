// `gfec monitor CHART --http HOST:PORT` (docs/live.md "The live page"): the chart as the live page
// shows it, from the compiled model, and the server that shows it while the monitor reads.
#pragma once

#include "live_recording.h"
#include "model.h"
#include "plan_trace_format.h"
#include "recording.h"

#include <functional>
#include <iosfwd>
#include <string>

namespace gfec {

/// Chart `c` and the charts its places run, depth first, as the recording builder reads them
/// (gfec run --html and the live page: the rows in the order of gfec run's `av` lines).
viewer::ChartOutline chart_outline(const model::Model &model, model::ChartId c);

/// Chart `c`'s picture (the svg back end): {svg, ""}, or {"", why there is none}. A chart too
/// large to draw in time throws ToolTimeLimit (driver/external_tool.h): an error, not a page
/// without a picture.
std::pair<std::string, std::string> chart_picture(const model::Model &model, model::ChartId c,
                                                  const std::string &input);

/// What the live page shows of chart `c` before a tick arrives: rows, instances, picture, period.
/// `source` names the stream ("stdin", "tcp 127.0.0.1:5000").
live::LiveChart live_chart(const model::Model &model, model::ChartId c, const std::string &input, std::string source);

/// What the live page shows of plan `p` (docs/live.md "Plans on the live page"): its actors' rows
/// (node "aN" in its picture), then each sub-plan level's actors, grouped by the level's path, in
/// the trace's level order (`layout`); the picture; the node of each of its supervisors.
live::LiveChart live_plan(const model::Model &model, const trace::PlanLayout &layout, const std::string &input,
                          std::string source);

/// The monitor's --http: serves `recording`'s page on `address` ("127.0.0.1:8080", port 0: a free
/// one; a non-loopback host only with `allow_remote`), prints the page's address to `err`, runs
/// `read_stream` (the monitor's reading loop, which feeds `recording`), then serves the page of
/// the ended run until the process is stopped (Ctrl-C). Returns 2 when it cannot listen.
int serve_live_page(live::LiveRecording &recording, const std::string &address, bool allow_remote,
                    const std::function<void()> &read_stream, std::ostream &err);

}  // namespace gfec
