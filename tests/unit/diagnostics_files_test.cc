// Diagnostic tests as files (tests/diagnostics/README.md): each case is an input that states every
// diagnostic `gfec --check` must print for it and the exit code: in a comment block at its end
// when its language has line comments (the row's line_comment, compiler/input_languages.h), else
// in a sidecar file beside it (`plan.pml.expected`, as re2c keeps expected stderr beside a test).
// A reviewer reads the input and its expected messages side by side; tools/regen-diagnostics.sh
// rewrites the blocks and sidecars after a deliberate change, for review with `git diff`.
#include "input_languages.h"
#include "support.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <regex>
#include <set>
#include <sstream>

using namespace gfec;
using namespace gfec::test;
namespace fs = std::filesystem;

namespace {

const std::string kExpected = "Expected (tools/regen-diagnostics.sh rewrites this block):";
const std::string kFlags = "gfec-flags:";
/// What a sidecar's name adds to its case's.
const std::string kSidecar = ".expected";

/// One case: its input without the expected block, the expected output and the extra options,
/// from the block (comment syntax `comment`) or the sidecar (comment empty).
struct Case {
  fs::path file;
  std::string comment;  ///< the language's line comment; empty: a sidecar holds the expectation
  std::string body;
  std::string expected;
  std::string flags;
  bool has_sidecar = false;
  fs::path sidecar() const { return file.string() + kSidecar; }
};

/// The lines of `text` that begin with `prefix`, without it, each with a newline.
std::string lines_after(const std::string &text, const std::string &prefix) {
  std::string out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    if (line.rfind(prefix, 0) == 0) out += line.substr(prefix.size()) + "\n";
  return out;
}

Case read_case(const fs::path &file, const InputLanguage &language) {
  Case c;
  c.file = file;
  c.comment = std::string(language.line_comment);
  std::string text = read_file(file.string());
  if (c.comment.empty()) {
    // The sidecar: `gfec-flags:` lines, then the expected output as gfec prints it.
    c.body = text;
    c.has_sidecar = fs::is_regular_file(c.sidecar());
    std::istringstream in(c.has_sidecar ? read_file(c.sidecar().string()) : "");
    for (std::string line; std::getline(in, line);) {
      if (line.rfind(kFlags, 0) == 0) c.flags += " " + line.substr(kFlags.size());
      else c.expected += line + "\n";
    }
    return c;
  }
  const std::string marker = c.comment + " " + kExpected;
  std::size_t at = text.find(marker);
  c.body = at == std::string::npos ? text : text.substr(0, at);
  if (at != std::string::npos) c.expected = lines_after(text.substr(at + marker.size()), c.comment + " ");
  std::istringstream lines(lines_after(c.body, c.comment + " " + kFlags));
  for (std::string line; std::getline(lines, line);) c.flags += " " + line;
  return c;
}

/// Writes what gfec printed as the case's expectation (GFEC_UPDATE_DIAGNOSTICS).
void update_case(const Case &c, const std::string &got) {
  if (c.comment.empty()) {
    std::string text;
    std::istringstream flags(c.flags);
    for (std::string flag; flags >> flag;) text += kFlags + " " + flag + "\n";
    write_file(c.sidecar().string(), text + got);
    return;
  }
  std::string block = c.comment + " " + kExpected + "\n";
  std::istringstream in(got);
  for (std::string line; std::getline(in, line);) block += c.comment + " " + line + "\n";
  std::string body = c.body;
  while (!body.empty() && (body.back() == '\n' || body.back() == ' ')) body.pop_back();
  write_file(c.file.string(), body + "\n\n" + block);
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

/// Every case: the files below tests/diagnostics/ that are main files of an input language (a
/// chart, a plan, an ALICA plan; not an interface or a toolbox the cases import, nor a sidecar).
std::vector<std::pair<fs::path, const InputLanguage *>> cases() {
  std::vector<std::pair<fs::path, const InputLanguage *>> out;
  const fs::path root = fs::path(GFEC_SOURCE_DIR) / "tests" / "diagnostics";
  for (const auto &e : fs::recursive_directory_iterator(root)) {
    if (!e.is_regular_file()) continue;
    const std::string path = e.path().string();
    const InputLanguage &language = input_language_of(path, read_file(path));
    const FileType *type = language.file_type(path);
    if (type && type->main) out.emplace_back(e.path(), &language);
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

TEST_CASE("diagnostics files: every case prints exactly its expected block", "[diagnostics_files]") {
  const bool update = std::getenv("GFEC_UPDATE_DIAGNOSTICS") != nullptr;
  const auto all = cases();
  REQUIRE(all.size() >= 10);
  for (const auto &[file, language] : all) {
    const fs::path rel = fs::relative(file, fs::path(GFEC_SOURCE_DIR));
    DYNAMIC_SECTION(rel.string()) {
      const Case c = read_case(file, *language);
      const std::string got = actual(file, c.flags);
      if (update) {
        update_case(c, got);
        continue;
      }
      INFO("regenerate with tools/regen-diagnostics.sh and review the diff");
      // A language without comments keeps the expectation beside the case: one missing is a
      // case that checks nothing.
      if (c.comment.empty()) {
        INFO(rel.string() << " is " << language->name << ", which has no comments: its expected output belongs in "
                          << fs::relative(c.sidecar(), fs::path(GFEC_SOURCE_DIR)).string());
        CHECK(c.has_sidecar);
      }
      CHECK(got == c.expected);
      // Every case makes gfec say something located, or it tests nothing.
      const bool says_something =
          got.find(": error: ") != std::string::npos || got.find(": warning: ") != std::string::npos;
      CHECK(says_something);
    }
  }
}

TEST_CASE("diagnostics files: each language's cases take their expectation as its row says", "[diagnostics_files]") {
  // Every language with cases here: chart text's are in `//` comments, ALICA's (JSON has none)
  // in sidecars; the comment syntax is the table's, not this runner's.
  std::set<std::string> seen;
  for (const auto &[file, language] : cases()) {
    seen.insert(std::string(language->name));
    const std::string text = read_file(file.string());
    if (language->line_comment.empty()) {
      CHECK(fs::is_regular_file(file.string() + kSidecar));
    } else {
      INFO(file.string());
      CHECK(text.find(std::string(language->line_comment) + " " + kExpected) != std::string::npos);
    }
  }
  CHECK(seen.count("gfec") == 1);
  CHECK(seen.count("alica") == 1);
}
