// The run viewer: one self-contained HTML page showing a recorded run (docs/viewer.md). The page
// is a fixed template (viewer/page/, its modules assembled at build time) plus the run's data as
// JSON, the recording that RecordingBuilder (recording.h) builds.
#pragma once

#include <nlohmann/json.hpp>

#include <string>
#include <unordered_map>
#include <vector>

namespace gfec::viewer {

/// The template's text (assembled from viewer/page/ by embed_template.cmake).
const std::string &page_template();

/// The page for `data`, a recording as docs/viewer.md describes it ("kind", "rows", "active",
/// ...). The JSON is embedded in a non-executed script element, with every '<' escaped so that
/// no text of the run (an SVG, a call) can close that element.
std::string page(const nlohmann::json &data);

/// Change lists, the compact form of per-tick values the page reads: `[[tick, value], ...]`
/// with an entry only where the value differs from the previous tick's.
class ChangeList {
public:
  void record(long tick, const nlohmann::json &value) {
    if (has_last_ && value == last_) return;
    list_.push_back(nlohmann::json::array({tick, value}));
    last_ = value;
    has_last_ = true;
  }
  const nlohmann::json &json() const { return list_; }
  /// The entries from `tick` on: what a page that holds the ticks before `tick` lacks (a live
  /// page's update, docs/viewer.md "Live mode").
  nlohmann::json since(long tick) const;

private:
  nlohmann::json list_ = nlohmann::json::array();
  nlohmann::json last_;
  bool has_last_ = false;
};

/// Per-tick lists of call texts, stored as change lists of indices into one table of distinct
/// texts: `{"texts": [...], "ticks": [[tick, [i, ...]], ...]}`.
class CallRecorder {
public:
  void record(long tick, const std::vector<std::string> &calls);
  nlohmann::json json() const { return {{"texts", texts_}, {"ticks", changes_.json()}}; }
  /// The ticks from `tick` on and the texts from number `texts_known` on (`texts_from` says
  /// where they go): a live page's update.
  nlohmann::json since(long tick, std::size_t texts_known) const;
  std::size_t texts() const { return texts_.size(); }

private:
  std::vector<std::string> texts_;
  std::unordered_map<std::string, int> index_;
  ChangeList changes_;
};

}  // namespace gfec::viewer
