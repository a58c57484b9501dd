// What the validator records of the names it resolves (compiler/name_uses.h), which the language
// server's definition, references and rename read: each use points at its declaration, across
// files and into test blocks; nothing is recorded unless asked for, and an unknown name is not.
#include "file_system.h"
#include "pipeline/compilation.h"

#include <catch2/catch.hpp>

#include <string>

using namespace gfec;

namespace {

MemoryFileSystem files() {
  MemoryFileSystem fs;
  fs.add("io.iface", "interface Io {\n  void led_on();\n  bool ready();\n}\n");
  fs.add("blink.sfc", "import \"io.iface\";\n"
                      "sfc Blink {\n"
                      "  var int count = 3;\n"
                      "  initial place Off { }\n"
                      "  place On { led_on(); count = count - 1; }\n"
                      "  transition Off -> On when ready();\n"
                      "  transition On -> Off when count > 0;\n"
                      "}\n");
  fs.add("blink.test", "import \"blink.sfc\";\ntest \"t\" of Blink { set ready = true; tick; expect active(On); }\n");
  return fs;
}

/// The text of `r` in `c`'s sources.
std::string text(const pipeline::Compilation &c, const SourceRange &r) {
  return c.sources.file(r.file).text().substr(r.begin, r.end - r.begin);
}

/// The uses (not declarations) of `name` whose declaration is in `decl_path`.
int uses_of(const pipeline::Compilation &c, const std::string &name, const std::string &decl_path) {
  int n = 0;
  for (const NameUse &u : c.name_uses.list)
    if (!u.declaration() && text(c, u.at) == name && c.sources.file(u.decl.file).path() == decl_path &&
        text(c, u.decl) == name)
      ++n;
  return n;
}

}  // namespace

TEST_CASE("name uses: each resolved name points at its declaration, in its own file or another", "[name_uses]") {
  MemoryFileSystem fs = files();
  pipeline::FrontEndOptions options;
  options.record_name_uses = true;
  pipeline::Compilation c(options);
  REQUIRE(c.front_end("blink.sfc", fs));
  CHECK(uses_of(c, "led_on", "io.iface") == 1);
  CHECK(uses_of(c, "ready", "io.iface") == 1);
  CHECK(uses_of(c, "On", "blink.sfc") == 2);     // both transitions
  CHECK(uses_of(c, "count", "blink.sfc") == 3);  // assigned, read, compared
  // The declarations are there too, each its own declaration.
  int declarations = 0;
  for (const NameUse &u : c.name_uses.list)
    if (u.declaration() && text(c, u.at) == "Blink") {
      ++declarations;
      CHECK(u.kind == validation::Sym::Chart);
    }
  CHECK(declarations == 1);
  // NameUses::at finds the name over an offset, its end included; of() lists a declaration's uses.
  const SourceFile &main = c.sources.file(c.model.main_file);
  const std::uint32_t led = static_cast<std::uint32_t>(main.text().find("led_on"));
  const NameUse *at = c.name_uses.at(c.model.main_file, led + 6);
  REQUIRE(at);
  CHECK(text(c, at->decl) == "led_on");
  CHECK(c.name_uses.of(at->decl).size() == 2);  // the declaration and the call
}

TEST_CASE("name uses: a test block's chart, functions and places are uses", "[name_uses]") {
  MemoryFileSystem fs = files();
  pipeline::FrontEndOptions options;
  options.record_name_uses = true;
  pipeline::Compilation c(options);
  REQUIRE(c.front_end("blink.test", fs));
  CHECK(uses_of(c, "Blink", "blink.sfc") >= 1);
  CHECK(uses_of(c, "ready", "io.iface") >= 1);
  bool on_in_test = false;
  for (const NameUse &u : c.name_uses.list)
    if (!u.declaration() && text(c, u.at) == "On" && c.sources.file(u.at.file).path() == "blink.test")
      on_in_test = true;
  CHECK(on_in_test);
}

TEST_CASE("name uses: nothing is recorded unless asked for, and an unknown name never", "[name_uses]") {
  MemoryFileSystem fs = files();
  pipeline::Compilation quiet{pipeline::FrontEndOptions()};
  REQUIRE(quiet.front_end("blink.sfc", fs));
  CHECK(quiet.name_uses.list.empty());

  fs.add("bad.sfc", "sfc Bad {\n  initial place A { }\n  place B { }\n  transition A -> B when nowhere;\n}\n");
  pipeline::FrontEndOptions options;
  options.record_name_uses = true;
  pipeline::Compilation c(options);
  CHECK_FALSE(c.front_end("bad.sfc", fs));
  for (const NameUse &u : c.name_uses.list) CHECK(text(c, u.at) != "nowhere");
  CHECK(uses_of(c, "B", "bad.sfc") == 1);
}
