// Make dependency files, as gcc's -MD/-MF/-MP/-MT/-MQ write them: the outputs depend on the chart
// and on every file it imports, transitively, so make or ninja recompiles a chart when an
// imported interface or toolbox changes.
#pragma once

#include "options.h"

#include <string>
#include <vector>

namespace gfec {

/// The text of the dependency file: "targets: deps" (lines wrapped with " \" as gcc does),
/// then with -MP an empty rule for every dependency but the first (the main file).
/// `targets` are the -MT/-MQ names, or else every output written (quoted); `deps` the main file
/// first, quoted for make.
std::string dependency_rule(const std::vector<DependencyTarget> &targets, const std::vector<std::string> &deps,
                            bool phony);

/// The dependency file's name: -MF, else the primary output with ".d" (gcc's default with -o).
std::string dependency_file_name(const DependencyOptions &deps, const std::string &primary_output);

/// A path as make reads it: spaces, tabs, '#' and ':' escaped with '\\', '$' doubled.
std::string make_escape(const std::string &path);

/// Why make cannot read `path` in a rule whatever the escaping, or "" if it can: control
/// characters (a newline would end the rule and start another, a NUL ends the text), ';' (starts
/// a recipe), '=' (makes the rule a variable assignment), '|' (order-only prerequisites) and
/// '\\' (escapes the separator after it). gfec refuses to write such a dependency file.
std::string make_unreadable(const std::string &path);

}  // namespace gfec
