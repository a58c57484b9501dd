#include "c_type_name.h"

#include <cctype>
#include <set>
#include <utility>

namespace gfec::naming {

namespace {

bool word_char(char ch) { return std::isalnum(static_cast<unsigned char>(ch)) || ch == '_'; }

bool qualifier(const std::string &w) { return w == "const" || w == "volatile" || w == "restrict"; }

/// C's keywords that are no part of a type name: storage classes, statements, specifiers.
bool other_keyword(const std::string &w) {
  static const std::set<std::string> words = {
      "auto",  "break",    "case",     "continue", "default",  "do",        "else",           "extern",       "for",
      "goto",  "if",       "inline",   "register", "return",   "sizeof",    "static",         "switch",       "typedef",
      "while", "_Alignas", "_Alignof", "_Atomic",  "_Generic", "_Noreturn", "_Static_assert", "_Thread_local"};
  return words.count(w) > 0;
}

/// The engine stores the context in a struct member and assigns it (X_set_context): the type
/// must be a complete object type that can be assigned, or the engine does not compile.
std::string object_type_problem(const CTypeName &t) {
  for (const auto &w : t.words)
    if (other_keyword(w))
      return "'" + w + "' is not part of a type name: the context type is a type (e.g. 'struct motor *')";
  const std::size_t star = t.spelling.rfind('*');
  const bool pointer = star != std::string::npos;
  // The words after the last '*' (all of them without one) qualify or name the stored type.
  std::vector<std::string> top;
  if (pointer) {
    std::string rest = t.spelling.substr(star + 1), word;
    for (char ch : rest + " ")
      if (word_char(ch)) word += ch;
      else if (!word.empty()) top.push_back(std::exchange(word, ""));
    if (t.spelling.find_first_not_of(" *") == std::string::npos || t.spelling.find_first_not_of(" *") > star)
      return "a C type name needs a type before '*' (e.g. 'struct motor *')";
  } else {
    top = t.words;
  }
  for (const auto &w : top) {
    if (pointer && !qualifier(w)) return "a C type name has no words after its last '*' but qualifiers";
    // const: not assignable; volatile and restrict: the getter's return type would carry
    // them (-Wignored-qualifiers), and restrict qualifies only pointers.
    if (qualifier(w))
      return "the engine stores, assigns and returns its context: the type cannot be '" + w +
             "' itself (a pointer to one, 'const T *', can)";
  }
  for (std::size_t i = 0; i < t.words.size(); ++i) {
    const std::string &w = t.words[i];
    if ((w == "struct" || w == "union" || w == "enum") &&
        (i + 1 == t.words.size() || qualifier(t.words[i + 1]) || t.spelling.find(w + " *") != std::string::npos))
      return "'" + w + "' needs its tag (e.g. '" + w + " motor *')";
  }
  if (!pointer) {
    bool named = false;
    for (const auto &w : t.words) named = named || !qualifier(w);
    if (!named) return "a C type name needs a type, not only qualifiers (e.g. 'struct motor *')";
    if (t.words.size() == 1 && t.words[0] == "void") return "'void' has no values: a context of no type is 'void *'";
  }
  return {};
}

}  // namespace

std::string read_c_type_name(const std::string &text, CTypeName &out) {
  CTypeName t;
  std::string word;
  bool space = false;  // a space since the last word or star
  for (char ch : text + " ") {
    if (word_char(ch)) {
      word += ch;
      continue;
    }
    if (!word.empty()) {
      if (std::isdigit(static_cast<unsigned char>(word.front()))) return "a C type name begins with a letter";
      if (!t.spelling.empty() && (space || t.spelling.back() != '*')) t.spelling += ' ';  // `void *const`
      t.spelling += word;
      t.words.push_back(std::exchange(word, ""));
      space = false;
    }
    if (ch == ' ') {
      space = true;
    } else if (ch == '*') {
      if (!t.spelling.empty() && (space || t.spelling.back() != '*')) t.spelling += ' ';
      t.spelling += '*';
      space = false;
    } else {
      return "a C type name is words and '*' only (e.g. 'void *', 'struct motor *')";
    }
  }
  if (t.words.empty()) return "a C type name needs a word (e.g. 'struct motor *')";
  if (std::string why = object_type_problem(t); !why.empty()) return why;
  out = std::move(t);
  return {};
}

}  // namespace gfec::naming
