// The two primitives every byte in and out goes through: RealFileSystem::read, which sizes its
// buffer from fstat but must not trust that size, and CodeWriter, which formats lines in place
// and must still count them for #line.
#include "code_writer.h"
#include "file_system.h"
#include "support.h"

#include <catch2/catch.hpp>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>

#include <sys/stat.h>
#include <unistd.h>

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
  // Not a regular file, or a read that fails: no text at all, never a short one.
  CHECK(fs.read("/dev/zero").why == "not a regular file (a character device); gfec reads no devices, pipes or sockets");
  CHECK(!fs.read(dir + "/missing"));
  CHECK(fs.read(dir + "/missing").why == "no such file");
  CHECK(fs.read(dir).why == "it is a folder");
}

TEST_CASE("io: the kernel's files, FIFOs and files past the limits are refused unread", "[io]") {
  RealFileSystem fs;
  const std::string kernel = "a file of /proc, /sys or another of the kernel's pseudo file systems; gfec reads none";
  // /proc/self/pagemap says 0 bytes and has gigabytes; /proc/kmsg (root only) blocks and takes
  // the kernel's log; /proc/self/status stands in for it: it is never opened, let alone read.
  for (const char *path :
       {"/proc/self/pagemap", "/proc/self/status", "/proc/self/mem", "/sys/kernel/mm/transparent_hugepage/enabled"}) {
    if (!std::filesystem::exists(path)) continue;  // /sys may be missing in a container
    INFO(path);
    auto got = fs.read(path);
    CHECK(!got);
    CHECK(got.why == kernel);
  }
  const std::string dir = scratch_dir("io-limits");
  // Through a symlink too: the checks are on the file it leads to.
  std::filesystem::remove(dir + "/status.sfc");
  std::filesystem::create_symlink("/proc/self/status", dir + "/status.sfc");
  CHECK(fs.read(dir + "/status.sfc").why == kernel);
  // A FIFO with no writer: open() would wait for ever without O_NONBLOCK; refused at once.
  const std::string fifo = dir + "/pipe.sfc";
  std::filesystem::remove(fifo);
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  CHECK(fs.read(fifo).why == "not a regular file (a FIFO); gfec reads no devices, pipes or sockets");

  // The limits, made small: one file, then what one file system reads in all.
  ReadLimits small;
  small.max_file = std::size_t{1} << 20;
  small.max_total = std::size_t{3} << 20;
  RealFileSystem limited(small);
  write_file(dir + "/one.sfc", std::string(small.max_file, 'a'));
  write_file(dir + "/over.sfc", std::string(small.max_file + 1, 'a'));
  CHECK(limited.read(dir + "/one.sfc"));
  CHECK(limited.read(dir + "/over.sfc").why == "larger than 1 MiB, the most gfec reads of one file");
  CHECK(limited.read(dir + "/one.sfc"));
  CHECK(limited.read(dir + "/one.sfc"));
  CHECK(limited.read(dir + "/one.sfc").why ==
        "the files read so far and this one are larger than 3 MiB, the most gfec reads for one input");
  // A sparse file says its size honestly: refused before a byte is read, whatever the default.
  {
    std::FILE *f = std::fopen((dir + "/sparse.sfc").c_str(), "w");
    REQUIRE(f);
    REQUIRE(::ftruncate(::fileno(f), std::int64_t{1} << 34) == 0);
    std::fclose(f);
  }
  CHECK(fs.read(dir + "/sparse.sfc").why == "larger than 128 MiB, the most gfec reads of one file");
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
