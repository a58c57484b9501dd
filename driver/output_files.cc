#include "output_files.h"

#include "safe_output.h"

namespace gfec {

std::string write_atomically(const std::vector<OutputFile> &files, const std::vector<std::string> &inputs) {
  std::vector<safe_output::File> set;
  set.reserve(files.size());
  for (const auto &f : files) set.push_back({f.path, f.contents});
  return safe_output::write_all(set, inputs);
}

}  // namespace gfec
