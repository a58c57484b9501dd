// Writing a set of output files safely, for gfec and carbot-sim alike (docs/security.md):
// only regular files are replaced, never an input, never a special file such as /dev/null or a
// FIFO, never one file twice; each output is first written to a temporary file created beside
// it with an unpredictable name (O_CREAT|O_EXCL, so a planted symlink is never followed), and
// only when every temporary is complete are they renamed into place, one after the other, with
// SIGINT, SIGTERM and SIGHUP held back. Those signals arriving while the temporaries are being
// written remove them before the process dies.
//
// What a kill can leave: SIGKILL (or a crash) while writing leaves temporaries named
// "NAME.gfec-tmp-XXXXXX" beside the outputs and the outputs as they were; between two renames,
// which take microseconds, some outputs new and some old. Two concurrent writers of the same
// outputs each commit a whole set, but the last rename of each output wins.
//
// Self-contained (POSIX and the standard library only) so carbot-sim builds it on its own.
#pragma once

#include <string>
#include <vector>

namespace gfec::safe_output {

struct File {
  std::string path;
  std::string contents;
};

/// Writes every file or none. `never_overwrite` are files read by this run (the inputs and
/// imports): an output that is one of them (same device and inode, also through symlinks or
/// hard links) is refused. On failure returns a message naming the file and the reason, and
/// nothing has been written; otherwise an empty string.
std::string write_all(const std::vector<File> &files, const std::vector<std::string> &never_overwrite);

} // namespace gfec::safe_output
