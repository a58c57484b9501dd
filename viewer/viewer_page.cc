#include "viewer_page.h"

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

}  // namespace gfec::viewer
