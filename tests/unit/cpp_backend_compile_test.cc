// The cpp back end's output as compilers and people meet it: every golden file (wiring and
// skeleton) compiles warning-free with g++ and clang++; the sample plans compile against the
// simulator's hand-written Carbot toolbox (the contract's other implementation); a skeleton
// links and runs and says what is not implemented yet; every `#line` points where it should;
// and the gfec executable writes the files the documentation promises.
#include "../run/cpp_backend_support.h"

#include <regex>

using namespace cppt;

namespace {

const std::string gfec_exe = std::string(GFEC_BINARY_DIR) + "/gfec";

std::vector<std::string> golden_sources() {
  std::vector<std::string> names;
  for (const auto &entry : fs::directory_iterator(kGoldenDir))
    if (entry.path().extension() == ".cpp") names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

std::vector<std::string> lines_of(const std::string &text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  return lines;
}

/// A toolbox's skeleton (header and source) and a plan's wiring (source and header), compiled
/// from `files`: the four files a program that runs the plan starts from.
std::vector<OutputFile> skeleton_and_wiring(const std::map<std::string, std::string> &files, const std::string &toolbox,
                                            const std::string &skeleton_header, const std::string &plan,
                                            const std::string &wiring_source) {
  auto skeleton = compile(files, toolbox, skeleton_header, true);
  auto wiring = compile(files, plan, wiring_source);
  INFO(skeleton->errors << wiring->errors);
  REQUIRE(skeleton->files.size() == 2);
  REQUIRE(wiring->files.size() == 2);
  std::vector<OutputFile> all = skeleton->files;
  all.insert(all.end(), wiring->files.begin(), wiring->files.end());
  return all;
}

}  // namespace

TEST_CASE("cpp compile: every golden file compiles warning-free with g++ and clang++, -Wshadow too",
          "[cpp_backend][compile]") {
  auto names = golden_sources();
  REQUIRE(names.size() >= 7);  // five plans, two skeletons
  if (cxx_compilers().size() < 2) WARN("clang++ is not installed: the generated C++ is tested with g++ only");
  for (const auto &cxx : cxx_compilers())
    for (const auto &name : names) {
      // The plans include the skeleton headers beside them: the wiring and the skeleton agree.
      // No handle hides another name either (-Wshadow).
      auto r = compile_object(cxx, kGoldenDir.string(), name, {}, "-Wshadow");
      INFO(cxx << " " << name << ":\n" << r.out);
      CHECK(r.exit_code == 0);
      CHECK(r.out.empty());
    }
}

TEST_CASE("cpp compile: the sample plans compile against the simulator's Carbot toolbox", "[cpp_backend][compile]") {
  // sim/toolbox/carbot_toolbox.h is written by hand to the same contract as the skeleton.
  fs::path sim_toolbox = kSourceDir / "sim" / "toolbox";
  REQUIRE(fs::exists(sim_toolbox / "carbot_toolbox.h"));
  for (const char *sample : {"wall_follow.plan", "square.plan"}) {
    std::string stem = fs::path(sample).stem().string();
    auto compiled = compile(sample_files(), sample, stem + ".cpp");
    INFO(compiled->errors);
    REQUIRE(!compiled->diag.has_errors());
    std::string dir = write_all("sim-" + stem, compiled->files);
    for (const auto &cxx : cxx_compilers()) {
      auto r = compile_object(cxx, dir, stem + ".cpp", {sim_toolbox.string()});
      INFO(cxx << " " << sample << ":\n" << r.out);
      CHECK(r.exit_code == 0);
    }
  }
}

TEST_CASE("cpp compile: a fresh skeleton links with the wiring and fails where nothing is written yet",
          "[cpp_backend][compile]") {
  std::vector<OutputFile> all =
      skeleton_and_wiring(sample_files(), "carbot.toolbox", "carbot_toolbox.h", "wall_follow.plan", "wall_follow.cpp");
  all.push_back({"main.cpp", "#include \"wall_follow.hpp\"\n"
                             "#include <iostream>\n"
                             "int main() {\n"
                             "    Carbot ee;\n"
                             "    afp::Configuration config;\n"
                             "    auto plan = make_WallFollow(ee);\n"
                             "    afp::SteppedExecutor exec(*plan, config);\n"
                             "    exec.start();\n"
                             "    exec.step(std::chrono::milliseconds(10));\n"
                             "    std::cout << afp::to_string(exec.status()) << \": \" << exec.error() << \"\\n\";\n"
                             "}\n"});
  std::string dir = write_all("skeleton-links", all);
  for (const auto &cxx : runtime_linking_compilers()) {
    auto build = test::run_command(fmt::format(
        "cd '{}' && {} {} -I . -I '{}' main.cpp wall_follow.cpp carbot_toolbox.cpp "
        "'{}' {} -pthread -o run-{}",
        dir, cxx, kStrictFlags, kRuntimeInclude.string(), kRuntimeLibrary.string(), kRuntimeLinkFlags, cxx));
    INFO(cxx << ":\n" << build.out);
    REQUIRE(build.exit_code == 0);
    auto run = test::run_command(fmt::format("'{}/run-{}'", dir, cxx));
    // The global escape is checked first, at the first step.
    CHECK(run.out == "failed: escape: CheckEscape::check is not implemented\n");
  }
}

TEST_CASE("cpp compile: every #line names the plan line of its statement, or the next line of the file",
          "[cpp_backend][compile]") {
  auto files = chart_files(kGoldenDir);
  for (const char *main : {"wall_follow.plan", "square.plan", "formulas.plan"}) {
    auto compiled = compile(files, main, "out.cpp");
    REQUIRE(!compiled->diag.has_errors());
    auto lines = lines_of(compiled->files[0].contents);
    // Follow the compiler's idea of where each line comes from.
    std::string file = "out.cpp";
    long where = 1;
    const std::regex directive(R"re(^#line (\d+) "([^"]+)"$)re");
    const std::regex add(R"re(plan->add_(?:actor|supervisor)\("(\w+)")re");
    const std::regex declare(R"re(plan->declare\("(\w+)")re");
    const std::regex rule(R"re(plan->define_(?:subsequent|supervision|global_supervision)\(.*::(\w+), [\w:]+\);$)re");
    int checked = 0;
    for (std::size_t i = 0; i < lines.size(); ++i, ++where) {
      std::smatch m;
      if (std::regex_match(lines[i], m, directive)) {
        file = m[2];
        where = std::stol(m[1]) - 1;
        if (file == "out.cpp") CHECK(where + 1 == static_cast<long>(i) + 2);  // names the line after it
        continue;
      }
      std::string key;
      if (std::regex_search(lines[i], m, add) || std::regex_search(lines[i], m, declare) ||
          std::regex_search(lines[i], m, rule))
        key = m[1];
      if (key.empty()) continue;
      INFO(main << " line " << i + 1 << ": " << lines[i] << "\nattributed to " << file << ":" << where);
      REQUIRE(file != "out.cpp");
      auto plan_lines = lines_of(files.at(file));
      REQUIRE(where >= 1);
      REQUIRE(where <= static_cast<long>(plan_lines.size()));
      CHECK(plan_lines[static_cast<std::size_t>(where - 1)].find(key) != std::string::npos);
      ++checked;
    }
    CHECK(checked >= 10);
  }
}

TEST_CASE("cpp compile: gfec writes plan.cpp with plan.hpp, and the skeleton's header with its source",
          "[cpp_backend][compile]") {
  std::string dir = test::scratch_dir("cpp_backend/driver");
  std::string samples = (kSourceDir / "samples").string();
  auto plan = test::run_command(
      fmt::format("cd '{}' && '{}' wall_follow.plan -o '{}/wall_follow.cpp'", samples, gfec_exe, dir));
  INFO(plan.out);
  REQUIRE(plan.exit_code == 0);
  auto compiled = compile(sample_files(), "wall_follow.plan", dir + "/wall_follow.cpp");
  CHECK(test::read_file(dir + "/wall_follow.cpp") == compiled->files[0].contents);
  CHECK(test::read_file(dir + "/wall_follow.hpp") == compiled->files[1].contents);

  auto skeleton = test::run_command(fmt::format(
      "cd '{}' && '{}' --emit=toolbox-skeleton carbot.toolbox -o '{}/carbot_toolbox.h'", samples, gfec_exe, dir));
  INFO(skeleton.out);
  REQUIRE(skeleton.exit_code == 0);
  CHECK(test::read_file(dir + "/carbot_toolbox.h").find("class WallForward : public afp::Actor {") !=
        std::string::npos);
  CHECK(test::read_file(dir + "/carbot_toolbox.cpp").find("afp::StepResult WallForward::step(afp::Context& ctx) {") !=
        std::string::npos);

  // A plan is compiled by the cpp back end without --emit; the wiring includes carbot_toolbox.h.
  auto square =
      test::run_command(fmt::format("cd '{}' && '{}' square.plan -o '{}/square.cpp'", samples, gfec_exe, dir));
  INFO(square.out);
  REQUIRE(square.exit_code == 0);
  CHECK(test::read_file(dir + "/square.cpp").find("#include \"carbot_toolbox.h\"") != std::string::npos);
  CHECK(test::read_file(dir + "/square.hpp").find("std::unique_ptr<afp::Plan> make_Square(Carbot& ee);") !=
        std::string::npos);
}

TEST_CASE("cpp compile: templates named like the factory's own names (ee, the formula helpers) compile",
          "[cpp_backend][compile]") {
  // The factory's parameter `ee`, and the helpers `text` and `divide` its formulas call, give
  // way to the templates' classes, which cannot move: they are the toolbox contract.
  const std::map<std::string, std::string> files = {
      {"kit.toolbox", "toolbox Kit {\n  actor ee() -> DONE;\n  actor text(in string s) -> DONE;\n"
                      "  actor divide(in int n) -> DONE;\n}\n"},
      {"p.plan", "import \"kit.toolbox\";\nplan P {\n  config { int n = 7; }\n  start a;\n"
                 "  actor a: ee() { DONE -> b; }\n  actor b: text(\"n = \" + n / 2) { DONE -> c; }\n"
                 "  actor c: divide(n / 2) { DONE -> terminate; }\n}\n"}};
  std::string dir =
      write_all("names-factory", skeleton_and_wiring(files, "kit.toolbox", "kit_toolbox.h", "p.plan", "p.cpp"));
  for (const auto &cxx : cxx_compilers())
    for (const char *source : {"p.cpp", "kit_toolbox.cpp"}) {
      auto r = compile_object(cxx, dir, source, {}, "-Wshadow");
      INFO(cxx << " " << source << ":\n" << r.out);
      CHECK(r.exit_code == 0);
    }
}
