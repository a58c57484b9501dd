// gfec: the command-line compiler. Reads the options and hands them to the driver, which runs
// lexer -> parser -> validator -> model -> back end and decides the exit code.
#include "driver.h"
#include "run_command.h"
#include "test_command.h"

#include <iostream>
#include <string_view>

int main(int argc, char **argv) {
  // `gfec run CHART ...`: the reference interpreter (run_command.h).
  if (argc > 1 && std::string_view(argv[1]) == "run")
    return gfec::run_command(argc - 1, argv + 1, std::cout, std::cerr);
  // `gfec test FILE...`: scenario tests on the interpreter and the C engine (test_command.h).
  if (argc > 1 && std::string_view(argv[1]) == "test")
    return gfec::test_command(argc - 1, argv + 1, std::cout, std::cerr);
  gfec::ParsedCommandLine cl = gfec::parse_command_line(argc, argv);
  if (cl.exit_now) {
    (cl.exit_code == 0 ? std::cout : std::cerr) << cl.message;
    return cl.exit_code;
  }
  return gfec::run(cl.options, std::cout, std::cerr);
}
