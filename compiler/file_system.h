// The file system behind an interface, so the loader's tests run in memory (as ninja does).
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace gfec {

class FileSystem {
public:
  virtual ~FileSystem() = default;
  /// The whole file, or nothing if it cannot be read.
  virtual std::optional<std::string> read(const std::string &path) const = 0;
  /// The names of the files in a folder (for did-you-mean on imports); none if unreadable.
  virtual std::vector<std::string> list(const std::string &dir) const = 0;
  /// What makes two paths the same file (device and inode), or nothing if it cannot tell:
  /// "/src/a.iface" and "link/a.iface" through a symlinked folder are one file, read once.
  virtual std::optional<std::string> identity(const std::string &path) const {
    (void)path;
    return std::nullopt;
  }
};

class RealFileSystem : public FileSystem {
public:
  std::optional<std::string> read(const std::string &path) const override;
  std::vector<std::string> list(const std::string &dir) const override;
  std::optional<std::string> identity(const std::string &path) const override;
};

/// "cannot read 'x.sfc': no such file", for a path RealFileSystem::read refused: missing, a
/// folder, not a regular file (gfec reads no device, pipe or socket: one could block it or never
/// end, docs/security.md), or not readable.
std::string cannot_read(const std::string &path);
/// Why the file system refuses `path`: cannot_read's reason alone ("no such file", ...).
std::string unreadable_reason(const std::string &path);

class MemoryFileSystem : public FileSystem {
public:
  void add(std::string path, std::string text) { files_[std::move(path)] = std::move(text); }
  std::optional<std::string> read(const std::string &path) const override;
  std::vector<std::string> list(const std::string &dir) const override;

private:
  std::map<std::string, std::string> files_;
};

}  // namespace gfec
