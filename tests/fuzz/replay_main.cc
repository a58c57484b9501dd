// Replays saved fuzz inputs (files, or every file under a folder) through the fuzz target's
// checks without libFuzzer: the regression test of every crash the fuzzer found, runnable
// with gcc and under the sanitizers (ctest: fuzz_regressions).
#include "fuzz_support.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <vector>

int main(int argc, char **argv) {
  namespace fs = std::filesystem;
  std::vector<fs::path> files;
  bool verbose = false;
  for (int i = 1; i < argc; ++i) {
    fs::path p = argv[i];
    if (p == "-v") {  // print what gfec says about each input
      verbose = true;
      continue;
    }
    if (!fs::exists(p)) continue;  // an empty folder is not kept by git
    if (fs::is_directory(p)) {
      for (const auto &e : fs::recursive_directory_iterator(p))
        if (e.is_regular_file()) files.push_back(e.path());
    } else {
      files.push_back(p);
    }
  }
  std::sort(files.begin(), files.end());
  for (const auto &f : files) {
    std::ifstream in(f, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    std::string said = gfec::fuzz::check_one(text.str());
    if (verbose) std::cout << "== " << f.string() << "\n" << said;
  }
  std::cout << "replayed " << files.size() << " inputs\n";
  return files.empty() ? 1 : 0;
}
