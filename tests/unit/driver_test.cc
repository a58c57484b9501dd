// The gfec executable as users and build systems see it: exit codes, atomic outputs, --help.
#include "support.h"

#include <catch2/catch.hpp>

#include <filesystem>

using namespace gfec::test;

namespace {

const std::string gfec_exe = std::string(GFEC_BINARY_DIR) + "/gfec";
const std::string samples = std::string(GFEC_SOURCE_DIR) + "/samples";

const char *kGood = R"(interface R { bool Ready(); void Go(); }
sfc Tiny {
  initial place A { Go(); }
  place B;
  transition A -> B when Ready();
}
)";

}  // namespace

TEST_CASE("gfec: --version and --help exit 0") {
  auto v = run_command(gfec_exe + " --version");
  CHECK(v.exit_code == 0);
  CHECK(v.out.rfind("gfec ", 0) == 0);
  auto h = run_command(gfec_exe + " --help");
  CHECK(h.exit_code == 0);
  CHECK(h.out.find("--check") != std::string::npos);
  CHECK(h.out.find("-Wunreachable-place") != std::string::npos);
}

TEST_CASE("gfec: usage errors exit 2") {
  CHECK(run_command(gfec_exe).exit_code == 2);
  CHECK(run_command(gfec_exe + " --no-such-option x.sfc").exit_code == 2);
  auto w = run_command(gfec_exe + " -Wno-such-warning x.sfc");
  CHECK(w.exit_code == 2);
  CHECK(w.out == "gfec: error: unknown warning option '-Wno-such-warning' ('gfec --help' lists the warnings)\n");
  auto missing = run_command(gfec_exe + " does-not-exist.sfc");
  CHECK(missing.exit_code == 2);
  CHECK(missing.out == "gfec: error: cannot read 'does-not-exist.sfc': no such file\n");
  // Only regular files are read: a folder or a device is refused with the reason, never waited on
  // (--check takes a folder for the files below it: tests/cli/check.sh).
  auto folder = run_command(gfec_exe + " /tmp");
  CHECK(folder.exit_code == 2);
  CHECK(folder.out == "gfec: error: cannot read '/tmp': it is a folder\n");
  auto device = run_command(gfec_exe + " run /dev/zero");
  CHECK(device.exit_code == 2);
  CHECK(device.out == "gfec: error: cannot read '/dev/zero': not a regular file (a character device); gfec reads no "
                      "devices, pipes or sockets\n");
}

TEST_CASE("gfec: compiles a chart into engine.c and engine.h") {
  std::string dir = scratch_dir("driver-good");
  write_file(dir + "/tiny.sfc", kGood);
  auto r = run_command("cd " + dir + " && " + gfec_exe + " tiny.sfc -o engine.c");
  CHECK(r.out == "");
  CHECK(r.exit_code == 0);
  CHECK(read_file(dir + "/engine.c").find("Tiny_run") != std::string::npos);
  CHECK(read_file(dir + "/engine.h").find("Tiny_PLACE_COUNT") != std::string::npos);
  // Nothing else is left behind: no temporary files.
  int files = 0;
  for (auto &e : std::filesystem::directory_iterator(dir)) files += e.is_regular_file();
  CHECK(files == 3);
}

TEST_CASE("gfec: an input error exits 1 and leaves existing outputs untouched") {
  std::string dir = scratch_dir("driver-bad");
  write_file(dir + "/bad.sfc", "sfc Bad { initial place A; A -> Nowhere; }\n");
  write_file(dir + "/engine.c", "old engine\n");
  write_file(dir + "/engine.h", "old header\n");
  auto r = run_command("cd " + dir + " && " + gfec_exe + " bad.sfc -o engine.c");
  CHECK(r.exit_code == 1);
  CHECK(r.out.find("bad.sfc:1:33: error: ") == 0);
  CHECK(read_file(dir + "/engine.c") == "old engine\n");
  CHECK(read_file(dir + "/engine.h") == "old header\n");

  write_file(dir + "/syntax.sfc", "sfc Bad { initial place A }\n");
  auto s = run_command("cd " + dir + " && " + gfec_exe + " syntax.sfc -o new.c");
  CHECK(s.exit_code == 1);
  CHECK_FALSE(std::filesystem::exists(dir + "/new.c"));
  CHECK_FALSE(std::filesystem::exists(dir + "/new.h"));
}

