// The concrete back ends by name, with what the driver and the option parser need to know
// about each: the one place that knows them all. The driver, --help, --emit's checks and their
// messages read this table; nothing else names a back end (docs/architecture.md).
#pragma once

#include "backend.h"
#include "backend_option_group.h"
#include "pipeline/kind.h"

#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace gfec {

struct BackendInfo {
  const char *name;        ///< as --emit spells it
  unsigned accepts;        ///< what it compiles: pipeline::Kind bits
  const char *extension;   ///< the primary output's, for the name derived from the input (".c")
  const char *companions;  ///< outputs written beside the primary one ("" when none), for --help
  const char *summary;     ///< one line for --help
  const char *help;        ///< where to read more: the docs page
  std::unique_ptr<Backend> (*make)();
  /// Its own command-line options (the C engine's --context, --context-type, --names), or null.
  /// Every group is declared on the command line; giving one for another back end is an error.
  std::unique_ptr<BackendOptionGroup> (*option_group)() = nullptr;

  bool accepts_kind(unsigned kind) const { return (accepts & kind) != 0; }
  /// Writes only its primary output (so `-o -` can send it to stdout).
  bool single_file() const { return companions[0] == '\0'; }
};

/// Every back end, in the order --help lists them.
const std::vector<BackendInfo> &backends();
/// The back end called `name`, or null.
const BackendInfo *find_backend(std::string_view name);
/// The back end used when --emit is not given, for what is compiled (one pipeline::Kind bit): the C
/// engine for an sfc or fsm, the C++ wiring for a plan, the skeleton for a toolbox.
const BackendInfo &default_backend(unsigned kind);
/// "c, cpp, json, ...": for messages.
std::string backend_names_list();
/// The back ends' lines of --help.
std::string backends_help();
/// "sfc and fsm", "sfc, fsm and plan": what `b` compiles, for messages.
std::string accepted_kinds(const BackendInfo &b);

/// A back end's option group as one command line filled it.
struct BackendOptionsGiven {
  const BackendInfo *backend;
  std::shared_ptr<BackendOptionGroup> group;
};
/// Declares every back end's option group on `app`, in the table's order (parse_command_line).
std::vector<BackendOptionsGiven> add_backend_options(CLI::App &app);

/// The back end called `name`, or null (a new instance).
std::unique_ptr<Backend> make_backend(std::string_view name);

}  // namespace gfec
