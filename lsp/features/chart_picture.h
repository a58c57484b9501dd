// The custom request gfec/chartPicture (docs/editors.md "The chart picture"): gfec's own
// picture of a chart (the SVG back end: the DOT picture drawn by Graphviz's dot) and, for every
// node of it, the source range it was drawn from, so an editor's preview jumps from a node to
// the text and lights the node under the cursor. Node ids are support/chart_nodes.h's.
#pragma once

#include "backend.h"
#include "pipeline/compilation.h"
#include "source_ranges.h"

#include <nlohmann/json.hpp>

#include <string>

namespace gfec::lsp {

/// The elements of the picture of `selection` (a chart or plan of `m`): [{node, kind, name,
/// uri, range}], kind "place" | "state" | "transition" | "chart" (a sub-chart instance's frame)
/// | "actor" | "supervisor" | "plan" (an actor that runs a sub-plan).
nlohmann::json picture_elements(const model::Model &m, const pipeline::Selection &selection, const UriOf &uri_of);

/// The result of gfec/chartPicture for a compilation of the document (`version` is the
/// document's, echoed): {version, svg, note, elements}. `chart` names the chart or plan ("":
/// the file's only candidate, as `gfec FILE` picks it). With errors in the text, or nothing
/// to draw, `svg` is null and `note` says why; `tools` runs dot.
nlohmann::json chart_picture(const pipeline::Compilation &compilation, const std::string &chart,
                             const nlohmann::json &version, const UriOf &uri_of, const ToolRunner &tools);

}  // namespace gfec::lsp
