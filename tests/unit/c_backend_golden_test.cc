// Golden tests of the C back end: every chart under tests/golden/c (*.sfc, *.fsm, with the files
// it imports beside it) goes through the real front end and the back end in memory, and the
// engine must equal <case>.c and <case>.h byte for byte. <case>.flags holds gfec options for a
// case (--no-line-directives and --engine= matter here). tools/regen-golden.sh c rewrites the expected
// files with the real gfec; a reviewer reads the diff (tests/README.md).
#include "../run/c_backend_support.h"
#include "support.h"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdlib>

using namespace cbt;
using gfec::test::first_difference;

namespace {

const fs::path kGoldenDir = fs::path(GFEC_SOURCE_DIR) / "tests" / "golden" / "c";

/// Every file of the golden folder that a chart may import or be: name -> text.
std::map<std::string, std::string> chart_files() {
  std::map<std::string, std::string> files;
  for (const auto &entry : fs::directory_iterator(kGoldenDir)) {
    auto ext = entry.path().extension();
    if (ext == ".sfc" || ext == ".fsm" || ext == ".iface")
      files[entry.path().filename().string()] = read_file(entry.path());
  }
  return files;
}

std::vector<std::string> cases(const std::map<std::string, std::string> &files) {
  std::vector<std::string> names;
  for (const auto &[name, text] : files) {
    auto ext = fs::path(name).extension();
    if (ext == ".sfc" || ext == ".fsm") names.push_back(name);
  }
  return names;  // std::map keeps them sorted
}

/// Compares `actual` with the golden file; GFEC_UPDATE_GOLDEN=1 writes it instead.
void check_golden(const std::string &name, const std::string &actual) {
  fs::path golden = kGoldenDir / name;
  if (const char *update = std::getenv("GFEC_UPDATE_GOLDEN"); update && std::string(update) == "1") {
    write_file(golden, actual);
    WARN("updated " << golden.string());
    return;
  }
  REQUIRE(fs::exists(golden));
  std::string expected = read_file(golden);
  if (expected == actual) return;
  fs::path out = fs::path(GFEC_BINARY_DIR) / "test-scratch" / "golden" / "c" / name;
  write_file(out, actual);
  FAIL_CHECK("tests/golden/c/" << name << " differs from what the back end writes now; "
                               << first_difference(expected, actual) << "\nsee: diff -u " << golden.string() << " "
                               << out.string() << "\naccept (after reading the diff): tools/regen-golden.sh c");
}

/// The case's gfec options from <case>.flags: whether it wants #line directives, which form.
struct CaseFlags {
  bool line_directives = true;
  EngineForm engine = EngineForm::Auto;
  std::string context_type;  ///< --context: void *
  bool names = false;        ///< --names
};
CaseFlags flags_for(const std::string &stem) {
  CaseFlags f;
  fs::path flags = kGoldenDir / (stem + ".flags");
  if (!fs::exists(flags)) return f;
  std::istringstream in(read_file(flags));
  for (std::string flag; in >> flag;) {
    INFO(flags.string() << ": only --no-line-directives, --engine=readable|scalable, --context and --names are "
                           "understood here");
    if (flag == "--context") {
      f.context_type = "void *";
    } else if (flag == "--names") {
      f.names = true;
    } else if (flag == "--engine=scalable") {
      f.engine = EngineForm::Scalable;
    } else if (flag == "--engine=readable") {
      f.engine = EngineForm::Readable;
    } else {
      REQUIRE(flag == "--no-line-directives");
      f.line_directives = false;
    }
  }
  return f;
}

}  // namespace

TEST_CASE("c golden: engines equal tests/golden/c byte for byte", "[c_backend][golden]") {
  auto files = chart_files();
  auto names = cases(files);
  REQUIRE(names.size() >= 4);
  for (const auto &name : names) {
    DYNAMIC_SECTION(name) {
      std::string stem = fs::path(name).stem().string();
      CaseFlags flags = flags_for(stem);
      auto compiled =
          compile_chart(files, name, stem + ".c", flags.line_directives, flags.engine, flags.context_type, flags.names);
      INFO(compiled->errors);
      REQUIRE(!compiled->diag.has_errors());
      REQUIRE(compiled->files.size() == 2);
      CHECK(compiled->files[0].path == stem + ".c");
      CHECK(compiled->files[1].path == stem + ".h");
      for (const auto &f : compiled->files) check_golden(f.path, f.contents);
    }
  }
}

TEST_CASE("c golden: the same chart gives byte-identical engines", "[c_backend][golden]") {
  auto files = chart_files();
  for (const auto &name : cases(files)) {
    CaseFlags flags = flags_for(fs::path(name).stem().string());
    auto one = compile_chart(files, name, "engine.c", true, flags.engine, flags.context_type, flags.names);
    auto two = compile_chart(files, name, "engine.c", true, flags.engine, flags.context_type, flags.names);
    INFO(name << one->errors);
    REQUIRE(!one->diag.has_errors());
    REQUIRE(one->files.size() == two->files.size());
    for (std::size_t i = 0; i < one->files.size(); ++i) CHECK(one->files[i].contents == two->files[i].contents);
  }
}
