#include "c_context_type.h"

#include <cctype>
#include <utility>

namespace gfec::c_backend {

ContextType::ContextType(std::string s) : spelling(std::move(s)) {
  std::string word;
  for (char ch : spelling + " ") {
    if (std::isalnum(static_cast<unsigned char>(ch)) || ch == '_') word += ch;
    else if (!word.empty()) words.push_back(std::exchange(word, ""));
  }
  // `const struct motor *`, `struct motor const *`: the word after the keyword is the tag; a
  // bare `struct *` names none.
  for (std::size_t i = 0; i + 1 < words.size(); ++i)
    if (words[i] == "struct" || words[i] == "union") {
      tag_keyword = words[i];
      tag = words[i + 1];
      break;
    }
}

std::string ContextType::param(const std::string &name) const {
  return !spelling.empty() && spelling.back() == '*' ? spelling + name : spelling + " " + name;
}

}  // namespace gfec::c_backend
