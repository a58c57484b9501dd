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

TEST_CASE("naming: each scope's prefix sees the outer names added since an earlier scope's", "[naming]") {
  // The C back end reserves the prefix once per sub-chart instance, in a new scope inside the
  // file's names, which grow in between: what an earlier reservation read must not hide the
  // names added after it, here or outside.
  NameSpace globals;
  globals.claim("gfec_tx");
  NameSpace first(&globals);
  CHECK(first.reserve_numbered_prefix("gfec_t") == "gfec_t");
  globals.claim("gfec_t12");
  NameSpace second(&globals);
  CHECK(second.reserve_numbered_prefix("gfec_t") == "gfec_t_");
  globals.claim("gfec_t_3");
  NameSpace third(&globals);
  CHECK(third.reserve_numbered_prefix("gfec_t") == "gfec_t__");
  // A scope's own names count too, and the first scope's prefix stays what it was.
  NameSpace fourth(&globals);
  fourth.claim("gfec_t__0");
  CHECK(fourth.reserve_numbered_prefix("gfec_t") == "gfec_t___");
  CHECK(first.take("gfec_t9") == "gfec_t9_");
}

TEST_CASE("naming: the compilers' names, the GNU modes' macros and main are reserved", "[naming]") {
  CHECK(reserved("__LINE__") == Reserved::Implementation);  // a predefined macro
  CHECK(reserved("__func__") == Reserved::Implementation);
  CHECK(reserved("_Exit") == Reserved::Implementation);
  CHECK(reserved("_Pragma") == Reserved::Implementation);
  CHECK(reserved("_lower") == Reserved::None);  // only at file scope in C, and no compiler minds
  CHECK(reserved("_") == Reserved::None);
  CHECK(reserved("linux") == Reserved::Predefined);
  CHECK(reserved("unix") == Reserved::Predefined);
  CHECK(reserved("main") == Reserved::EntryPoint);
  CHECK(reserved("EBUSY") == Reserved::CppLibrary);  // <cerrno>
  CHECK(reserved("EXIT_FAILURE") == Reserved::CppLibrary);
  CHECK(reserved("afp") == Reserved::CppNamespace);
  // No trailing `_` frees a name of the compilers': a back end's own name gets a `g` first.
  CHECK(unreserved("delete") == "delete_");
  CHECK(unreserved("__x") == "g__x");
  CHECK(unreserved("Motor") == "Motor");
  CHECK(unreserved("FLT_MAX") == "FLT_MAX_x");  // <float.h>: FLT_ and any capitals and '_'
  NameSpace names;
  CHECK(names.take("__init") == "g__init");
  CHECK(names.take("FLT_MAX") == "FLT_MAX_x");  // a chart FLT's place MAX: it once looped for ever
  CHECK(names.take("FLT_MAX") == "FLT_MAX_x_");
}

TEST_CASE("naming: the C headers' families of names, read without <regex>", "[naming]") {
  for (const char *w :
       {"int8_t", "uint64_t", "int_least16_t", "uint_fast32_t", "INT8_MAX", "UINT64_C", "INT_LEAST8_MIN",
        "UINT_FAST16_MAX", "INTPTR_MIN", "UINTMAX_MAX", "INTMAX_C", "INT_MAX", "UINT_MAX", "FLT_EPSILON",
        "DBL_MAX_10_EXP", "LDBL_DIG", "LLONG_MIN", "UCHAR_MAX", "SHRT_MIN"}) {
    INFO(w);
    CHECK(reserved(w) == Reserved::CLibrary);
  }
  for (const char *w : {"int_t", "int8", "uint8_tx", "int_least_t", "INT8", "INT8_MAXX", "INT_LEAST_MAX", "INTPTR",
                        "FLT_", "FLT_x", "Int8_t", "int8_T", "INT_C", "interface", "INTERRUPT", "DBLX"}) {
    INFO(w);
    CHECK(reserved(w) == Reserved::None);
  }
}

TEST_CASE("naming: the engine's names for its caller, by chart", "[naming]") {
  CHECK(engine_name("P", "P_init") != nullptr);
  CHECK(engine_name("P", "P_PLACE_COUNT") != nullptr);
  CHECK(engine_name("P_A", "P_A_run") != nullptr);
  CHECK(engine_name("P", "P_set_agent")->team);
  CHECK_FALSE(engine_name("P", "P_instance")->always);  // only an engine with sub-charts has it
  CHECK(engine_name("P", "P_lowest") == nullptr);       // the scalable form's own helper moves aside
  CHECK(engine_name("P", "Q_init") == nullptr);
  CHECK(engine_name("P", "Pinit") == nullptr);
  CHECK(engine_name("P", "P_") == nullptr);
}

TEST_CASE("naming: the C library's functions, as gcc and clang know them", "[naming]") {
  const CFunction *fabs = c_library_function("fabs");
  REQUIRE(fabs != nullptr);
  CHECK(fabs->builtin);
  CHECK(fabs->iso);
  CHECK(c_declaration(*fabs) == "double fabs(double)");
  CHECK(matches(*fabs, "double", {"double"}));
  CHECK_FALSE(matches(*fabs, "float", {"float"}));
  CHECK_FALSE(matches(*fabs, "double", {}));
  // No prototype (a type-generic macro of <math.h>): int and double parameters match it.
  const CFunction *isnan = c_library_function("isnan");
  REQUIRE(isnan != nullptr);
  CHECK(matches(*isnan, "int", {"double"}));
  CHECK(matches(*isnan, "int", {"int", "double"}));
  CHECK_FALSE(matches(*isnan, "int", {"float"}));
  CHECK_FALSE(matches(*isnan, "bool", {"double"}));
  // Nothing gfec can write is printf's.
  const CFunction *printf = c_library_function("printf");
  REQUIRE(printf != nullptr);
  CHECK_FALSE(matches(*printf, "int", {}));
  CHECK(c_library_function("Motor") == nullptr);
  // In C++ the classes of a toolbox share the global namespace with ISO C's names.
  CHECK(is_c_library_global("time"));  // no built-in, but ISO C's
  CHECK(is_c_library_global("FILE"));
  CHECK_FALSE(is_c_library_global("sqrtf128"));  // a GNU built-in, not ISO C's
  CHECK_FALSE(is_c_library_global("Forward"));
  CHECK(is_template_member("step"));
  CHECK_FALSE(is_template_member("Actor"));
  CHECK(is_template_scope_name("Actor"));
}
