#include "semantic_tokens.h"

#include "lexed_text.h"
#include "text_index.h"

#include <algorithm>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace gfec::lsp {

namespace {

// The legend's order is the protocol: a token's type is its index here.
enum Type : std::uint32_t {
  Keyword,
  TypeName,
  Function,
  Variable,
  Parameter,
  EnumMember,
  Class,
  String,
  Number,
  Comment,
  Operator,
  Macro,
  Event
};
const char *const kTypes[] = {"keyword", "type",   "function", "variable", "parameter", "enumMember", "class",
                              "string",  "number", "comment",  "operator", "macro",     "event"};
enum Modifier : std::uint32_t { Declaration = 1, Readonly = 2, DefaultLibrary = 4 };
const char *const kModifiers[] = {"declaration", "readonly", "defaultLibrary"};

bool is_type_word(std::string_view s) {
  for (const char *t : {"bool", "int", "float", "double", "void", "string", "object", "time", "int8", "int16", "int64",
                        "uint8", "uint16", "uint32", "uint64"})
    if (s == t) return true;
  return false;
}

/// Words that are keywords inside a `test` block only (docs/language.md §1), and the `of` and
/// `agents` of its header.
bool is_test_word(std::string_view s) {
  for (const char *t : {"tick", "set", "expect", "called", "calls", "status", "agent", "of", "agents"})
    if (s == t) return true;
  return false;
}

bool is_builtin(std::string_view s) {
  for (const char *t : {"elapsed", "succeeded", "failed", "active", "agent", "team"})
    if (s == t) return true;
  return false;
}

struct NameClass {
  std::uint32_t type;
  std::uint32_t modifiers = 0;
};

/// What a declared name is, per chart (-1: the file's own level) and by spelling.
struct Declarations {
  std::map<std::pair<int, std::string_view>, NameClass> names;

  const NameClass *find(int chart, std::string_view name) const {
    auto it = names.find({chart, name});
    if (it == names.end() && chart >= 0) it = names.find({-1, name});
    return it == names.end() ? nullptr : &it->second;
  }
};

struct Classified {
  std::uint32_t begin, end, type, modifiers;
};

class Classifier {
public:
  explicit Classifier(const LexedText &lexed) : t_(lexed.tokens) {}

  std::vector<Classified> run() {
    scope_pass(true);
    return scope_pass(false);
  }

private:
  Tok kind(std::size_t i) const { return i < t_.size() ? t_[i].kind : Tok::End; }

  /// One walk: the first declares (collecting names by chart), the second classifies every token.
  std::vector<Classified> scope_pass(bool declare) {
    std::vector<Classified> out;
    std::vector<int> stack;  // the chart each open brace belongs to
    int chart = -1, charts = 0;
    int pending_chart = -1;
    bool test_header = false;           // after `test`, before its `{`
    std::size_t test_depth = SIZE_MAX;  // the depth of the open `test` block's brace
    for (std::size_t i = 0; i < t_.size(); ++i) {
      const Token &tok = t_[i];
      const Tok k = tok.kind;
      auto emit = [&](std::uint32_t type, std::uint32_t mods = 0) {
        if (!declare) out.push_back({tok.range.begin, tok.range.end, type, mods});
      };
      if (k == Tok::LBrace) {
        stack.push_back(chart);
        if (pending_chart >= 0) chart = pending_chart, pending_chart = -1;
        if (test_header) test_depth = stack.size(), test_header = false;
        emit(Operator);
        continue;
      }
      if (k == Tok::RBrace) {
        if (stack.size() == test_depth) test_depth = SIZE_MAX;
        if (!stack.empty()) chart = stack.back(), stack.pop_back();
        emit(Operator);
        continue;
      }
      if (k == Tok::KwSfc || k == Tok::KwFsm || k == Tok::KwPlan) pending_chart = charts++;
      if (k == Tok::KwTest) test_header = true;
      if (k == Tok::Ident && (test_header || test_depth != SIZE_MAX) && is_test_word(tok.text) &&
          kind(i + 1) != Tok::LParen) {
        emit(Keyword);
        continue;
      }
      if (is_keyword(k)) {
        emit(Keyword);
        continue;
      }
      switch (k) {
      case Tok::Int:
      case Tok::Float:
      case Tok::Duration: emit(Number); continue;
      case Tok::String: emit(String); continue;
      case Tok::Verbatim: emit(Macro); continue;
      case Tok::Ident: break;
      case Tok::Error: continue;
      default: emit(Operator); continue;
      }
      // An identifier: a declaration by what precedes it, else a use of a declared name.
      const Tok before = i > 0 ? kind(i - 1) : Tok::End;
      const Tok before2 = i > 1 ? kind(i - 2) : Tok::End;
      const bool call = kind(i + 1) == Tok::LParen;
      std::optional<NameClass> decl;
      int scope = chart;
      if (before == Tok::KwSfc || before == Tok::KwFsm || before == Tok::KwPlan || before == Tok::KwToolbox ||
          before == Tok::KwInterface)
        decl = NameClass{Type::Class}, scope = -1;
      else if (before == Tok::KwPlace || before == Tok::KwState) decl = NameClass{EnumMember};
      else if (before == Tok::Ident && (before2 == Tok::KwVar || before2 == Tok::KwConfig)) decl = NameClass{Variable};
      else if (before == Tok::Ident && before2 == Tok::KwConst) decl = NameClass{Variable, Readonly}, scope = chart;
      else if ((before == Tok::KwActor || before == Tok::KwComputation || before == Tok::KwSupervisor ||
                before == Tok::KwSupervise) &&
               kind(i + 1) != Tok::LParen)
        decl = NameClass{Variable};
      else if ((before == Tok::KwActor || before == Tok::KwComputation || before == Tok::KwSupervisor))
        decl = NameClass{Function};
      else if (before == Tok::Ident && is_type_word(t_[i - 1].text) && call)
        decl = NameClass{Function}, scope = -1;  // a prototype in an interface
      else if (before == Tok::Ident && is_type_word(t_[i - 1].text) &&
               (kind(i + 1) == Tok::Comma || kind(i + 1) == Tok::RParen))
        decl = NameClass{Parameter};
      else if ((before == Tok::KwIn || before == Tok::KwOut || before == Tok::KwInOut)) decl = NameClass{TypeName};
      if (decl && decl->type != TypeName) {
        if (declare) names_.names.emplace(std::make_pair(scope, tok.text), *decl);
        emit(decl->type, decl->modifiers | Declaration);
        continue;
      }
      if (is_type_word(tok.text) && !call) {
        emit(TypeName);
        continue;
      }
      if (call) {
        emit(Function, is_builtin(tok.text) ? std::uint32_t{DefaultLibrary} : 0u);
        continue;
      }
      if (const NameClass *c = names_.find(chart, tok.text)) {
        emit(c->type, c->modifiers);
        continue;
      }
      emit(Variable);
    }
    return out;
  }

