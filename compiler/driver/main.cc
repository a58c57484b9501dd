// gfec: the command-line compiler. Reads the options and hands them to the driver, which runs
// lexer -> parser -> validator -> model -> back end and decides the exit code.
#include "driver.h"

#include <iostream>

int main(int argc, char **argv) {
  gfec::ParsedCommandLine cl = gfec::parse_command_line(argc, argv);
  if (cl.exit_now) {
    (cl.exit_code == 0 ? std::cout : std::cerr) << cl.message;
    return cl.exit_code;
  }
  return gfec::run(cl.options, std::cout, std::cerr);
}
