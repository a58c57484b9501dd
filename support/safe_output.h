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

#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

namespace gfec::safe_output {

struct File {
  std::string path;
  std::string contents;
};

/// A set of outputs written as they are produced, without holding them in memory: each open()
/// checks its name as write_all does and creates the temporary; commit() closes them all and
/// renames them into place. A refused name, a failed write or a transaction destroyed without
/// commit() removes every temporary, and no output has changed.
class Transaction {
public:
  /// `never_overwrite`: as for write_all.
  explicit Transaction(std::vector<std::string> never_overwrite);
  ~Transaction();
  Transaction(const Transaction &) = delete;
  Transaction &operator=(const Transaction &) = delete;

  /// The stream writing the temporary of `path`, valid until commit() or destruction; null when
  /// `path` is refused or an earlier step failed (error() says why).
  std::ostream *open(const std::string &path);
  /// Renames every output into place, or none: "" on success, else the first failure.
  std::string commit();
  /// The first failure so far ("" if none).
  const std::string &error() const { return error_; }

private:
  struct Output;
  struct State;
  void fail(const std::string &why);

  std::vector<std::string> never_overwrite_;
  std::unique_ptr<State> state_;
  std::vector<std::unique_ptr<Output>> outputs_;
  std::string error_;
  bool committed_ = false;
};

/// The mkostemp pattern of the temporary beside `path`: `NAME.gfec-tmp-XXXXXX`, NAME cut (at a
/// character's boundary) where the whole would pass 255 bytes.
std::string temporary_pattern(const std::string &path);

/// Writes every file or none. `never_overwrite` are files read by this run (the inputs and
/// imports): an output that is one of them (same device and inode, also through symlinks or
/// hard links) is refused. On failure returns a message naming the file and the reason, and
/// nothing has been written; otherwise an empty string.
std::string write_all(const std::vector<File> &files, const std::vector<std::string> &never_overwrite);

}  // namespace gfec::safe_output
