// Conversions between configuration types, as docs/runtime.md 3 and docs/language.md §8 define them.
#include <afp/value.h>

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <string>

using afp::ConversionError;
using afp::convert;
using afp::Type;
using afp::Value;

TEST_CASE("a value knows its type - text literals are strings, not bools", "[value]") {
  CHECK(Value(1).type() == Type::Int);
  CHECK(Value(1.5f).type() == Type::Float);
  CHECK(Value(1.5).type() == Type::Double);
  CHECK(Value(true).type() == Type::Bool);
  CHECK(Value("text").type() == Type::String);
  CHECK(Value(afp::Object()).type() == Type::Object);
  CHECK(Value() == Value(0));
}

TEST_CASE("numbers convert among themselves as in C", "[value]") {
  CHECK(convert<float>(Value(3)) == 3.0f);
  CHECK(convert<double>(Value(2.5f)) == 2.5);
  CHECK(convert<int>(Value(2.7f)) == 2);
  CHECK(convert<int>(Value(-2.7)) == -2);
  CHECK(convert<float>(Value(0.1)) == 0.1f);
}

TEST_CASE("a float that no int can hold does not convert to int", "[value]") {
  CHECK_THROWS_AS(convert<int>(Value(1e20)), ConversionError);
  CHECK_THROWS_AS(convert<int>(Value(std::nan(""))), ConversionError);
  CHECK_THROWS_AS(convert<int>(Value(std::numeric_limits<float>::infinity())), ConversionError);
}

TEST_CASE("a number becomes its shortest decimal text", "[value]") {
  CHECK(convert<std::string>(Value(42)) == "42");
  CHECK(convert<std::string>(Value(-7)) == "-7");
  CHECK(convert<std::string>(Value(30.0f)) == "30");
  CHECK(convert<std::string>(Value(0.1f)) == "0.1");
  CHECK(convert<std::string>(Value(2.5)) == "2.5");
}

TEST_CASE("a string becomes a number when its whole text is a number", "[value]") {
  CHECK(convert<int>(Value("12")) == 12);
  CHECK(convert<int>(Value("-12")) == -12);
  CHECK(convert<int>(Value("+4")) == 4);
  CHECK(convert<int>(Value("2.9")) == 2);
  CHECK(convert<float>(Value(" 3.5 ")) == 3.5f);
  CHECK(convert<double>(Value("1e-3")) == 1e-3);
  CHECK(convert<double>(Value(".5")) == 0.5);
}

TEST_CASE("a string that is not a number does not convert to one", "[value]") {
  for (const char* text : {"abc", "12abc", "", "  ", "nan", "inf", "-", "+", "1 2", "0x10"}) {
    INFO("text: '" << text << "'");
    CHECK_THROWS_AS(convert<float>(Value(text)), ConversionError);
    CHECK_THROWS_AS(convert<int>(Value(text)), ConversionError);
  }
  CHECK_THROWS_WITH(convert<float>(Value("abc")), "cannot convert string \"abc\" to float: not a number");
}

TEST_CASE("bool converts only to and from its words", "[value]") {
  CHECK(convert<std::string>(Value(true)) == "true");
  CHECK(convert<bool>(Value("false")) == false);
  CHECK_THROWS_AS(convert<bool>(Value("yes")), ConversionError);
  CHECK_THROWS_AS(convert<int>(Value(true)), ConversionError);
  CHECK_THROWS_AS(convert<bool>(Value(1)), ConversionError);
}

TEST_CASE("objects keep their type and convert to nothing else", "[value]") {
  afp::Object obj = afp::make_object<std::string>("map");
  REQUIRE(obj.get<std::string>() != nullptr);
  CHECK(*obj.get<std::string>() == "map");
  CHECK(obj.get<int>() == nullptr);
  CHECK(convert<afp::Object>(Value(obj)) == obj);
  CHECK_THROWS_AS(convert<std::string>(Value(obj)), ConversionError);
  CHECK_THROWS_AS(convert<afp::Object>(Value(1)), ConversionError);
  CHECK_FALSE(afp::Object());
}

TEST_CASE("each type has a C-like default value", "[value]") {
  CHECK(afp::default_value(Type::Int) == Value(0));
  CHECK(afp::default_value(Type::Float) == Value(0.0f));
  CHECK(afp::default_value(Type::Double) == Value(0.0));
  CHECK(afp::default_value(Type::Bool) == Value(false));
  CHECK(afp::default_value(Type::String) == Value(""));
  CHECK(afp::default_value(Type::Object) == Value(afp::Object()));
}
