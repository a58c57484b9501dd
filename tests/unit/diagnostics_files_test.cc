// Diagnostic tests as files (tests/diagnostics/README.md): each case is a chart that states, in a
// comment block at its end, every diagnostic `gfec --check` must print for it and the exit code.
// A reviewer reads the chart and its expected messages side by side; tools/regen-diagnostics.sh
// rewrites the blocks after a deliberate change, for review with `git diff`.
#include "support.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <regex>
#include <sstream>

using namespace gfec::test;
namespace fs = std::filesystem;

namespace {

const std::string kMarker = "// Expected (tools/regen-diagnostics.sh rewrites this block):";
const std::string kFlags = "// gfec-flags:";

/// The case's text without its expected block, and the block's lines without their `// `.
struct Case {
  std::string body;
  std::string expected;
  std::string flags;
};

Case read_case(const fs::path &file) {
  Case c;
  std::string text = read_file(file.string());
  std::size_t at = text.find(kMarker);
  c.body = at == std::string::npos ? text : text.substr(0, at);
  if (at != std::string::npos) {
    std::istringstream block(text.substr(at + kMarker.size()));
    std::string line;
    while (std::getline(block, line))
      if (line.rfind("// ", 0) == 0) c.expected += line.substr(3) + "\n";
  }
  std::istringstream lines(c.body);
  std::string line;
  while (std::getline(lines, line))
    if (line.rfind(kFlags, 0) == 0) c.flags += " " + line.substr(kFlags.size());
  return c;
}

/// What gfec says about the case, run in the case's folder so file names stay as written: every
/// located diagnostic line (source lines, carets and gutters left out) and the exit code. The
/// interface most cases share is found on the import path (tests/diagnostics/common/).
std::string actual(const fs::path &file, const std::string &flags) {
  const std::string gfec = std::string(GFEC_BINARY_DIR) + "/gfec";
  auto r = run_command("cd '" + file.parent_path().string() + "' && NO_COLOR=1 '" + gfec + "' --check -I ../common" +
                       flags + " '" + file.filename().string() + "' 2>&1");
  static const std::regex located(R"(^[^ :][^:]*:[0-9]+:[0-9]+: (error|warning|note): .*)");
  std::string out;
  std::istringstream in(r.out);
  std::string line;
  while (std::getline(in, line))
    if (std::regex_match(line, located)) out += line + "\n";
  out += "exit " + std::to_string(r.exit_code) + "\n";
  return out;
}

std::vector<fs::path> cases() {
  std::vector<fs::path> out;
  const fs::path root = fs::path(GFEC_SOURCE_DIR) / "tests" / "diagnostics";
  for (const auto &e : fs::recursive_directory_iterator(root)) {
    const std::string ext = e.path().extension().string();
    if (e.is_regular_file() && (ext == ".sfc" || ext == ".fsm" || ext == ".plan" || ext == ".test"))
      out.push_back(e.path());
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

TEST_CASE("diagnostics files: every case prints exactly its expected block", "[diagnostics_files]") {
  const bool update = std::getenv("GFEC_UPDATE_DIAGNOSTICS") != nullptr;
  const auto all = cases();
  REQUIRE(all.size() >= 10);
  for (const auto &file : all) {
    const fs::path rel = fs::relative(file, fs::path(GFEC_SOURCE_DIR));
    DYNAMIC_SECTION(rel.string()) {
      Case c = read_case(file);
      const std::string got = actual(file, c.flags);
      if (update) {
        std::string block = kMarker + "\n";
        std::istringstream in(got);
        std::string line;
        while (std::getline(in, line)) block += "// " + line + "\n";
        std::string body = c.body;
        while (!body.empty() && (body.back() == '\n' || body.back() == ' ')) body.pop_back();
        write_file(file.string(), body + "\n\n" + block);
        continue;
      }
      INFO("regenerate with tools/regen-diagnostics.sh and review the diff");
      CHECK(got == c.expected);
      // Every case makes gfec say something located, or it tests nothing.
      const bool says_something =
          got.find(": error: ") != std::string::npos || got.find(": warning: ") != std::string::npos;
      CHECK(says_something);
    }
  }
}
