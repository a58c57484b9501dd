// The configuration: typed entries by name, thread-safe, committed from shadows.
#include <afp/configuration.h>

#include <catch2/catch.hpp>

#include <string>
#include <thread>
#include <vector>

using afp::ConfigError;
using afp::Configuration;
using afp::Type;
using afp::Value;

TEST_CASE("declared entries hold their initial or default value", "[config]") {
  Configuration config;
  config.declare("walldist", Value(30.0f));
  config.declare("wallangle", Type::Float);
  CHECK(config.value("walldist") == Value(30.0f));
  CHECK(config.value("wallangle") == Value(0.0f));
  CHECK(config.type_of("wallangle") == Type::Float);
  CHECK(config.names() == std::vector<std::string>{"wallangle", "walldist"});
}

TEST_CASE("declaring an existing entry keeps the value the application set", "[config]") {
  Configuration config;
  config.declare("walldist", Value(30.0f));
  config.set("walldist", 25);
  config.declare("walldist", Value(30.0f));
  CHECK(config.get<float>("walldist") == 25.0f);
  CHECK_THROWS_AS(config.declare("walldist", Type::Int), ConfigError);
}

TEST_CASE("set converts to the entry's type and leaves it unchanged on failure", "[config]") {
  Configuration config;
  config.declare("n", Type::Int);
  config.set("n", 7.9);
  CHECK(config.value("n") == Value(7));
  config.set("n", "12");
  CHECK(config.value("n") == Value(12));
  CHECK_THROWS_AS(config.set("n", "twelve"), afp::ConversionError);
  CHECK(config.value("n") == Value(12));
  CHECK(config.get<std::string>("n") == "12");
}

TEST_CASE("unknown entries are errors", "[config]") {
  Configuration config;
  CHECK_FALSE(config.contains("x"));
  CHECK_THROWS_WITH(config.value("x"), "unknown configuration entry 'x'");
  CHECK_THROWS_AS(config.set("x", 1), ConfigError);
  CHECK_THROWS_AS(config.type_of("x"), ConfigError);
}

TEST_CASE("a shadow keeps the last write per entry and commits them together", "[config]") {
  Configuration config;
  config.declare("a", Type::Int);
  config.declare("b", Type::Int);
  afp::Shadow shadow;
  shadow.write("a", 1);
  shadow.write("b", 2);
  shadow.write("a", 3);
  REQUIRE(shadow.writes().size() == 2);
  CHECK(config.value("a") == Value(0));  // nothing reaches the configuration before the commit
  config.commit(shadow);
  CHECK(config.value("a") == Value(3));
  CHECK(config.value("b") == Value(2));
  shadow.clear();
  CHECK(shadow.writes().empty());
}

TEST_CASE("the configuration may be read and written from several threads", "[config][threads]") {
  // Under ThreadSanitizer (tests/runtime/tsan.sh) this proves the locking.
  Configuration config;
  config.declare("a", Type::Int);
  config.declare("b", Type::Int);
  std::thread writer([&] {
    for (int i = 1; i <= 2000; ++i) {
      afp::Shadow shadow;
      shadow.write("a", i);
      shadow.write("b", -i);
      config.commit(shadow);
    }
  });
  std::thread setter([&] {
    for (int i = 0; i < 2000; ++i) config.set("b", config.get<int>("b"));
  });
  int last = 0;
  for (int i = 0; i < 2000; ++i) {
    int a = config.get<int>("a");
    CHECK(a >= last);  // commits arrive in order
    last = a;
  }
  writer.join();
  setter.join();
  CHECK(config.get<int>("a") == 2000);
}
