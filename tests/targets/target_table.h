// The target table (tests/targets/targets.txt, docs/targets.md): each row a microcontroller the
// generated engines are built for and run on under an emulator. gfec_differential reads it for
// --target; the benchmark scripts read the same file.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace gfec::targets {

struct Target {
  std::string name;
  int double_bits = 64;  ///< 32 where `double` is binary32: a chart's double is refused there
  std::string cc;        ///< the C compiler
  std::string flags;     ///< compile flags (machine, optimisation, FP contraction)
  std::string link;      ///< link-only flags
  std::string support;   ///< the target's side of the program, relative to the table's folder
  std::string run;       ///< the emulator command: {elf}, {bin}
  long ram = 0, flash = 0;

  /// binutils' size for this compiler: `avr-gcc` -> `avr-size`.
  std::string size_tool() const;
  /// The first word of `run`, expanded: what must be installed (or built) to run.
  std::string emulator(const std::map<std::string, std::string> &vars) const;
};

/// The rows of the table in `path`; a malformed row is an error naming its line.
struct Table {
  std::vector<Target> rows;
  std::string folder;  ///< where the table is: support files are relative to it
  std::string error;   ///< empty when the table was read
  const Target *find(const std::string &name) const;
  std::string names() const;  ///< comma-separated, for messages
};
Table read_table(const std::string &path);

/// `text` with every `{key}` of `vars` replaced by its value.
std::string expand(std::string text, const std::map<std::string, std::string> &vars);

}  // namespace gfec::targets
