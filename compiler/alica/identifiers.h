// ALICA names are free text ("Default Name", "MISSING_NAME", "1601278930769"); gfec names are
// identifiers. These turn one into the other the same way every time (docs/alica.md "Names").
#pragma once

#include <set>
#include <string>

namespace gfec::alica {

struct JsonValue;

/// False for a name the ALICA designers write when the user gave none: empty, MISSING_NAME, or
/// digits only (the element's id).
bool meaningful(const std::string &name);

/// An element's name for messages: "" when the designer wrote none (MISSING_NAME, the id).
std::string label_of(const JsonValue &v);

/// `text` as an identifier: every byte that is not a letter, digit or '_' becomes '_' (a run of
/// them one '_'); a leading digit gets 'N' in front; a gfec or C keyword gets '_' appended;
/// empty text gives `fallback`.
std::string identifier(const std::string &text, const std::string &fallback);

/// Hands out identifiers unique within one scope: the first taker keeps the plain name, later
/// ones get "_<id>" appended (and then "_2", "_3", ... if even that is taken).
class NameScope {
public:
  std::string take(const std::string &name, const std::string &id);
  bool taken(const std::string &name) const { return used_.count(name) > 0; }

private:
  std::set<std::string> used_;
};

}  // namespace gfec::alica
