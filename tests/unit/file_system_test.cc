// What a language server needs of the front end: an editor's unsaved buffers read over the disk
// (OverlayFileSystem), a recursive listing on every file system (walk), and the syntax tree kept
// whole after validation (FrontEndOptions::keep_syntax_tree).
#include "file_system.h"
#include "support.h"

#include <catch2/catch.hpp>

#include <filesystem>

using namespace gfec;
using namespace gfec::test;

namespace {

/// One tree for every file system: files at several depths, one in a hidden folder, one deeper
/// than walk goes by default (six folders below the root), and one beside the root.
const char *const kTree[] = {
    "root/top.sfc",     "root/plans/a.pml",           "root/plans/behaviours/b.beh",
    "root/.git/config", "root/1/2/3/4/5/at_five.sfc", "root/1/2/3/4/5/6/at_six.sfc",
    "beside/c.sfc",
};

const std::vector<std::string> kWalked = {
    "root/1/2/3/4/5/at_five.sfc",
    "root/plans/a.pml",
    "root/plans/behaviours/b.beh",
    "root/top.sfc",
};

MemoryFileSystem memory_tree() {
  MemoryFileSystem fs;
  for (const char *path : kTree) fs.add(path, std::string("text of ") + path);
  return fs;
}

}  // namespace

TEST_CASE("file system: walk lists the files below a folder, within its limits", "[file_system]") {
  SECTION("in memory") {
    MemoryFileSystem fs = memory_tree();
    CHECK(fs.walk("root") == kWalked);
    CHECK(fs.walk("root/") == kWalked);
    CHECK(fs.walk("root/plans") == std::vector<std::string>{"root/plans/a.pml", "root/plans/behaviours/b.beh"});
    WalkLimits shallow;
    shallow.max_depth = 1;
    CHECK(fs.walk("root", shallow) == std::vector<std::string>{"root/plans/a.pml", "root/top.sfc"});
    WalkLimits all;
    all.max_depth = 10;
    all.skip_hidden = false;
    CHECK(fs.walk("root", all).size() == 6);
    // "." and "": every relative path within the default limits; at_five.sfc is six deep from here.
    const std::vector<std::string> from_here = {"beside/c.sfc", "root/plans/a.pml", "root/plans/behaviours/b.beh",
                                                "root/top.sfc"};
    CHECK(fs.walk(".") == from_here);
    CHECK(fs.walk("") == from_here);
    CHECK(fs.walk("nowhere").empty());
  }
  SECTION("on disk") {
    const std::filesystem::path dir = scratch_dir("file-system-walk");
    for (const char *path : kTree) {
      std::filesystem::create_directories((dir / path).parent_path());
      write_file((dir / path).string(), path);
    }
    RealFileSystem fs;
    std::vector<std::string> expected;
    for (const auto &p : kWalked) expected.push_back((dir / p).lexically_normal().generic_string());
    CHECK(fs.walk((dir / "root").string()) == expected);
    CHECK(fs.walk((dir / "nowhere").string()).empty());
  }
  SECTION("through an overlay") {
    MemoryFileSystem disk = memory_tree();
    OverlayFileSystem fs(disk);
    CHECK(fs.walk("root") == kWalked);
    fs.open("root/plans/./unsaved.pml", "{}");  // a new file, not yet on disk
    fs.open("root/top.sfc", "changed");         // listed once
    fs.open("beside/d.sfc", "elsewhere");       // not below root
    std::vector<std::string> with_buffers = kWalked;
    with_buffers.insert(with_buffers.begin() + 3, "root/plans/unsaved.pml");
    CHECK(fs.walk("root") == with_buffers);
  }
}

TEST_CASE("file system: an overlay's open buffers shadow the files below", "[file_system]") {
  MemoryFileSystem disk;
  disk.add("src/a.sfc", "on disk");
  disk.add("src/b.iface", "interface");
  OverlayFileSystem fs(disk);
  CHECK(fs.read("src/a.sfc").text == std::optional<std::string>("on disk"));
  fs.open("src/a.sfc", "in the editor");
  fs.open("src/new.sfc", "not saved yet");
  CHECK(fs.read("src/a.sfc").text == std::optional<std::string>("in the editor"));
  CHECK(fs.read("src/./a.sfc").text == std::optional<std::string>("in the editor"));
  CHECK(fs.read("src/new.sfc").text == std::optional<std::string>("not saved yet"));
  CHECK(fs.read("src/b.iface").text == std::optional<std::string>("interface"));
  CHECK(!fs.read("src/none.sfc"));
  CHECK(fs.list("src") == std::vector<std::string>{"a.sfc", "b.iface", "new.sfc"});
  fs.close("src/a.sfc");
  CHECK(fs.read("src/a.sfc").text == std::optional<std::string>("on disk"));
  CHECK(disk.read("src/a.sfc").text == std::optional<std::string>("on disk"));  // the disk was never written
}

