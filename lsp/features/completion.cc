#include "completion.h"

#include "lexed_text.h"

#include <algorithm>
#include <filesystem>
#include <set>
#include <vector>

namespace gfec::lsp {

namespace {

// LSP's CompletionItemKind.
enum ItemKind {
  kFunction = 3,
  kVariable = 6,
  kClass = 7,
  kKeyword = 14,
  kFile = 17,
  kFolder = 19,
  kEnumMember = 20,
  kConstant = 21,
  kTypeParameter = 25
};

/// What an open brace opened.
enum class Scope { Chart, Place, Block, Interface, Toolbox, Plan, Test, Other };

struct Frame {
  Scope scope;
  std::string chart;  ///< Scope::Chart: its name
};

/// The tokens before the cursor, the brace frames open there and the current statement.
struct Where {
  std::vector<Frame> frames;
  std::vector<const Token *> statement;  ///< since the last `;` `{` `}`, before the cursor
  const Token *inside = nullptr;         ///< the token the cursor is in or at the end of
  const Token *before_statement = nullptr;
};

Where locate(const LexedText &lexed, std::uint32_t offset) {
  Where w;
  std::vector<const Token *> statement;
  for (const Token &t : lexed.tokens) {
    if (t.range.begin >= offset) break;
    if (t.range.end >= offset && (t.kind == Tok::Ident || is_keyword(t.kind) || t.kind == Tok::String ||
                                  t.kind == Tok::Error || t.kind == Tok::Int)) {
      w.inside = &t;  // the word being typed: the prefix, not the context
      break;
    }
    if (t.kind == Tok::LBrace) {
      Frame f{Scope::Other, {}};
      if (!statement.empty()) {
        Tok first = statement.front()->kind;
        if (first == Tok::KwSfc || first == Tok::KwFsm) {
          f.scope = Scope::Chart;
          if (statement.size() > 1) f.chart = std::string(statement[1]->text);
        } else if (first == Tok::KwPlace || first == Tok::KwState || first == Tok::KwInitial ||
                   first == Tok::KwSuccess || first == Tok::KwFailure) {
          f.scope = Scope::Place;
        } else if (first == Tok::KwEntry || first == Tok::KwExit || first == Tok::KwIf || first == Tok::KwElse) {
          f.scope = Scope::Block;
        } else if (first == Tok::KwInterface) {
          f.scope = Scope::Interface;
        } else if (first == Tok::KwToolbox) {
          f.scope = Scope::Toolbox;
        } else if (first == Tok::KwPlan) {
          f.scope = Scope::Plan;
        } else if (first == Tok::KwTest) {
          f.scope = Scope::Test;
          // `test "NAME" of CHART`: the chart whose inputs a `set` may name.
          for (std::size_t k = 0; k + 1 < statement.size(); ++k)
            if (statement[k]->text == "of" && statement[k + 1]->kind == Tok::Ident)
              f.chart = std::string(statement[k + 1]->text);
        }
      } else if (w.before_statement && w.before_statement->kind == Tok::RBrace) {
        f.scope = Scope::Block;  // `} else {` reads as a statement of its own
      }
      w.frames.push_back(std::move(f));
      statement.clear();
      w.before_statement = &t;
      continue;
    }
    if (t.kind == Tok::RBrace) {
      if (!w.frames.empty()) w.frames.pop_back();
      statement.clear();
      w.before_statement = &t;
      continue;
    }
    if (t.kind == Tok::Semi) {
      statement.clear();
      w.before_statement = &t;
      continue;
    }
    statement.push_back(&t);
  }
  w.statement = std::move(statement);
  return w;
}

bool has(const std::vector<const Token *> &s, Tok kind) {
  return std::any_of(s.begin(), s.end(), [&](const Token *t) { return t->kind == kind; });
}

/// Whether the statement's last open parenthesis follows one of the built-ins that take a place.
bool in_place_call(const std::vector<const Token *> &s) {
  int depth = 0;
  for (std::size_t i = s.size(); i-- > 0;) {
    if (s[i]->kind == Tok::RParen) ++depth;
    if (s[i]->kind == Tok::LParen && depth-- == 0) {
      if (i == 0) return false;
      std::string_view f = s[i - 1]->text;
      return f == "elapsed" || f == "active" || f == "succeeded" || f == "failed";
    }
  }
  return false;
}

/// Inside `if (` ... before its `)`.
bool in_if_condition(const std::vector<const Token *> &s) {
  int depth = 0;
  bool after_if = false;
  for (const Token *t : s) {
    if (t->kind == Tok::KwIf) after_if = true, depth = 0;
    else if (t->kind == Tok::LParen) ++depth;
    else if (t->kind == Tok::RParen) --depth;
  }
  return after_if && depth > 0;
}

CompletionContext classify(const Where &w) {
  if (w.inside && (w.inside->kind == Tok::String ||
                   (w.inside->kind == Tok::Error && !w.inside->text.empty() && w.inside->text.front() == '"')))
    return w.statement.size() == 1 && w.statement[0]->kind == Tok::KwImport ? CompletionContext::Import
                                                                            : CompletionContext::None;
  const auto &s = w.statement;
  const Scope scope = w.frames.empty() ? Scope::Other : w.frames.back().scope;
  const Tok last = s.empty() ? Tok::End : s.back()->kind;
  if (in_place_call(s)) return CompletionContext::PlaceList;
  if (last == Tok::KwVar || last == Tok::KwConst || last == Tok::KwIn || last == Tok::KwOut || last == Tok::KwInOut ||
      last == Tok::KwConfig)
    return CompletionContext::Types;
  if (last == Tok::KwRuns) return CompletionContext::Charts;
  if (w.frames.empty()) return s.empty() ? CompletionContext::TopLevel : CompletionContext::None;
  switch (scope) {
  case Scope::Chart:
    if (s.empty()) return CompletionContext::ChartItem;
    if (has(s, Tok::KwWhen) || has(s, Tok::KwPost)) return CompletionContext::Condition;
    if (s.front()->kind == Tok::KwTransition || has(s, Tok::Arrow)) return CompletionContext::PlaceList;
    if (s.front()->kind == Tok::Ident && s.size() == 1) return CompletionContext::PlaceList;
    if (has(s, Tok::Assign)) return CompletionContext::Condition;  // a var's initial value
    return CompletionContext::None;
  case Scope::Place:
  case Scope::Block:
    if (s.empty()) return CompletionContext::Statement;
    if (in_if_condition(s) || has(s, Tok::Assign) || has(s, Tok::PlusAssign) || has(s, Tok::MinusAssign) ||
        has(s, Tok::KwPost) || has(s, Tok::LParen))
      return CompletionContext::Condition;
    return CompletionContext::None;
  case Scope::Test:
    if (s.empty()) return CompletionContext::TestStep;
    if (s.size() == 1 && s.front()->text == "set") return CompletionContext::TestSet;
    return CompletionContext::Condition;
  default: return CompletionContext::None;
  }
}

/// The names completion offers, gathered once per request.
struct Names {
  std::set<std::string> value_functions, action_functions, consts, vars, places, charts;
  std::set<std::string> inputs;  ///< the chart's `in` and `inout` variables: what a test may set

