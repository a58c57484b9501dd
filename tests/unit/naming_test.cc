// The naming policy of generated code (compiler/naming/): reserved words and name spaces.
#include "naming/naming.h"

#include <catch2/catch.hpp>

#include <string>

using namespace gfec::naming;

TEST_CASE("naming: one list of reserved words for the validator and both back ends", "[naming]") {
  CHECK(reserved("while") == Reserved::CKeyword);
  CHECK(reserved("_Thread_local") == Reserved::CKeyword);
  CHECK(reserved("class") == Reserved::CppKeyword);
  CHECK(reserved("co_yield") == Reserved::CppKeyword);  // C++20
  CHECK(reserved("char8_t") == Reserved::CppKeyword);   // C++20
  CHECK(reserved("uint16_t") == Reserved::CLibrary);
  CHECK(reserved("INT_MAX") == Reserved::CLibrary);
  CHECK(reserved("memcpy") == Reserved::CLibrary);
  CHECK(reserved("stderr") == Reserved::CppLibrary);
  CHECK(reserved("Motor") == Reserved::None);
  CHECK(reserved("uint16") == Reserved::None);
}

TEST_CASE("naming: a name space hands out free names with a trailing _", "[naming]") {
  NameSpace names;
  names.claim("init");
  CHECK(names.take("init") == "init_");
  CHECK(names.take("init") == "init__");
  CHECK(names.take("delete") == "delete_");  // reserved in C++
  CHECK(names.take("m") == "m");
  CHECK_FALSE(names.free("m"));
}

TEST_CASE("naming: a name space of many names finds each one, claimed twice or not", "[naming]") {
  NameSpace names;
  for (int i = 0; i < 3000; ++i) CHECK(names.take("P" + std::to_string(i)) == "P" + std::to_string(i));
  names.claim("P7");  // already taken: claiming again changes nothing
  for (int i = 0; i < 3000; ++i) CHECK_FALSE(names.free("P" + std::to_string(i)));
  CHECK(names.take("P2999") == "P2999_");
  CHECK(names.free("P3000"));
}

TEST_CASE("naming: a local scope avoids the names of the scope around it", "[naming]") {
  NameSpace globals;
  globals.claim("add");
  NameSpace locals(&globals);
  CHECK(locals.take("add") == "add_");
  CHECK(globals.free("add_"));  // the local does not leak out
}

TEST_CASE("naming: the temporaries' prefix is reserved where names are handed out", "[naming]") {
  NameSpace globals;
  globals.claim("gfec_t1");  // e.g. an interface function of that name
  NameSpace locals(&globals);
  locals.take("gfec_t_");  // not followed by digits: no clash
  CHECK(locals.reserve_numbered_prefix("gfec_t") == "gfec_t_");
  // A name handed out after the prefix was reserved moves aside instead of clashing.
  CHECK(locals.take("gfec_t_7") == "gfec_t_7_");
  CHECK(locals.take("gfec_t_x") == "gfec_t_x");

  NameSpace clean;
  CHECK(clean.reserve_numbered_prefix("gfec_t") == "gfec_t");
}
