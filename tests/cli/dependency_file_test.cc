// The text of -MD dependency files, as make reads it.
#include "dependency_file.h"

#include <catch2/catch.hpp>

using namespace gfec;

TEST_CASE("dependency file: outputs depend on the chart and its imports, -MP adds empty rules") {
  CHECK(dependency_rule({{"engine.c"}, {"engine.h"}}, {"lf.sfc", "linebot.iface"}, false) ==
        "engine.c engine.h: lf.sfc linebot.iface\n");
  CHECK(dependency_rule({{"engine.c"}}, {"lf.sfc", "a.iface", "b.iface"}, true) ==
        "engine.c: lf.sfc a.iface b.iface\n\na.iface:\n\nb.iface:\n");
  // The main file never gets an empty rule: make must not think it can be made from nothing.
  CHECK(dependency_rule({{"x.c"}}, {"x.sfc"}, true) == "x.c: x.sfc\n");
}

TEST_CASE("dependency file: long lists wrap with backslashes, as gcc's do") {
  std::vector<std::string> deps;
  for (int i = 0; i < 12; ++i) deps.push_back("charts/interface_" + std::to_string(i) + ".iface");
  std::string rule = dependency_rule({{"engine.c"}}, deps, false);
  std::size_t start = 0;
  int lines = 0;
  while (start < rule.size()) {
    std::size_t end = rule.find('\n', start);
    std::string line = rule.substr(start, end - start);
    CHECK(line.size() <= 80);
    bool last = end + 1 == rule.size();
    CHECK((line.back() == '\\') == !last);
    start = end + 1;
    ++lines;
  }
  CHECK(lines > 3);
  // Every dependency is there once the continuations are joined.
  std::string joined;
  for (char c : rule)
    if (c != '\\' && c != '\n') joined += c;
  for (const auto &d : deps) CHECK(joined.find(" " + d) != std::string::npos);
}

TEST_CASE("dependency file: make's special characters are escaped") {
  CHECK(make_escape("my charts/a#1$.sfc") == "my\\ charts/a\\#1$$.sfc");
  CHECK(dependency_rule({{"out dir/e.c"}}, {"a b.sfc"}, false) == "out\\ dir/e.c: a\\ b.sfc\n");
  // gcc's -MT writes the target as given (a make variable stays one), -MQ quotes it.
  CHECK(dependency_rule({{"$(OBJ)/e.c", false}, {"$(OBJ)/e.h", true}}, {"x.sfc"}, false) ==
        "$(OBJ)/e.c $$(OBJ)/e.h: x.sfc\n");
}

TEST_CASE("dependency file: ':' is escaped, what make cannot read in a rule is named") {
  CHECK(make_escape("c:/a b.iface") == "c\\:/a\\ b.iface");
  CHECK(make_unreadable("charts/a#b$c d:e%f.iface") == "");
  CHECK(make_unreadable("e1\nall:touch${IFS}PWNED") == "a newline");
  CHECK(make_unreadable(std::string("a\0b", 3)) == "a NUL character");
  CHECK(make_unreadable("a\rb") == "the control character 0x0d");
  CHECK(make_unreadable("x;touch PWNED") == "';'");
  CHECK(make_unreadable("GFEC=evil") == "'='");
  CHECK(make_unreadable("a|b") == "'|'");
  CHECK(make_unreadable("a\\ b") == "'\\'");
}

TEST_CASE("dependency file: the name is -MF, else the primary output with .d") {
  DependencyOptions o;
  CHECK(dependency_file_name(o, "build/engine.c") == "build/engine.d");
  CHECK(dependency_file_name(o, "engine") == "engine.d");
  o.file = "deps/all.d";
  CHECK(dependency_file_name(o, "build/engine.c") == "deps/all.d");
}
