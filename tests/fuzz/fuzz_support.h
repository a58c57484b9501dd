// What the fuzz target checks for one input; shared by the libFuzzer target and the replayer.
#pragma once

#include <string>

namespace gfec::fuzz {

/// Runs every stage on `input` and traps (__builtin_trap) if a promise is broken. Returns
/// the diagnostics as gfec prints them (empty: the input validated without a word).
std::string check_one(const std::string &input);

}  // namespace gfec::fuzz
