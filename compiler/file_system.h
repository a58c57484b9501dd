// The file system behind an interface, so the loader's tests run in memory (as ninja does) and a
// language server reads its editor's unsaved buffers over the disk (OverlayFileSystem).
#pragma once

#include <atomic>
#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace gfec {

/// How far FileSystem::walk goes: a reader searching for a file below a folder must stay fast
/// beside a huge tree.
struct WalkLimits {
  int max_depth = 5;                ///< folders below the one walked that are entered
  std::size_t max_entries = 20000;  ///< entries (files and folders) looked at, at most
  bool skip_hidden = true;          ///< folders whose name begins with '.' (.git) are not entered
};

/// How much RealFileSystem reads (docs/security.md, "Special files and sizes"). The largest chart
/// gfec is measured on (a million places, docs/performance.md) is about 90 MB; beyond these a
/// file is refused before it is read, or as soon as reading passes the limit (a file that grows,
/// or one of a pseudo file system whose size says 0), never read on to the end.
struct ReadLimits {
  std::size_t max_file = std::size_t{128} << 20;   ///< bytes of one file
  std::size_t max_total = std::size_t{256} << 20;  ///< bytes of every file one file system reads
};

/// A file's text, or why there is none ("no such file", "it is a folder", ...): FileSystem::read.
/// It reads like the optional it wraps (`if (auto text = fs.read(p)) use(*text)`).
struct FileText {
  std::optional<std::string> text;
  std::string why;  ///< set when there is no text

  explicit operator bool() const { return text.has_value(); }
  std::string &operator*() { return *text; }
  const std::string &operator*() const { return *text; }
  const std::string *operator->() const { return &*text; }
};

class FileSystem {
public:
  virtual ~FileSystem() = default;
  /// The whole file, or why it cannot be read.
  virtual FileText read(const std::string &path) const = 0;
  /// The names of the files in a folder (for did-you-mean on imports); none if unreadable.
  virtual std::vector<std::string> list(const std::string &dir) const = 0;
  /// Every file below `dir`, in its sub-folders too, within `limits`: paths that begin with
  /// `dir` ("" and "." list relative paths), normalised, with '/', sorted.
  std::vector<std::string> walk(const std::string &dir, const WalkLimits &limits = WalkLimits()) const {
    return walk_files(dir, limits);
  }
  /// What makes two paths the same file (device and inode), or nothing if it cannot tell:
  /// "/src/a.iface" and "link/a.iface" through a symlinked folder are one file, read once.
  virtual std::optional<std::string> identity(const std::string &path) const {
    (void)path;
    return std::nullopt;
  }

protected:
  virtual std::vector<std::string> walk_files(const std::string &dir, const WalkLimits &limits) const = 0;
};

/// The disk. It reads only regular files of ordinary file systems, within its ReadLimits: never a
/// device, FIFO or socket (one could block gfec or never end), nor a file of /proc, /sys or the
/// kernel's other pseudo file systems (/proc/kmsg blocks and consumes the kernel's log; a size
/// of 0 there says nothing), and never waits in open() or read().
class RealFileSystem : public FileSystem {
public:
  explicit RealFileSystem(ReadLimits limits = ReadLimits()) : limits_(limits) {}
  FileText read(const std::string &path) const override;
  std::vector<std::string> list(const std::string &dir) const override;
  std::optional<std::string> identity(const std::string &path) const override;

protected:
  std::vector<std::string> walk_files(const std::string &dir, const WalkLimits &limits) const override;

private:
  ReadLimits limits_;
  mutable std::atomic<std::size_t> total_{0};  ///< bytes read so far (gfec test reads in threads)
};

/// `path` lexically normal, with '/', no trailing '/' ("a/./b/" is "a/b", "" is "."): how the
/// file systems and the readers that search folders compare paths.
std::string normal_path(const std::string &path);

/// "cannot read 'x.sfc': no such file", for a path a file system refused with `why`
/// (FileText::why); the path is escaped for printing.
std::string cannot_read(const std::string &path, const std::string &why);

class MemoryFileSystem : public FileSystem {
public:
  void add(std::string path, std::string text) { files_[std::move(path)] = std::move(text); }
  FileText read(const std::string &path) const override;
  std::vector<std::string> list(const std::string &dir) const override;

protected:
  std::vector<std::string> walk_files(const std::string &dir, const WalkLimits &limits) const override;

private:
  std::map<std::string, std::string> files_;
};

/// Open editor buffers over another file system (the disk): what a language server compiles.
/// A path with a buffer open reads as the buffer, saved or not; every other path reads through.
/// Paths are compared normalised ("a/./b.sfc" is "a/b.sfc").
class OverlayFileSystem : public FileSystem {
public:
  explicit OverlayFileSystem(const FileSystem &base) : base_(base) {}
  /// Opens or replaces the buffer of `path`.
  void open(const std::string &path, std::string text);
  /// Closes the buffer of `path`: it reads from the file system below again.
  void close(const std::string &path);

  FileText read(const std::string &path) const override;
  /// The folder's files below and its buffers, a name once.
  std::vector<std::string> list(const std::string &dir) const override;
  /// The file below's, when it has one: a buffer of a file on disk is that file.
  std::optional<std::string> identity(const std::string &path) const override;

protected:
  std::vector<std::string> walk_files(const std::string &dir, const WalkLimits &limits) const override;

private:
  const FileSystem &base_;
  std::map<std::string, std::string> buffers_;  ///< normalised path -> text
};

}  // namespace gfec
