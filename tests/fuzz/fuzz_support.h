// What the fuzz target checks for one input; shared by the libFuzzer target and the replayer.
#pragma once

#include <string>

namespace gfec::fuzz {

/// Runs every stage on `input` and traps (__builtin_trap) if a promise is broken. Returns
/// the diagnostics as gfec prints them (empty: the input validated without a word). `name` is
/// the file's name, whose extension picks the input language (".st": IEC structured text).
std::string check_one(const std::string &input, const std::string &name = "fuzz.sfc");

/// `text` changed by pseudo-random `seed`: cut short, a span deleted or duplicated, bytes
/// replaced; for replaying the inputs of a language the libFuzzer target does not reach.
std::string mutate(const std::string &text, unsigned seed);

}  // namespace gfec::fuzz