TEST_CASE("file system: the pipeline compiles the editor's buffer, and a file it imports from disk", "[file_system]") {
  const std::filesystem::path dir = scratch_dir("file-system-overlay");
  const std::string chart = (dir / "bot.sfc").string();
  write_file((dir / "bot.iface").string(), "interface Bot { void Go(); bool Done(); }\n");
  write_file(chart, "import \"bot.iface\";\nsfc Bot { period 10ms; initial place A { Go(); } place B;\n"
                    "A -> B when Done(); }\n");
  RealFileSystem disk;
  OverlayFileSystem fs(disk);
  // The editor has a typo the saved file does not have.
  fs.open(chart, "import \"bot.iface\";\nsfc Bot { period 10ms; initial place A { Goo(); } place B;\n"
                 "A -> B when Done(); }\n");
  Pipeline edited(chart, fs);
  CHECK(edited.text().find("bot.sfc:2:42: error: unknown function 'Goo'") != std::string::npos);
  fs.close(chart);
  Pipeline saved(chart, fs);
  CHECK(saved.text().empty());
  CHECK(!saved.diag.has_errors());
}

TEST_CASE("file system: keep_syntax_tree keeps the tree whole after front_end", "[file_system]") {
  const char *const text = "interface Bot { void Go(); bool Done(); }\n"
                           "sfc S {\n"
                           "  period 10ms;\n"
                           "  initial place A { Go(); %{ x++; %} entry { Go(); } }\n"
                           "  place B;\n"
                           "  A -> B when Done();\n"
                           "}\n";
  auto run = [&](bool keep) {
    pipeline::FrontEndOptions options;
    options.analyze = false;
    options.keep_syntax_tree = keep;
    auto c = std::make_unique<pipeline::Compilation>(options);
    c->front_end("s.sfc", files({{"s.sfc", text}}));
    return c;
  };
  auto dropped = run(false);
  auto kept = run(true);
  INFO(dropped->diag.all().size());
  REQUIRE(!dropped->diag.has_errors());
  REQUIRE(!kept->diag.has_errors());
  CHECK(dropped->loaded.program.files.empty());  // the default: gone before the back ends run
  REQUIRE(kept->loaded.program.files.size() == 1);
  const ast::Chart &chart = kept->loaded.program.files[0]->charts.at(0);
  // What the validator would have released once lowered: bodies, entry blocks, verbatim text,
  // conditions and the transition's places.
  REQUIRE(chart.places.at(0).action.size() == 2);
  CHECK(chart.places[0].action[0].kind == ast::Stmt::Kind::Call);
  REQUIRE(chart.places[0].action[1].verbatim);
  CHECK(*chart.places[0].action[1].verbatim == " x++; ");
  REQUIRE(chart.places[0].entry());
  CHECK(chart.places[0].entry()->size() == 1);
  REQUIRE(chart.transitions.at(0).condition);
  CHECK(chart.transitions[0].condition->name.text == "Done");
  REQUIRE(chart.transitions[0].inputs().size() == 1);
  CHECK(chart.transitions[0].inputs()[0].text == "A");
  CHECK(chart.transitions[0].outputs()[0].text == "B");
  // The model is the same either way.
  const model::Chart &a = dropped->model.charts.at(model::ChartId(0));
  const model::Chart &b = kept->model.charts.at(model::ChartId(0));
  CHECK(a.places[model::PlaceId(0)].action.size() == b.places[model::PlaceId(0)].action.size());
  REQUIRE(a.places[model::PlaceId(0)].action.size() == 2);
  CHECK(*a.places[model::PlaceId(0)].action[1].verbatim == " x++; ");
  CHECK(*b.places[model::PlaceId(0)].action[1].verbatim == " x++; ");
  REQUIRE(a.places[model::PlaceId(0)].entry);
  REQUIRE(b.places[model::PlaceId(0)].entry);
  CHECK(a.places[model::PlaceId(0)].entry->size() == b.places[model::PlaceId(0)].entry->size());
  CHECK(bool(a.transitions[model::TransitionId(0)].condition) == bool(b.transitions[model::TransitionId(0)].condition));
}
