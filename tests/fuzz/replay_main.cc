// Replays saved fuzz inputs (files, or every file under a folder) through the fuzz target's
// checks without libFuzzer: the regression test of every crash the fuzzer found, runnable
// with gcc and under the sanitizers (ctest: fuzz_regressions).
//
// With --lsp the inputs are language server sessions (lsp_session.h), and --random N plays N
// pseudo-random sessions of edits and requests over each input as the document besides
// (ctest: fuzz_lsp_sessions): the short run of the server's fuzzing that CI can afford.
//
// With --mutate N each input is also checked in N pseudo-random mutations (cut short, spans
// deleted or repeated, bytes replaced): the inputs of a language the libFuzzer target does not
// read (IEC structured text and PLCopen XML, by the file's extension; ctest: fuzz_iec_st,
// fuzz_plcopen).
#include "fuzz_support.h"
#include "lsp_session.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <vector>

int main(int argc, char **argv) {
  namespace fs = std::filesystem;
  std::vector<fs::path> files;
  bool verbose = false, lsp = false;
  unsigned random_sessions = 0, mutations = 0;
  for (int i = 1; i < argc; ++i) {
    fs::path p = argv[i];
    if (p == "-v") {  // print what gfec says about each input
      verbose = true;
      continue;
    }
    if (p == "--lsp") {
      lsp = true;
      continue;
    }
    if (p == "--mutate" && i + 1 < argc) {
      mutations = static_cast<unsigned>(std::stoul(argv[++i]));
      continue;
    }
    if (p == "--random" && i + 1 < argc) {
      random_sessions = static_cast<unsigned>(std::stoul(argv[++i]));
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
    if (lsp) {
      if (verbose) std::cout << "== " << f.string() << "\n";
      gfec::fuzz::check_lsp_session(text.str());
      for (unsigned seed = 1; seed <= random_sessions; ++seed)
        gfec::fuzz::check_lsp_session(gfec::fuzz::random_lsp_session(text.str(), seed));
      continue;
    }
    const std::string name = "fuzz" + f.extension().string();
    std::string said = gfec::fuzz::check_one(text.str(), name);
    if (verbose) std::cout << "== " << f.string() << "\n" << said;
    for (unsigned seed = 1; seed <= mutations; ++seed)
      gfec::fuzz::check_one(gfec::fuzz::mutate(text.str(), seed), name);
  }
  if (lsp) std::cout << "played " << files.size() * (1 + random_sessions) << " language server sessions\n";
  else std::cout << "replayed " << files.size() << " inputs\n";
  return files.empty() ? 1 : 0;
}