  const std::vector<Token> &t_;
  Declarations names_;
};

}  // namespace

nlohmann::json semantic_tokens_legend() {
  return {{"tokenTypes", std::vector<std::string>(std::begin(kTypes), std::end(kTypes))},
          {"tokenModifiers", std::vector<std::string>(std::begin(kModifiers), std::end(kModifiers))}};
}

nlohmann::json semantic_tokens(std::string_view text, std::uint32_t begin, std::uint32_t end) {
  LexedText lexed = lex_text(text);
  std::vector<Classified> all = Classifier(lexed).run();
  // Tokens and comments are each in text order already: a merge, not a sort.
  const std::size_t tokens = all.size();
  for (const ByteRange &c : lexed.comments) all.push_back({c.begin, c.end, Comment, 0});
  std::inplace_merge(all.begin(), all.begin() + static_cast<std::ptrdiff_t>(tokens), all.end(),
                     [](const Classified &a, const Classified &b) { return a.begin < b.begin; });

  // LSP's encoding: five numbers a token, line and start relative to the previous token; a
  // token may not span lines, so a block comment or verbatim block is cut at each line end.
  TextIndex index(text);
  std::vector<std::uint32_t> data;
  data.reserve(all.size() * 5);
  std::uint32_t last_line = 0, last_char = 0;
  auto put = [&](Position p, std::uint32_t length, std::uint32_t type, std::uint32_t mods) {
    if (length == 0) return;
    data.push_back(p.line - last_line);
    data.push_back(p.line == last_line ? p.character - last_char : p.character);
    data.push_back(length);
    data.push_back(type);
    data.push_back(mods);
    last_line = p.line, last_char = p.character;
  };
  for (const Classified &c : all) {
    if (c.end <= begin || c.begin >= end) continue;
    Position from = index.position(c.begin), to = index.position(c.end);
    for (std::uint32_t line = from.line; line <= to.line; ++line) {
      std::uint32_t b = line == from.line ? c.begin : index.line_start(line);
      std::uint32_t e = line == to.line ? c.end : index.line_end(line);
      if (e <= b) continue;
      put(line == from.line ? from : Position{line, 0}, utf16_length(text.substr(b, e - b)), c.type, c.modifiers);
    }
  }
  // Built in place: an initializer list would copy the array, a few hundred thousand numbers
  // for a large chart.
  nlohmann::json result = nlohmann::json::object();
  result["data"] = std::move(data);
  return result;
}

}  // namespace gfec::lsp