TEST_CASE("gfec: an unwritable output is an I/O error, exit 2") {
  std::string dir = scratch_dir("driver-io");
  write_file(dir + "/tiny.sfc", kGood);
  auto r = run_command("cd " + dir + " && " + gfec_exe + " tiny.sfc -o no/such/dir/engine.c");
  CHECK(r.exit_code == 2);
  CHECK(r.out.find("gfec: error: cannot write 'no/such/dir/engine.c'") == 0);
}

TEST_CASE("gfec: several charts need --chart, and the error lists them") {
  std::string dir = scratch_dir("driver-select");
  write_file(dir + "/two.sfc", std::string(kGood) + "sfc Other { initial place X; }\n");
  auto r = run_command("cd " + dir + " && " + gfec_exe + " two.sfc -o e.c");
  CHECK(r.exit_code == 2);
  CHECK(r.out == "two.sfc: error: the file declares several things to compile (sfc 'Tiny', sfc 'Other'); "
                 "choose one with --chart NAME\n");
  auto ok = run_command("cd " + dir + " && " + gfec_exe + " two.sfc --chart Other -o e.c");
  CHECK(ok.exit_code == 0);
  CHECK(read_file(dir + "/e.h").find("Other_init") != std::string::npos);
}

TEST_CASE("gfec --check: every file, nothing written, exit 1 on any error") {
  std::string dir = scratch_dir("driver-check");
  write_file(dir + "/good.sfc", kGood);
  write_file(dir + "/bad.sfc", "sfc Bad { place A; }\n");
  auto good = run_command("cd " + dir + " && " + gfec_exe + " --check good.sfc");
  CHECK(good.exit_code == 0);
  CHECK(good.out == "");
  auto both =
      run_command("cd " + dir + " && " + gfec_exe + " --check bad.sfc good.sfc " + samples + "/line_follower.sfc");
  CHECK(both.exit_code == 1);
  CHECK(both.out.find("bad.sfc:1:") == 0);
  int files = 0;
  for (auto &e : std::filesystem::directory_iterator(dir)) files += e.is_regular_file();
  CHECK(files == 2);
}

TEST_CASE("gfec: the samples compile without a diagnostic") {
  std::string dir = scratch_dir("driver-samples");
  for (const char *chart : {"line_follower.sfc", "cleanup.fsm", "work_cell.sfc"}) {
    auto r = run_command(gfec_exe + " " + samples + "/" + chart + " -o " + dir + "/" + chart + ".c");
    INFO(chart << ": " << r.out);
    CHECK(r.exit_code == 0);
    // A sample is what users copy: it must not teach them to ignore a warning.
    CHECK(r.out.empty());
  }
}

// The default root (docs/language.md "Sub-charts"): the one chart of the file that no chart runs.
TEST_CASE("gfec: a file with sub-charts compiles the chart no other chart runs") {
  std::string dir = scratch_dir("driver-root");
  write_file(dir + "/h.sfc", R"(interface R { bool Ready(); void Go(); }
sfc Leaf { initial place L { Go(); } }
fsm Mid { initial state M runs Leaf; success state Done; M -> Done when Ready(); }
sfc Top { initial place A runs Mid; place B; A -> B when succeeded(A); }
sfc Spare { initial place S; }
)");
  // Two charts run by none: Top and Spare; the error lists only those.
  auto r = run_command("cd " + dir + " && " + gfec_exe + " --emit=dot h.sfc -o -");
  CHECK(r.exit_code == 2);
  CHECK(r.out == "h.sfc: error: the file declares several things to compile (sfc 'Top', sfc 'Spare'); "
                 "choose one with --chart NAME\n");
  // --chart may still name a sub-chart, to compile it alone; Top is then neither run nor compiled,
  // but Leaf runs nothing, so nothing is said.
  auto leaf = run_command("cd " + dir + " && " + gfec_exe + " --emit=dot --chart Leaf h.sfc -o -");
  CHECK(leaf.exit_code == 0);
  CHECK(leaf.out.rfind("digraph \"Leaf\"", 0) == 0);
  // Compiling the hierarchy: Spare is neither compiled nor run by it, which is worth a warning.
  auto top = run_command("cd " + dir + " && " + gfec_exe + " --emit=dot --chart Top h.sfc -o out.dot");
  CHECK(top.exit_code == 0);
  CHECK(top.out == "h.sfc:5:1: warning: sfc 'Spare' is neither compiled nor run by 'Top', the chart being compiled "
                   "[-Wunused-chart]\n"
                   "    5 | sfc Spare { initial place S; }\n"
                   "      | ^~~~~~~~~~~~~~~~~~~~~~~~~~~~~~\n"
                   "h.sfc:4:1: note: to use it, let a place or state of 'Top' run it ('runs Spare')\n"
                   "    4 | sfc Top { initial place A runs Mid; place B; A -> B when succeeded(A); }\n"
                   "      | ^~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~~\n");
  // Without Spare, Top is the only root and needs no --chart.
  write_file(dir + "/h2.sfc", R"(interface R { bool Ready(); void Go(); }
sfc Leaf { initial place L { Go(); } }
sfc Top { initial place A runs Leaf; }
)");
  auto one = run_command("cd " + dir + " && " + gfec_exe + " --emit=dot h2.sfc -o -");
  CHECK(one.exit_code == 0);
  CHECK(one.out.rfind("digraph \"Top\"", 0) == 0);
}

