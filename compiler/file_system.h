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
  /// The names of the files in folder `dir` (no paths, sorted); empty if it cannot be listed.
  /// Only did-you-mean notes use it.
  virtual std::vector<std::string> list(const std::string &dir) const {
    (void)dir;
    return {};
  }
};

class RealFileSystem : public FileSystem {
public:
  std::optional<std::string> read(const std::string &path) const override;
  std::vector<std::string> list(const std::string &dir) const override;
};

class MemoryFileSystem : public FileSystem {
public:
  void add(std::string path, std::string text) { files_[std::move(path)] = std::move(text); }
  std::optional<std::string> read(const std::string &path) const override;
  std::vector<std::string> list(const std::string &dir) const override;

private:
  std::map<std::string, std::string> files_;
};

} // namespace gfec