  void from_tree(const ast::Program &p, const std::string &chart) {
    for (const auto &file : p.files) {
      for (const ast::Interface &i : file->interfaces)
        for (const ast::FunctionDecl &f : i.functions)
          (f.result.text == "void" ? action_functions : value_functions).insert(std::string(f.name.text));
      for (const ast::ValueDecl &c : file->consts) consts.insert(std::string(c.name.text));
      for (const ast::Chart &c : file->charts) {
        charts.insert(std::string(c.name.text));
        if (c.name.text != chart) continue;
        for (const ast::Place &pl : c.places) places.insert(std::string(pl.name.text));
        for (const ast::ValueDecl &v : c.values) {
          (v.is_const ? consts : vars).insert(std::string(v.name.text));
          if (!v.is_const && (v.role == ast::VarRole::In || v.role == ast::VarRole::InOut))
            inputs.insert(std::string(v.name.text));
        }
      }
    }
  }

  /// The declarations of the text as it is now, which the last tree may not have yet.
  void from_tokens(const LexedText &lexed, const std::string &chart) {
    std::string current;
    int depth = 0, chart_depth = -1;
    const auto &t = lexed.tokens;
    for (std::size_t i = 0; i < t.size(); ++i) {
      if (t[i].kind == Tok::LBrace) ++depth;
      if (t[i].kind == Tok::RBrace && --depth == chart_depth) current.clear(), chart_depth = -1;
      if (i + 1 >= t.size() || t[i + 1].kind != Tok::Ident) continue;
      const std::string name(t[i + 1].text);
      if (t[i].kind == Tok::KwSfc || t[i].kind == Tok::KwFsm) {
        charts.insert(name);
        current = name, chart_depth = depth;
      } else if ((t[i].kind == Tok::KwPlace || t[i].kind == Tok::KwState) && current == chart) {
        places.insert(name);
      } else if (i > 0 && t[i].kind == Tok::Ident) {
        const Tok role = t[i - 1].kind;  // `var TYPE NAME`, `in TYPE NAME`, ...
        if (role == Tok::KwConst) consts.insert(name);
        if (current != chart) continue;
        if (role == Tok::KwVar || role == Tok::KwIn || role == Tok::KwOut || role == Tok::KwInOut) vars.insert(name);
        if (role == Tok::KwIn || role == Tok::KwInOut) inputs.insert(name);
      }
    }
  }
};

const char *const kTopLevel[] = {"import", "sfc", "fsm", "plan", "toolbox", "interface", "const", "test"};
const char *const kChartItems[] = {"place",  "state", "initial", "transition", "var",   "const",
                                   "period", "team",  "success", "failure",    "entry", "exit"};
const char *const kStatements[] = {"if", "else", "while", "do", "for", "break", "return", "entry", "exit"};
const char *const kTestSteps[] = {"tick", "set", "expect", "agent"};
const char *const kTypes[] = {"bool",  "int",   "float", "double", "string", "time",  "int8",
                              "int16", "int64", "uint8", "uint16", "uint32", "uint64"};
const char *const kPlaceBuiltins[] = {"elapsed", "active", "succeeded", "failed"};

bool chart_file(const std::filesystem::path &p) {
  const std::string ext = p.extension().string();
  return ext == ".sfc" || ext == ".fsm" || ext == ".plan" || ext == ".toolbox" || ext == ".iface";
}

}  // namespace

CompletionContext completion_context(std::string_view text, std::uint32_t offset) {
  const LexedText lexed = lex_text(text);
  return classify(locate(lexed, offset));
}

nlohmann::json completion(std::string_view text, std::uint32_t offset, const ast::Program *program,
                          const std::string &directory) {
  const LexedText lexed = lex_text(text);
  const Where w = locate(lexed, offset);
  const CompletionContext context = classify(w);
  std::string chart;
  for (const Frame &f : w.frames)
    if (f.scope == Scope::Chart || f.scope == Scope::Test) chart = f.chart;
  Names names;
  if (program) names.from_tree(*program, chart);
  names.from_tokens(lexed, chart);

  nlohmann::json items = nlohmann::json::array();
  std::set<std::string> seen;
  auto add = [&](const std::string &label, int kind, const char *detail) {
    if (!seen.insert(label).second) return;
    items.push_back({{"label", label}, {"kind", kind}, {"detail", detail}});
  };
  auto add_all = [&](const std::set<std::string> &set, int kind, const char *detail) {
    for (const std::string &n : set) add(n, kind, detail);
  };
  auto add_words = [&](auto &words, int kind, const char *detail) {
    for (const char *word : words) add(word, kind, detail);
  };
  auto values = [&] {
    add_all(names.vars, kVariable, "var");
    add_all(names.consts, kConstant, "const");
    add_all(names.value_functions, kFunction, "function");
    add_words(kPlaceBuiltins, kFunction, "built-in");
    add("true", kKeyword, "bool");
    add("false", kKeyword, "bool");
  };
  switch (context) {
  case CompletionContext::TopLevel: add_words(kTopLevel, kKeyword, "keyword"); break;
  case CompletionContext::ChartItem:
    add_words(kChartItems, kKeyword, "keyword");
    add_all(names.places, kEnumMember, "place");  // `A -> B;` needs no `transition`
    break;
  case CompletionContext::PlaceList: add_all(names.places, kEnumMember, "place"); break;
  case CompletionContext::Condition: values(); break;
  case CompletionContext::Statement:
    add_words(kStatements, kKeyword, "keyword");
    add_all(names.action_functions, kFunction, "function");
    add_all(names.value_functions, kFunction, "function");
    add_all(names.vars, kVariable, "var");
    break;
  case CompletionContext::Charts: add_all(names.charts, kClass, "chart"); break;
  case CompletionContext::Types: add_words(kTypes, kTypeParameter, "type"); break;
  case CompletionContext::TestStep: add_words(kTestSteps, kKeyword, "keyword"); break;
  case CompletionContext::TestSet:
    add_all(names.inputs, kVariable, "input");
    add_all(names.value_functions, kFunction, "function");
    break;
  case CompletionContext::Import: {
    // The folder of what is typed so far, beside the document.
    std::string typed(w.inside->text.substr(1, offset - w.inside->range.begin - 1));
    std::string sub = typed.substr(0, typed.find_last_of('/') == std::string::npos ? 0 : typed.find_last_of('/') + 1);
    std::error_code ec;
    std::filesystem::path dir = std::filesystem::path(directory.empty() ? "." : directory) / sub;
    std::vector<std::pair<std::string, bool>> found;
    for (auto it = std::filesystem::directory_iterator(dir, ec); !ec && it != std::filesystem::directory_iterator();
         it.increment(ec)) {
      const std::string name = it->path().filename().string();
      if (name.empty() || name[0] == '.') continue;
      bool folder = it->is_directory(ec);
      if (folder || chart_file(it->path())) found.emplace_back(sub + name + (folder ? "/" : ""), folder);
      if (found.size() >= 500) break;  // a huge folder: enough to choose from
    }
    std::sort(found.begin(), found.end());
    for (const auto &[label, folder] : found) add(label, folder ? kFolder : kFile, folder ? "folder" : "file");
    break;
  }
  case CompletionContext::None: break;
  }
  return {{"isIncomplete", false}, {"items", items}};
}

}  // namespace gfec::lsp
