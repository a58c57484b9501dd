// What the cpp back end's tests share (tests/unit/cpp_backend_*_test.cc): plan and toolbox text
// through the real front end and the back ends in memory, the golden folder, and building
// generated C++ with g++ and clang++ against the afp runtime (tests/run/cpp/ holds the scripted
// test toolboxes and the run harness).
#pragma once

#include "backend.h"
#include "cpp_backend.h"
#include "diagnostic_printer.h"
#include "file_system.h"
#include "loader.h"
#include "model.h"
#include "pipeline/compilation.h"

#include "../unit/support.h"

#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <filesystem>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace cppt {

namespace fs = std::filesystem;
using namespace gfec;

inline const fs::path kSourceDir = GFEC_SOURCE_DIR;
inline const fs::path kGoldenDir = kSourceDir / "tests" / "golden" / "cpp";
inline const fs::path kRunDir = kSourceDir / "tests" / "run" / "cpp";
inline const fs::path kRuntimeInclude = kSourceDir / "runtime" / "include";
inline const fs::path kRuntimeLibrary = fs::path(GFEC_BINARY_DIR) / "runtime" / "libafp_runtime.a";
/// What a program linking kRuntimeLibrary needs besides it: the sanitizers the build uses.
inline const std::string kRuntimeLinkFlags = GFEC_RUNTIME_LINK_FLAGS;

/// What generated C++ must compile warning-free with (docs/language.md §8 asks -Wall -Wextra -Werror;
/// the project holds generated code to -Wpedantic too).
inline const char *kStrictFlags = "-std=c++17 -Wall -Wextra -Wpedantic -Werror";

/// The files of one compilation, through the front end and one back end, all in memory. Files
/// are named as given, so #line paths stay short and the output byte-stable.
struct Compiled {
  pipeline::Compilation c{options()};
  SourceManager &sources = c.sources;
  Diagnostics &diag = c.diag;
  model::Model &model = c.model;
  std::vector<OutputFile> files;
  std::string errors;  ///< rendered diagnostics when the input did not compile

  static pipeline::FrontEndOptions options() {
    pipeline::FrontEndOptions f;
    f.analyze = false;  // the tests compare exact diagnostics
    return f;
  }
};

/// Compiles `main` (a plan, or with `skeleton` a toolbox) of `files` to `output`.
inline std::unique_ptr<Compiled> compile(const std::map<std::string, std::string> &files, const std::string &main,
                                         const std::string &output, bool skeleton = false,
                                         bool line_directives = true) {
  auto c = std::make_unique<Compiled>();
  MemoryFileSystem mem;
  for (const auto &[path, text] : files) mem.add(path, text);
  c->c.front_end(main, mem);
  for (const auto &d : c->diag.all()) c->errors += render_text(d, c->sources);
  if (c->diag.has_errors()) return c;
  pipeline::SelectionRequest request;
  request.among = skeleton ? pipeline::kToolbox : pipeline::kPlan;
  const pipeline::Selection &target = c->c.select(request);
  if (!target.chosen()) {
    c->errors += target.error + "\n";
    return c;
  }
  EmitOptions o;
  o.output_path = output;
  o.source_name = main;
  o.line_directives = line_directives;
  o.toolbox = target.toolbox;
  o.plan = target.plan;
  c->files = emit_to_memory(skeleton ? *make_toolbox_skeleton_backend() : *make_cpp_backend(), c->model, o);
  return c;
}

/// Every .plan and .toolbox file of a folder: name -> text.
inline std::map<std::string, std::string> chart_files(const fs::path &dir) {
  std::map<std::string, std::string> files;
  for (const auto &entry : fs::directory_iterator(dir)) {
    auto ext = entry.path().extension();
    if (ext == ".plan" || ext == ".toolbox")
      files[entry.path().filename().string()] = test::read_file(entry.path().string());
  }
  return files;
}

/// The samples the tests compile: samples/*.plan and samples/carbot.toolbox.
inline std::map<std::string, std::string> sample_files() { return chart_files(kSourceDir / "samples"); }

/// The C++ compilers generated code must satisfy; clang++ is skipped (the caller warns) where
/// it is not installed.
inline std::vector<std::string> cxx_compilers() {
  std::vector<std::string> cxx{"g++"};
  if (test::run_command("command -v clang++").exit_code == 0) cxx.push_back("clang++");
  return cxx;
}

/// The compilers that can link kRuntimeLibrary: both, unless the build is sanitized, when only
/// the one that built it (its sanitizer runtime is the one the library needs).
inline std::vector<std::string> runtime_linking_compilers() {
  if (kRuntimeLinkFlags.empty()) return cxx_compilers();
  return {GFEC_CXX_IS_CLANG ? "clang++" : "g++"};
}

/// Writes files into a fresh scratch folder; returns the folder.
inline std::string write_all(const std::string &test, const std::vector<OutputFile> &files) {
  std::string dir = test::scratch_dir("cpp_backend/" + test);
  for (const auto &f : files) test::write_file(dir + "/" + base_name(f.path), f.contents);
  return dir;
}

/// `cxx kStrictFlags extra -I runtime -I includes... -c source`: what the compiler said,
/// empty if it compiled. `source` relative to `dir`.
inline test::CommandResult compile_object(const std::string &cxx, const std::string &dir, const std::string &source,
                                          const std::vector<std::string> &includes, const std::string &extra = "") {
  std::string flags = extra.empty() ? "" : " " + extra;
  for (const auto &i : includes) flags += " -I '" + i + "'";
  return test::run_command(fmt::format("cd '{}' && {} {} -I '{}'{} -c '{}' -o /dev/null", dir, cxx, kStrictFlags,
                                       kRuntimeInclude.string(), flags, source));
}

/// Builds the run harness (tests/run/cpp/run_plan.cc) with the generated plan in `dir` and
/// the scripted toolboxes; returns the executable's path.
inline std::string build_harness(const std::string &cxx, const std::string &dir, const std::string &plan_base,
                                 const std::string &plan_name, const std::string &env) {
  std::string exe = dir + "/run-" + cxx;
  auto r = test::run_command(fmt::format("cd '{}' && {} {} -I . -I '{}' -I '{}' '-DPLAN_HEADER=\"{}.hpp\"' "
                                         "-DPLAN_FACTORY=make_{} -DPLAN_ENV={} '{}' {}.cpp "
                                         "'{}' {} -pthread -o '{}'",
                                         dir, cxx, kStrictFlags, kRunDir.string(), kRuntimeInclude.string(), plan_base,
                                         plan_name, env, (kRunDir / "run_plan.cc").string(), plan_base,
                                         kRuntimeLibrary.string(), kRuntimeLinkFlags, exe));
  INFO(cxx << " in " << dir << ":\n" << r.out);
  REQUIRE(r.exit_code == 0);
  return exe;
}

/// Runs a harness on a script (one line per step; the first before the start); `args`:
/// "threaded" runs the threaded executor instead.
inline std::string run_script(const std::string &exe, const std::string &script, const std::string &args = "") {
  std::string path = exe + ".script";
  test::write_file(path, script);
  auto r = test::run_command(fmt::format("'{}' {} < '{}'", exe, args, path));
  INFO(r.out);
  REQUIRE(r.exit_code == 0);
  return r.out;
}

using test::first_difference;

}  // namespace cppt
