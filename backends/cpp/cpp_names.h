// How the C++ back ends spell the model in C++: types, names that C++ would not accept, and the
// toolbox contract's fixed names (the header a toolbox's classes live in, the environment type).
// The wiring and the skeleton both use these, so that what one refers to the other declares.
#pragma once

#include "naming/naming.h"
#include "code_writer.h"
#include "model.h"

#include <set>
#include <string>
#include <vector>

namespace gfec::cpp_backend {

/// The C++ type of a parameter or config entry: "int", "float", "std::string", "afp::Object".
const char *cpp_type(model::Type type);

/// `afp::Type::Float`: the runtime's name of a type.
std::string afp_type(model::Type type);

/// A word generated C++ cannot use as a name (compiler/naming/: C and C++ keywords, the names of
/// the standard headers the runtime and the engines include).
inline bool is_reserved(const std::string &word) { return naming::is_reserved(word); }

/// A chart name as a C++ identifier: reserved words take a trailing `_` (`delete` -> `delete_`).
/// Template classes, their states and events, and toolbox environments are all spelled so.
std::string identifier(const std::string &name);

/// The class implementing a template: the template's name.
std::string class_name(const model::Template &t);

/// A state or event of a template, as its enum constant.
std::string outcome_name(const model::Template &t, int outcome);

/// The toolbox's execution environment type, which every constructor takes first: the
/// toolbox's name (toolbox Carbot -> `Carbot`).
std::string environment_type(const model::Toolbox &box);

/// The header declaring a toolbox's classes and environment: its name in lower case plus
/// `_toolbox.h` (toolbox Carbot -> "carbot_toolbox.h").
std::string toolbox_header(const model::Toolbox &box);

/// `std::chrono::milliseconds(10)`: a supervisor's period as a chrono value, exact to the
/// nanosecond.
std::string chrono_period(double ms);

/// Identifiers unique within one C++ scope: the naming policy's name space.
using naming::NameSpace;

/// The names inside a template's class in the skeleton: constructor parameters and the members
/// that keep them. Usually `ee`/`ee_` and `distance`/`distance_`; a parameter called like
/// something else of the class (`ctx`, an enum constant, `ee`) takes a trailing `_`.
struct MemberNames {
  std::string env_param, env_member;
  std::vector<std::string> param, member;  ///< by template parameter
};
MemberNames member_names(const model::Template &t);

/// `actor Forward(in float distance) -> FORWARD_OK;`: the template as the toolbox declares it.
std::string template_signature(const model::Template &t);

/// The first line of every generated file: the tool, the input and what was compiled; no date,
/// so the same input gives the same bytes.
std::string banner(const std::string &source_name, const std::string &what);

/// `#pragma once` is not standard; generated headers use a guard derived from their file name.
std::string include_guard(const std::string &header_base);

/// A preprocessor line at column 0, whatever the indentation.
void directive(CodeWriter &w, const std::string &text);

}  // namespace gfec::cpp_backend
