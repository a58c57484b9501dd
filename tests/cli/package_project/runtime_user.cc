// Links against gfec::runtime and uses it through its installed headers.
#include <afp/afp.h>

#include <iostream>

int main() {
  afp::Configuration config;
  config.declare("walldist", afp::Value(30.0f));
  config.set("walldist", afp::Value(42));
  std::cout << "walldist=" << config.get<float>("walldist") << "\n";
  return 0;
}
