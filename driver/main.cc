// gfec: the command-line compiler. Runs the command the arguments name (commands.h): the
// compiler itself (lexer -> parser -> validator -> model -> back end, driver.h), `gfec run`,
// `gfec test`, ...; the command decides the exit code.
#include "commands.h"

#include <iostream>

int main(int argc, char **argv) { return gfec::dispatch(argc, argv, std::cout, std::cerr); }
