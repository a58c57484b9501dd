#include "viewer_page.h"

#include <algorithm>
#include <stdexcept>

namespace gfec::viewer {

namespace {
constexpr const char *kPlaceholder = "/*GFEC_RUN_DATA*/";
}

std::string page(const nlohmann::json &data) {
  const std::string json = data.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  std::string safe;
  safe.reserve(json.size() + json.size() / 50);
  // '<' occurs only inside JSON strings, where \u003c means the same character.
  for (char c : json) {
    if (c == '<') safe += "\\u003c";
    else safe += c;
  }
  const std::string &t = page_template();
  const std::size_t at = t.find(kPlaceholder);
  if (at == std::string::npos) throw std::logic_error("the viewer template has no data placeholder");
  return t.substr(0, at) + safe + t.substr(at + std::string(kPlaceholder).size());
}

void CallRecorder::record(long tick, const std::vector<std::string> &calls) {
  nlohmann::json ids = nlohmann::json::array();
  for (const std::string &c : calls) {
    auto [it, added] = index_.emplace(c, static_cast<int>(texts_.size()));
    if (added) texts_.push_back(c);
    ids.push_back(it->second);
  }
  changes_.record(tick, ids);
}

nlohmann::json ChangeList::since(long tick) const {
  // Entries are in tick order: the first at or after `tick` by bisection.
  std::size_t lo = 0, hi = list_.size();
  while (lo < hi) {
    const std::size_t mid = (lo + hi) / 2;
    if (list_[mid][0].get<long>() < tick) lo = mid + 1;
    else hi = mid;
  }
  nlohmann::json out = nlohmann::json::array();
  for (std::size_t i = lo; i < list_.size(); ++i) out.push_back(list_[i]);
  return out;
}

nlohmann::json CallRecorder::since(long tick, std::size_t texts_known) const {
  const std::size_t from = std::min(texts_known, texts_.size());
  return {{"texts_from", from},
          {"texts", std::vector<std::string>(texts_.begin() + static_cast<std::ptrdiff_t>(from), texts_.end())},
          {"ticks", changes_.since(tick)}};
}

}  // namespace gfec::viewer
