// Reading a file that a careless or hostile command line names (carbot-sim's --world): only a
// regular file, never blocking (a FIFO or a device is refused before any read), and at most a
// given size, so /dev/zero, a named pipe or a huge file is a message, not a hang or gigabytes.
//
// Self-contained (POSIX and the standard library only) so carbot-sim builds it on its own.
#pragma once

#include <cstddef>
#include <string>

namespace gfec::bounded_file {

/// Reads all of `path` into `text` if it is a regular file (also through a symlink) of at most
/// `max_bytes`; else returns false and `error` says why ("not a regular file (a FIFO) ...").
bool read(const std::string &path, std::size_t max_bytes, std::string &text, std::string &error);

}  // namespace gfec::bounded_file