TEST_CASE("gfec: every --context-type gfec accepts gives an engine that compiles") {
  std::string dir = scratch_dir("driver-context-types");
  write_file(dir + "/tiny.sfc", kGood);
  write_file(dir + "/types.h", "#include <stdint.h>\nstruct motor { int a; };\nenum mode { M };\n");
  for (const char *type : {"void *", "const struct motor *", "struct motor const *", "struct motor", "uint32_t",
                           "unsigned long", "enum mode", "void **", "const char *const *", "volatile int *"}) {
    INFO(type);
    auto c = run_command("cd " + dir + " && " + gfec_exe + " --context-type='" + type + "' tiny.sfc -o e.c && " +
                         "cc -std=c99 -Wall -Wextra -Wpedantic -Werror -include types.h -c e.c -o e.o");
    CHECK(c.out == "");
    CHECK(c.exit_code == 0);
  }
}

TEST_CASE("gfec: --context and --names are the C engine's: other back ends reject them (exit 2)") {
  std::string dir = scratch_dir("driver-context");
  write_file(dir + "/tiny.sfc", kGood);
  auto c = run_command("cd " + dir + " && " + gfec_exe + " --context-type='struct bot *' --names tiny.sfc -o e.c");
  CHECK(c.out == "");
  REQUIRE(c.exit_code == 0);
  const std::string header = read_file(dir + "/e.h");
  CHECK(header.find("void Go(struct bot *ctx);") != std::string::npos);
  CHECK(header.find("bool Ready(struct bot *ctx);") != std::string::npos);
  CHECK(header.find("void Tiny_set_context(Tiny *m, struct bot *ctx);") != std::string::npos);
  CHECK(header.find("const char *Tiny_place_name(int place);") != std::string::npos);
  auto dot = run_command("cd " + dir + " && " + gfec_exe + " --emit=dot --context tiny.sfc -o t.dot");
  CHECK(dot.exit_code == 2);
  CHECK(dot.out == "gfec: error: --context applies only to the C engine; --emit=dot does not take it\n");
  CHECK_FALSE(std::filesystem::exists(dir + "/t.dot"));
  auto json = run_command("cd " + dir + " && " + gfec_exe + " --emit=json --names tiny.sfc -o t.json");
  CHECK(json.exit_code == 2);
  CHECK(json.out == "gfec: error: --names applies only to the C engine; --emit=json does not take it\n");
  auto help = run_command(gfec_exe + " --help");
  CHECK(help.out.find("--context-type") != std::string::npos);
  CHECK(help.out.find("--names") != std::string::npos);
}

TEST_CASE("gfec: --context warns about a C library function's own prototype, which it changes") {
  // sqrt(double) is the C library's until --context puts the context first (-Wlibrary-function).
  std::string dir = scratch_dir("driver-context-library");
  write_file(dir + "/lib.sfc",
             "interface L { double sqrt(double x); }\nsfc P { initial place A; A -> A when sqrt(2.0) > "
             "1.0; }\n");
  auto plain = run_command("cd " + dir + " && " + gfec_exe + " lib.sfc -o engine.c");
  CHECK(plain.out == "");
  CHECK(plain.exit_code == 0);
  auto context = run_command("cd " + dir + " && " + gfec_exe + " lib.sfc -o engine.c --context");
  CHECK(context.out.find("warning: with --context 'sqrt' takes the context first") != std::string::npos);
  CHECK(context.out.find("[-Wlibrary-function]") != std::string::npos);
  CHECK(context.exit_code == 0);
  CHECK(run_command("cd " + dir + " && " + gfec_exe + " lib.sfc -o engine.c --context -Werror").exit_code == 1);
}
