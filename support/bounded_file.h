// Reading a file that a careless or hostile input names (a chart's import, a trace, carbot-sim's
// --world): only a regular file of data — never a folder, a device, a FIFO, a socket or a file of
// the kernel's pseudo file systems (/proc, /sys …), whose sizes lie and whose reads may block,
// consume or act — opened without blocking, and never read past a bound, whatever its size says.
// So /proc/kmsg, /dev/zero, a named pipe or a huge file is a message, not a hang or gigabytes.
//
// Self-contained (POSIX and the standard library only): the compiler and carbot-sim share it.
#pragma once

#include <cstddef>
#include <optional>
#include <string>

namespace gfec::bounded_file {

struct Text {
  std::optional<std::string> text;  ///< the whole file, or nothing
  std::string why;                  ///< why not: "no such file", "it is a folder", …
  bool too_large = false;           ///< why not: more than the bound (`why` is empty; the caller says which bound)
};

/// Reads all of `path` (a symlink is followed: the checks are on the file it leads to) if it is
/// a regular file of data of at most `max_bytes`.
Text read(const std::string &path, std::size_t max_bytes);

/// "4 MiB": a bound as the messages say it.
std::string mib(std::size_t bytes);

}  // namespace gfec::bounded_file
