// Catch2 v2's main is slow to compile: it lives here once and every test executable links it.
#define CATCH_CONFIG_MAIN
#include <catch2/catch.hpp>
