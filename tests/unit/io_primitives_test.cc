// The two primitives every byte in and out goes through: RealFileSystem::read, which sizes its
// buffer from fstat but must not trust that size, and CodeWriter, which formats lines in place
// and must still count them for #line.
#include "code_writer.h"
#include "file_system.h"
#include "support.h"

#include <catch2/catch.hpp>

#include <string>

using namespace gfec;
using namespace gfec::test;

TEST_CASE("io: a file is read whole, whatever its size says", "[io]") {
  RealFileSystem fs;
  const std::string dir = scratch_dir("io-read");
  // Around the 64 KiB chunk the reader falls back to when fstat's size runs out.
  for (std::size_t size : {0u, 1u, 65535u, 65536u, 65537u, 300001u}) {
    std::string text(size, '\0');
    for (std::size_t i = 0; i < size; ++i) text[i] = static_cast<char>('a' + (i * 7 + i / 97) % 26);
    const std::string path = dir + "/f" + std::to_string(size);
    write_file(path, text);
    auto got = fs.read(path);
    REQUIRE(got);
    CHECK(got->size() == size);
    CHECK(*got == text);
  }
  // A /proc file says it has 0 bytes and has more: everything is read all the same.
  auto status = fs.read("/proc/self/status");
  REQUIRE(status);
  CHECK(status->find("Name:") == 0);
  CHECK(status->find("VmRSS:") != std::string::npos);
  // Not a regular file, or a read that fails: no text at all, never a short one.
  CHECK(!fs.read("/dev/zero"));
  CHECK(!fs.read("/proc/self/mem"));
  CHECK(!fs.read(dir + "/missing"));
}

TEST_CASE("io: lines formatted in place are indented, counted and end without blanks", "[io]") {
  SourceManager sources;
  CodeWriter w("out.c", true);
  w.line("int {} = {};", "a", 1);
  {
    auto block = w.block("{");
    w.line("{}", "");  // an empty line inside a block: no indentation left behind
    w.line("/* {}\n   {} */", "two", "lines");
    w.blank();
    w.line("x();");
  }
  w.line_back();  // names the line after it: the writer counted every line above
  CHECK(w.text() == "int a = 1;\n"
                    "{\n"
                    "\n"
                    "    /* two\n"
                    "   lines */\n"
                    "\n"
                    "    x();\n"
                    "}\n");
  // line_back() writes nothing until a #line pointed away; point away and back to see the count.
  const FileId file = sources.add("chart.sfc", "sfc S {}\n");
  w.line_from(sources, {file, 0, 0});  // line 9
  w.line("{}", "y();");                // line 10
  w.line_back();                       // line 11, naming line 12
  const std::string tail = "#line 1 \"chart.sfc\"\ny();\n#line 12 \"out.c\"\n";
  REQUIRE(w.text().size() > tail.size());
  CHECK(w.text().substr(w.text().size() - tail.size()) == tail);
}
