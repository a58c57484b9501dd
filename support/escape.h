// Text from a chart, a file name or a command line, made safe to print: one escaping for every
// message gfec writes (the diagnostics printer, the ALICA reader's names, the driver's own
// errors). What a file holds reaches the terminal as text, never as a control: no ESC sequence
// that recolours or rewrites the screen, no line break that starts a forged diagnostic, no
// bidirectional override that reorders what is read (Trojan Source).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace gfec::text {

/// One character of a text as it is printed.
struct Shown {
  std::size_t length = 0;  ///< its bytes in the text (at least 1)
  std::string text;        ///< itself, or its escape: <U+001B>, <ff>
  bool escaped = false;
};

/// The character at `s[at]` as gcc's -fdiagnostics-escape-format=unicode shows it: a control
/// character (C0 but the tab and, where `keep_newline`, the newline; DEL; C1) and a
/// bidirectional mark, embedding, override or isolate as <U+XXXX>, a byte that starts no
/// well-formed UTF-8 as <xx>; anything else, UTF-8 included, as itself.
Shown shown_at(std::string_view s, std::size_t at, bool keep_newline = false);

/// `s` with every character as shown_at() shows it.
std::string printable(std::string_view s, bool keep_newlines = false);

}  // namespace gfec::text
