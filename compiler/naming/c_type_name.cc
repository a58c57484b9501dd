#include "c_type_name.h"

#include <cctype>
#include <utility>

namespace gfec::naming {

namespace {

bool word_char(char ch) { return std::isalnum(static_cast<unsigned char>(ch)) || ch == '_'; }

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
  out = std::move(t);
  return {};
}

}  // namespace gfec::naming
