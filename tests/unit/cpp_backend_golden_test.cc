// Golden tests of the cpp back end and the toolbox skeleton: every plan under tests/golden/cpp
// (with the plans and toolboxes it imports beside it) goes through the real front end and the
// back end in memory and must equal <case>.cpp and <case>.hpp byte for byte; every toolbox
// <case>.toolbox must give <case>_toolbox.h and <case>_toolbox.cpp. <case>.flags holds gfec
// options (only --no-line-directives matters here). tools/regen-golden.sh cpp rewrites the
// expected files with the real gfec; a reviewer reads the diff (tests/README.md).
#include "../run/cpp_backend_support.h"

#include <cstdlib>

using namespace cppt;

namespace {

/// Compares `actual` with the golden file; GFEC_UPDATE_GOLDEN=1 writes it instead.
void check_golden(const std::string &name, const std::string &actual) {
  fs::path golden = kGoldenDir / name;
  if (const char *update = std::getenv("GFEC_UPDATE_GOLDEN"); update && std::string(update) == "1") {
    test::write_file(golden.string(), actual);
    WARN("updated " << golden.string());
    return;
  }
  REQUIRE(fs::exists(golden));
  std::string expected = test::read_file(golden.string());
  if (expected == actual) return;
  fs::path out = fs::path(GFEC_BINARY_DIR) / "test-scratch" / "golden" / "cpp" / name;
  fs::create_directories(out.parent_path());
  test::write_file(out.string(), actual);
  FAIL_CHECK("tests/golden/cpp/" << name << " differs from what the back end writes now; "
                                 << first_difference(expected, actual) << "\nsee: diff -u " << golden.string() << " "
                                 << out.string() << "\naccept (after reading the diff): tools/regen-golden.sh cpp");
}

bool line_directives_for(const std::string &stem) {
  fs::path flags = kGoldenDir / (stem + ".flags");
  if (!fs::exists(flags)) return true;
  std::istringstream in(test::read_file(flags.string()));
  bool lines = true;
  for (std::string flag; in >> flag;) {
    INFO(flags.string() << ": only --no-line-directives is understood here");
    REQUIRE(flag == "--no-line-directives");
    lines = false;
  }
  return lines;
}

std::vector<std::string> cases(const std::map<std::string, std::string> &files, const std::string &ext) {
  std::vector<std::string> names;
  for (const auto &[name, text] : files)
    if (fs::path(name).extension() == ext) names.push_back(name);
  return names;  // std::map keeps them sorted
}

}  // namespace

TEST_CASE("cpp golden: plan wiring equals tests/golden/cpp byte for byte", "[cpp_backend][golden]") {
  auto files = chart_files(kGoldenDir);
  auto names = cases(files, ".plan");
  REQUIRE(names.size() >= 5);  // formulas, square, square_side, wall_follow, wall_follow_plain
  for (const auto &name : names) {
    DYNAMIC_SECTION(name) {
      std::string stem = fs::path(name).stem().string();
      auto compiled = compile(files, name, stem + ".cpp", false, line_directives_for(stem));
      INFO(compiled->errors);
      REQUIRE(!compiled->diag.has_errors());
      REQUIRE(compiled->files.size() == 2);
      CHECK(compiled->files[0].path == stem + ".cpp");
      CHECK(compiled->files[1].path == stem + ".hpp");
      for (const auto &f : compiled->files) check_golden(f.path, f.contents);
    }
  }
}

TEST_CASE("cpp golden: toolbox skeletons equal tests/golden/cpp byte for byte", "[cpp_backend][golden]") {
  auto files = chart_files(kGoldenDir);
  auto names = cases(files, ".toolbox");
  REQUIRE(names.size() >= 2);  // carbot, probe
  for (const auto &name : names) {
    DYNAMIC_SECTION(name) {
      std::string stem = fs::path(name).stem().string();
      auto compiled = compile(files, name, stem + "_toolbox.h", true);
      INFO(compiled->errors);
      REQUIRE(!compiled->diag.has_errors());
      REQUIRE(compiled->files.size() == 2);
      CHECK(compiled->files[0].path == stem + "_toolbox.h");
      CHECK(compiled->files[1].path == stem + "_toolbox.cpp");
      for (const auto &f : compiled->files) check_golden(f.path, f.contents);
    }
  }
}

TEST_CASE("cpp golden: the same input gives byte-identical files", "[cpp_backend][golden]") {
  auto files = chart_files(kGoldenDir);
  for (const auto &name : cases(files, ".plan")) {
    auto one = compile(files, name, "plan.cpp");
    auto two = compile(files, name, "plan.cpp");
    INFO(name << one->errors);
    REQUIRE(!one->diag.has_errors());
    REQUIRE(one->files.size() == two->files.size());
    for (std::size_t i = 0; i < one->files.size(); ++i) CHECK(one->files[i].contents == two->files[i].contents);
  }
}

TEST_CASE("cpp golden: the golden cases are the samples", "[cpp_backend][golden]") {
  // wall_follow, square and the Carbot toolbox are copies of samples/: the goldens show what the
  // samples compile to, and a change to a sample must reach them.
  for (const char *name : {"wall_follow.plan", "square.plan", "square_side.plan", "carbot.toolbox"}) {
    INFO(name);
    CHECK(test::read_file((kGoldenDir / name).string()) == test::read_file((kSourceDir / "samples" / name).string()));
  }
}
