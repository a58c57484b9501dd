#include "backend.h"

#include <fmt/format.h>

#include <memory>
#include <sstream>
#include <stdexcept>

namespace gfec {

std::string replace_extension(const std::string &path, const std::string &ext) {
  auto slash = path.find_last_of('/');
  auto dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return path + ext;
  return path.substr(0, dot) + ext;
}

void OutputSink::filter(const std::string &path, const ExternalTool &tool, const std::string &input) {
  if (!tools_) throw std::runtime_error(fmt::format("{}, and this caller runs no external tools", tool.purpose));
  std::string output = tools_(tool, input);
  open(path) << output;
}

namespace {

class MemorySink : public OutputSink {
public:
  explicit MemorySink(const ToolRunner &tools) : OutputSink(tools) {}
  std::ostream &open(const std::string &path) override {
    finish();
    paths_.push_back(path);
    current_ = std::make_unique<std::ostringstream>();
    return *current_;
  }
  std::vector<OutputFile> take() {
    finish();
    return std::move(files_);
  }

private:
  void finish() {
    if (!current_) return;
    files_.push_back({paths_.back(), current_->str()});
    current_.reset();
  }
  std::vector<std::string> paths_;
  std::unique_ptr<std::ostringstream> current_;
  std::vector<OutputFile> files_;
};

}  // namespace

std::vector<OutputFile> emit_to_memory(const Backend &backend, const model::Model &model, const EmitOptions &options,
                                       const ToolRunner &tools) {
  MemorySink sink(tools);
  backend.emit(model, options, sink);
  return sink.take();
}

std::string base_name(const std::string &path) {
  auto slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

}  // namespace gfec
