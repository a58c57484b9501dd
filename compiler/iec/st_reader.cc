// The structure of an ST file: POUs with their variable sections and textual SFC (steps with
// their action associations, transitions, actions), and configurations with resources, tasks
// and program instances. Expressions and statement lists are st_expressions.cc's and
// st_statements.cc's; what gfec does not read yet is a located "not supported yet" error.
#include "iec/st_parser.h"
#include "iec/iec_text.h"
#include "iec/st_reader.h"
#include "iec/lower.h"

#include <fmt/format.h>

#include <cctype>
#include <cstdint>

namespace gfec::iec {

namespace {

bool qualifier(const std::string &q) {
  for (const char *k : {"N", "R", "S", "L", "D", "P", "P0", "P1", "SD", "DS", "SL"})
    if (q == k) return true;
  return false;
}

}  // namespace

// ------------------------------------------------------------------ the file

void StParser::file(Project &project) {
  while (!at_end()) {
    resync();
    const StToken t = tok();
    if (is_keyword(t, "PROGRAM")) {
      pou(project, PouKind::Program, "END_PROGRAM");
    } else if (is_keyword(t, "FUNCTION_BLOCK")) {
      pou(project, PouKind::FunctionBlock, "END_FUNCTION_BLOCK");
    } else if (is_keyword(t, "FUNCTION")) {
      pou(project, PouKind::Function, "END_FUNCTION");
    } else if (is_keyword(t, "CONFIGURATION")) {
      configuration(project);
    } else if (is_keyword(t, "TYPE")) {
      type_section(project);
    } else if (is_keyword(t, "VAR_GLOBAL")) {
      // Outside a CONFIGURATION, as CODESYS's global variable lists are exported: read as a
      // configuration's (docs/iec.md "Global variables").
      global_section(project);
    } else if (is_keyword(t, "USING")) {
      not_supported(range(t), "'USING' (IEC 61131-3 third edition namespaces) is not supported yet");
      skip_statement();
    } else if (is_keyword(t, "NAMESPACE") || is_keyword(t, "CLASS") || is_keyword(t, "INTERFACE")) {
      not_supported(range(t), fmt::format("'{}' (IEC 61131-3 third edition) is not supported yet", t.text));
      skip_block(upper(t.text));
    } else {
      error(range(t),
            fmt::format("expected 'PROGRAM', 'FUNCTION_BLOCK', 'FUNCTION' or 'CONFIGURATION', not {}", quoted()));
      // On to the next declaration that can begin a file's element.
      next();
      while (!at_end() && !keyword("PROGRAM") && !keyword("FUNCTION_BLOCK") && !keyword("FUNCTION") &&
             !keyword("CONFIGURATION") && !keyword("TYPE"))
        next();
    }
  }
}

bool StParser::var_section_start(const StToken &t) const {
  return t.kind == StTok::Ident && upper(t.text).rfind("VAR", 0) == 0 && !is_keyword(t, "VAR_X");
}

void StParser::close_pou(Pou &p, const StToken &start, std::string_view end) {
  p.range = range(start, tok());
  if (at_end()) {
    error(range(start), fmt::format("'{}' without its '{}'", start.text, end));
    return;
  }
  next();
}

void StParser::pou(Project &project, PouKind kind, std::string_view end) {
  const StToken start = tok();
  next();
  if (tok().kind != StTok::Ident) {
    error(range(tok()),
          fmt::format("expected the name of the {} after '{}', not {}", start.text, start.text, quoted()));
    skip_block(upper(start.text));
    return;
  }
  Pou &p = project.pous.emplace_back();
  p.kind = kind;
  p.name = name(tok());
  next();
  if (kind == PouKind::FunctionBlock) return function_block(p, start, end);
  if (kind != PouKind::Program) {
    // Reported by the lowering at its name; its body is not read, so that nothing in it adds
    // errors of its own.
    while (!at_end() && !keyword(end)) next();
    p.range = range(start, tok());
    if (!at_end()) next();
    return;
  }
  bool sfc = false;
  while (!at_end() && !keyword(end)) {
    resync();
    const std::size_t before = pos_;
    const StToken t = tok();
    if (var_section_start(t)) {
      var_section(p);
    } else if (is_keyword(t, "INITIAL_STEP") || is_keyword(t, "STEP")) {
      sfc = true;
      step(p, is_keyword(t, "INITIAL_STEP"));
    } else if (is_keyword(t, "TRANSITION")) {
      sfc = true;
      transition(p);
    } else if (is_keyword(t, "ACTION")) {
      action(p);
    } else if (is_keyword(t, "END_PROGRAM") || is_keyword(t, "END_FUNCTION_BLOCK") || is_keyword(t, "END_FUNCTION")) {
      error(range(t), fmt::format("'{}' closes no '{}'; expected '{}'", t.text, t.text.substr(4), end));
      next();
    } else if (!sfc && !p.body) {
      // A body of statements: a chart of one step that runs them every scan (lower.cc).
      p.body = statements();
      p.body_range = range(t);
    } else {
      error(range(t), fmt::format("expected a step, transition or action of the SFC, not {}", quoted()));
      skip_statement();
    }
    if (pos_ == before) next();  // never loop on a token nothing consumed
  }
  close_pou(p, start, end);
}

void StParser::function_block(Pou &p, const StToken &start, std::string_view end) {
  while (!at_end() && !keyword(end)) {
    resync();
    const std::size_t before = pos_;
    const StToken t = tok();
    if (var_section_start(t)) {
      var_section(p);
    } else if (is_keyword(t, "INITIAL_STEP") || is_keyword(t, "STEP")) {
      // An SFC body (docs/iec.md "SFC inside actions and function blocks"); statements beside it
      // are the lowering's to refuse, as a program's are.
      step(p, is_keyword(t, "INITIAL_STEP"));
    } else if (is_keyword(t, "TRANSITION")) {
      transition(p);
    } else if (is_keyword(t, "ACTION")) {
      action(p);
    } else if (block_end()) {
      error(range(t),
            fmt::format("expected a statement of function block '{}' or '{}', not {}", p.name.text, end, quoted()));
      next();
    } else {
      ast::Block b = statements();
      if (!p.body) {
        p.body.emplace();
        p.body_range = range(t);
      }
      for (ast::Stmt &s : b) p.body->push_back(std::move(s));
    }
    if (pos_ == before) next();
  }
  close_pou(p, start, end);
}

// ------------------------------------------------------------------ variables

void StParser::var_section(Pou &pou, std::optional<Section> given) {
  const StToken kw = tok();
  const std::string k = upper(kw.text);
  next();
  Section section = Section::Local;
  if (given) section = *given;
  else if (k == "VAR_INPUT") section = Section::Input;
  else if (k == "VAR_OUTPUT") section = Section::Output;
  else if (k == "VAR") section = Section::Local;
  else if (k == "VAR_EXTERNAL") section = Section::External;
  else if (k == "VAR_IN_OUT") section = Section::InOut;
  else {
    not_supported(range(kw), fmt::format("'{}' sections are not supported yet: gfec reads VAR_INPUT, VAR_OUTPUT, "
                                         "VAR_IN_OUT, VAR and VAR_EXTERNAL",
                                         kw.text));
    skip_block("VAR");
    return;
  }
  bool constant = false;
  while (keyword("CONSTANT") || keyword("RETAIN") || keyword("NON_RETAIN") || keyword("PERSISTENT")) {
    constant = constant || keyword("CONSTANT");
    next();
  }
  while (!at_end() && !keyword("END_VAR")) {
    resync();
    const std::size_t before = pos_;
    if (tok().kind != StTok::Ident || block_end()) {
      error(range(tok()),
            fmt::format("expected a variable declaration ('name : TYPE;') or 'END_VAR', not {}", quoted()));
      if (block_end()) return;
      skip_statement();
    } else {
      declaration(pou, section, constant, "END_VAR");
    }
    if (pos_ == before) next();
  }
  if (keyword("END_VAR")) next();
}

void StParser::global_section(Project &project) {
  // Declared as a POU's variables are (the same declarations), then moved to the file's scope.
  Pou scratch;
  var_section(scratch, Section::Global);
  for (Variable &v : scratch.variables) project.globals.push_back(std::move(v));
}

void StParser::declaration(Pou &pou, Section section, bool constant, std::string_view) {
  std::vector<ast::Name> names{name(tok())};
  const StToken first = tok();
  next();
  while (tok().kind == StTok::Comma && peek().kind == StTok::Ident) {
    next();
    names.push_back(name(tok()));
    next();
  }
  std::optional<SourceRange> located;
  std::string_view address;
  if (keyword("AT")) {
    next();
    if (tok().kind != StTok::Direct) {
      error(range(tok()), fmt::format("expected a direct address after 'AT' ('AT %IX0.0'), not {}", quoted()));
      skip_statement();
      return;
    }
    address = tok().text;
    located = range(tok());
    next();
  }
  if (tok().kind != StTok::Colon) {
    error(range(tok()), fmt::format("expected ':' and the type of '{}', not {}", first.text, quoted()));
    skip_statement();
    return;
  }
  next();
  // The type: one name, or anything up to ':=' or ';' (ARRAY, STRING(20), an enumeration, a
  // subrange), kept whole for the lowering to name as not supported.
  const StToken type_start = tok();
  const std::size_t type_begin = pos_;
  std::size_t type_end = pos_;
  int depth = 0;
  while (!at_end()) {
    StTok k = tok().kind;
    if (depth == 0 && (k == StTok::Assign || k == StTok::Semi)) break;
    if (depth == 0 && block_end()) break;
    if (k == StTok::LParen || k == StTok::LBracket) ++depth;
    if ((k == StTok::RParen || k == StTok::RBracket) && depth > 0) --depth;
    type_end = pos_;
    next();
  }
  if (type_start.kind == StTok::Assign || type_start.kind == StTok::Semi || pos_ == 0) {
    error(range(type_start), fmt::format("expected the type of '{}', not {}", first.text, quoted()));
    skip_statement();
    return;
  }
  const StToken &last = toks_[type_end];
  ast::Name type{text_.substr(type_start.begin, last.end - type_start.begin), range(type_start, last)};
  const std::string t = upper(type.text);
  // An elementary type, or one name (an alias of one, docs/iec.md "Type aliases"; a block's
  // instance, whose initial value the lowering refuses): its initial value is an expression.
  const bool readable = chart_type(t) != nullptr || (type_start.kind == StTok::Ident && type_end == type_begin);
  ast::ExprPtr init;
  if (tok().kind == StTok::Assign) {
    next();
    if (readable && tok().kind == StTok::LParen && peek().kind == StTok::Ident && peek(2).kind == StTok::Assign) {
      // `(PT := T#1s)`: a structure's or an instance's initial members, never silently dropped.
      not_supported(range(tok()), fmt::format("the initial value of '{}' names members ('({} := ...)'): initial "
                                              "values of structures and function-block instances are not supported "
                                              "yet",
                                              first.text, peek().text));
      while (!at_end() && tok().kind != StTok::Semi && !block_end()) next();
    } else if (readable) {
      init = expression();
      if (!init) {
        skip_statement();
        return;
      }
    } else {
      // The lowering reports the type; its initial value (a structure, an array) is not read.
      while (!at_end() && tok().kind != StTok::Semi && !block_end()) next();
    }
  }
  const StToken end = tok();
  if (!expect_semi("the declaration")) {
    skip_statement();
    return;
  }
  for (const ast::Name &n : names) {
    Variable &v = pou.variables.emplace_back();
    v.section = section;
    v.name = n;
    v.type = type;
    v.located = located;
    v.address = address;
    v.constant = constant;
    v.range = n.range.to(range(end));
    if (init) v.init = &n == &names.back() ? std::move(init) : clone(*init);
  }
}

// ------------------------------------------------------------------ the SFC

void StParser::step(Pou &pou, bool initial) {
  const StToken kw = tok();
  next();
  if (tok().kind != StTok::Ident) {
    error(range(tok()), fmt::format("expected the step's name after '{}', not {}", kw.text, quoted()));
    skip_block("STEP");
    return;
  }
  Step &s = pou.steps.emplace_back();
  s.initial = initial;
  s.name = name(tok());
  next();
  if (tok().kind != StTok::Colon) {
    error(range(tok()),
          fmt::format("expected ':' after the step's name ('{} {}:'), not {}", kw.text, s.name.text, quoted()))
        .fix(range(toks_[pos_ - 1]), std::string(s.name.text) + ":");
  } else {
    next();
  }
  for (std::size_t before = SIZE_MAX; !at_end() && !keyword("END_STEP");) {
    if (pos_ == before) next();  // never loop on a token nothing consumed
    if (at_end() || keyword("END_STEP")) break;
    before = pos_;
    resync();
    const StToken a = tok();
    if (a.kind != StTok::Ident || block_end()) {
      error(range(a), fmt::format("expected an action association ('Action(N);') or 'END_STEP', not {}", quoted()));
      if (block_end()) break;
      skip_statement();
      continue;
    }
    next();
    if (tok().kind != StTok::LParen) {
      error(range(tok()),
            fmt::format("expected '(' and the qualifier after '{}' ('{}(N);'), not {}", a.text, a.text, quoted()));
      skip_statement();
      continue;
    }
    const StToken open = tok();
    next();
    ast::Association as;
    as.action = name(a);
    // `a();` has no qualifier: the standard's default is N.
    as.qualifier = {"N", range(a)};
    bool ok = true;
    if (tok().kind == StTok::Ident) {
      const std::string q = upper(tok().text);
      if (!qualifier(q)) {
        error(
            range(tok()),
            fmt::format("'{}' is no action qualifier: IEC's are N, R, S, L, D, P, P0, P1, SD, DS and SL", tok().text));
        ok = false;
      }
      as.qualifier = name(tok());
      next();
    }
    if (ok && tok().kind == StTok::Comma) {
      next();
      if (tok().kind == StTok::Time) {
        if (tok().ms < 0) {
          not_supported(range(tok()), fmt::format("a negative duration ('{}')", tok().text));
          ok = false;
        }
        as.duration_ms = tok().ms;
        as.duration_range = range(tok());
        next();
      } else if (tok().kind == StTok::Ident) {
        not_supported(range(tok()), fmt::format("a duration or an indicator variable ('{}') in an action association "
                                                "is not supported yet: write a TIME literal ('T#2s')",
                                                tok().text));
        ok = false;
      } else {
        error(range(tok()), fmt::format("expected a TIME literal ('T#2s'), not {}", quoted()));
        ok = false;
      }
    }
    if (ok && tok().kind != StTok::RParen) {
      error(range(tok()), fmt::format("expected ')' to close the association, not {}", quoted()))
          .note(range(open), "the '(' it closes");
      ok = false;
    }
    if (!ok) {
      skip_statement();
      continue;
    }
    const StToken close = tok();
    next();
    as.range = range(a, close);
    if (!expect_semi("the action association")) {
      skip_statement();
      continue;
    }
    s.associations.push_back(std::move(as));
  }
  s.range = range(kw, tok());
  if (!keyword("END_STEP")) {
    error(range(tok()), fmt::format("expected 'END_STEP' to close step '{}', not {}", s.name.text, quoted()))
        .note(range(kw), "the step");
    return;
  }
  next();
  if (tok().kind == StTok::Semi) next();
}

std::vector<ast::Name> StParser::step_list(bool &parenthesised) {
  std::vector<ast::Name> out;
  parenthesised = tok().kind == StTok::LParen;
  if (!parenthesised) {
    if (tok().kind == StTok::Ident && !block_end()) {
      out.push_back(name(tok()));
      next();
    } else {
      error(range(tok()), fmt::format("expected a step name, not {}", quoted()));
    }
    return out;
  }
  const StToken open = tok();
  next();
  for (;;) {
    if (tok().kind != StTok::Ident || block_end()) {
      error(range(tok()), fmt::format("expected a step name, not {}", quoted()));
      return {};
    }
    out.push_back(name(tok()));
    next();
    if (tok().kind == StTok::Comma) {
      next();
      continue;
    }
    if (tok().kind == StTok::RParen) {
      next();
      return out;
    }
    error(range(tok()), fmt::format("expected ',' or ')' in the list of steps, not {}", quoted()))
        .note(range(open), "the list");
    return {};
  }
}

void StParser::transition(Pou &pou) {
  const StToken kw = tok();
  next();
  Transition t;
  if (tok().kind == StTok::Ident && !keyword("FROM")) {
    t.name = name(tok());
    next();
  }
  if (tok().kind == StTok::LParen && is_keyword(peek(), "PRIORITY")) {
    next();
    next();
    if (tok().kind == StTok::Assign && peek().kind == StTok::Int && peek(2).kind == StTok::RParen) {
      next();
      t.priority = tok().int_value;
      t.priority_range = range(tok());
      next();
      next();
    } else {
      error(range(tok()), "expected '(PRIORITY := n)' with an integer n");
      skip_block("TRANSITION");
      return;
    }
  }
  if (!keyword("FROM")) {
    error(range(tok()), fmt::format("expected 'FROM' and the steps the transition leaves, not {}", quoted()));
    skip_block("TRANSITION");
    return;
  }
  next();
  t.from = step_list(t.parenthesised_from);
  if (t.from.empty()) {
    skip_block("TRANSITION");
    return;
  }
  if (!keyword("TO")) {
    error(range(tok()), fmt::format("expected 'TO' and the steps the transition enters, not {}", quoted()));
    skip_block("TRANSITION");
    return;
  }
  next();
  t.to = step_list(t.parenthesised_to);
  if (t.to.empty()) {
    skip_block("TRANSITION");
    return;
  }
  if (tok().kind == StTok::Colon) {
    not_supported(range(tok()), "a transition condition in IL, LD or FBD (after ':') is not supported yet: write "
                                "':= condition;' in ST");
    skip_block("TRANSITION");
    return;
  }
  if (tok().kind != StTok::Assign) {
    error(range(tok()), fmt::format("expected ':=' and the transition's condition, not {}", quoted()));
    skip_block("TRANSITION");
    return;
  }
  next();
  t.condition = expression();
  if (!t.condition) {
    skip_block("TRANSITION");
    return;
  }
  if (!expect_semi("the transition's condition")) {
    skip_block("TRANSITION");
    return;
  }
  if (!keyword("END_TRANSITION")) {
    error(range(tok()), fmt::format("expected 'END_TRANSITION', not {}", quoted())).note(range(kw), "the transition");
    skip_block("TRANSITION");
    return;
  }
  t.range = range(kw, tok());
  next();
  if (tok().kind == StTok::Semi) next();
  pou.transitions.push_back(std::move(t));
}

void StParser::action(Pou &pou) {
  const StToken kw = tok();
  next();
  if (tok().kind != StTok::Ident) {
    error(range(tok()), fmt::format("expected the action's name after 'ACTION', not {}", quoted()));
    skip_block("ACTION");
    return;
  }
  Action &a = pou.actions.emplace_back();
  a.name = name(tok());
  next();
  if (tok().kind == StTok::Colon) {
    next();
  } else {
    // A dialect's `ACTION x` (no colon) is not IEC: say so, then read on as if it were there.
    SourceRange at = range(toks_[pos_ - 1]);
    error(at, fmt::format("IEC 61131-3 writes 'ACTION {}:' with a colon after the action's name", a.name.text))
        .fix({at.file, at.end, at.end}, ":");
    resync();
  }
  const std::size_t index = pou.actions.size() - 1;
  if (keyword("INITIAL_STEP") || keyword("STEP") || keyword("TRANSITION")) {
    // An SFC body (docs/iec.md "SFC inside actions and function blocks"): its steps and
    // transitions are the action's; an ACTION declared among them is the POU's, as IEC's
    // grammar lets an SFC declare its actions anywhere in it.
    Pou inner;
    while (!at_end() && !keyword("END_ACTION")) {
      resync();
      const std::size_t before = pos_;
      const StToken t = tok();
      if (is_keyword(t, "INITIAL_STEP") || is_keyword(t, "STEP")) {
        step(inner, is_keyword(t, "INITIAL_STEP"));
      } else if (is_keyword(t, "TRANSITION")) {
        transition(inner);
      } else if (is_keyword(t, "ACTION")) {
        if (deeper(range(t), "actions")) {
          action(inner);
          --depth_;
        } else {
          while (!at_end() && !keyword("END_ACTION")) next();
        }
      } else if (block_end()) {
        break;
      } else {
        error(range(t), fmt::format("expected a step, transition or action of the SFC inside action '{}', not {}",
                                    pou.actions[index].name.text, quoted()));
        skip_statement();
      }
      if (pos_ == before) next();
    }
    pou.actions[index].steps = std::move(inner.steps);
    pou.actions[index].transitions = std::move(inner.transitions);
    for (Action &nested : inner.actions) pou.actions.push_back(std::move(nested));
  } else {
    a.body = statements();
  }
  Action &done = pou.actions[index];
  done.range = range(kw, tok());
  if (!keyword("END_ACTION")) {
    error(range(tok()), fmt::format("expected 'END_ACTION' to close action '{}', not {}", done.name.text, quoted()))
        .note(range(kw), "the action");
    return;
  }
  next();
  if (tok().kind == StTok::Semi) next();
}

// ------------------------------------------------------------------ data types

void StParser::type_section(Project &project) {
  next();
  while (!at_end() && !keyword("END_TYPE")) {
    resync();
    const std::size_t before = pos_;
    if (tok().kind == StTok::Ident && peek().kind == StTok::Colon && peek(2).kind == StTok::Ident &&
        peek(3).kind == StTok::Semi && !is_keyword(peek(2), "STRUCT")) {
      project.aliases.push_back({name(tok()), name(peek(2)), range(tok(), peek(3))});
      for (int k = 0; k < 4; ++k) next();
    } else if (tok().kind == StTok::Ident && peek().kind == StTok::Colon && !block_end()) {
      not_supported(range(tok()), fmt::format("data type '{}': gfec reads a new name of another type ('{} : INT;'); "
                                              "structures, enumerations, arrays, subranges and initial values are "
                                              "not supported yet",
                                              tok().text, tok().text));
      next();
      next();
      if (keyword("STRUCT")) skip_block("STRUCT");
      else skip_statement();
    } else {
      error(range(tok()),
            fmt::format("expected a data type declaration ('Level : INT;') or 'END_TYPE', not {}", quoted()));
      if (block_end() && !keyword("END_TYPE")) return;
      skip_statement();
    }
    if (pos_ == before) next();
  }
  if (keyword("END_TYPE")) next();
  if (tok().kind == StTok::Semi) next();
}

// ------------------------------------------------------------------ configurations

void StParser::configuration(Project &project) {
  const StToken kw = tok();
  next();
  if (tok().kind == StTok::Ident) next();
  resource(project, "END_CONFIGURATION");
  (void)kw;
}

/// The body of a CONFIGURATION or RESOURCE up to `end`: resources, tasks, program instances.
void StParser::resource(Project &project, std::string_view end) {
  while (!at_end() && !keyword(end)) {
    resync();
    const std::size_t before = pos_;
    if (keyword("RESOURCE") && end == "END_CONFIGURATION") {
      next();
      if (tok().kind == StTok::Ident) next();
      if (keyword("ON")) {
        next();
        if (tok().kind == StTok::Ident) next();
      }
      resource(project, "END_RESOURCE");
    } else if (keyword("TASK")) {
      task(project);
    } else if (keyword("PROGRAM")) {
      program_instance(project);
    } else if (keyword("VAR_GLOBAL")) {
      global_section(project);
    } else if (keyword("VAR_ACCESS") || keyword("VAR_CONFIG")) {
      // Access paths for other devices and addresses of `AT %I*` variables: no program reads
      // them (an open address is reported where it is declared).
      skip_block("VAR");
    } else {
      error(range(tok()), fmt::format("expected 'RESOURCE', 'TASK', 'PROGRAM' or '{}', not {}", end, quoted()));
      skip_statement();
    }
    if (pos_ == before) next();
  }
  if (at_end()) {
    error(range(tok()), fmt::format("expected '{}' before the end of the text", end));
    return;
  }
  next();
  if (tok().kind == StTok::Semi) next();
}

void StParser::task(Project &project) {
  const StToken kw = tok();
  next();
  if (tok().kind != StTok::Ident) {
    error(range(tok()), fmt::format("expected the task's name, not {}", quoted()));
    skip_statement();
    return;
  }
  Task t;
  t.name = name(tok());
  next();
  if (tok().kind == StTok::LParen) {
    next();
    while (!at_end() && tok().kind != StTok::RParen) {
      const StToken key = tok();
      if (block_end()) break;
      if (key.kind != StTok::Ident || peek().kind != StTok::Assign) {
        error(range(key), fmt::format("expected 'INTERVAL :=', 'PRIORITY :=' or 'SINGLE :=', not {}", quoted()));
        skip_statement();
        return;
      }
      next();
      next();
      if (is_keyword(key, "INTERVAL")) {
        if (tok().kind == StTok::Time) {
          t.interval_ms = tok().ms;
          t.interval_range = range(tok());
        } else {
          not_supported(range(tok()), "a task INTERVAL that is not a TIME literal is not supported yet");
        }
      }
      next();
      if (tok().kind == StTok::Comma) next();
    }
    if (tok().kind == StTok::RParen) next();
  }
  t.range = range(kw, tok());
  expect_semi("the task");
  project.tasks.push_back(std::move(t));
}

void StParser::program_instance(Project &project) {
  next();  // PROGRAM
  if (keyword("RETAIN") || keyword("NON_RETAIN")) next();
  if (tok().kind != StTok::Ident) {
    error(range(tok()), fmt::format("expected the program instance's name, not {}", quoted()));
    skip_statement();
    return;
  }
  next();
  Task *task = nullptr;
  if (keyword("WITH")) {
    next();
    if (tok().kind == StTok::Ident) {
      const std::string wanted = upper(tok().text);
      for (Task &t : project.tasks)
        if (upper(t.name.text) == wanted) task = &t;
      if (!task)
        error(range(tok()), fmt::format("no TASK named '{}' is declared before", tok().text), ErrorKind::UnknownName);
      next();
    }
  }
  if (tok().kind != StTok::Colon || peek().kind != StTok::Ident) {
    error(range(tok()), fmt::format("expected ':' and the program's type, not {}", quoted()));
    skip_statement();
    return;
  }
  next();
  if (task) task->programs.push_back(name(tok()));
  next();
  skip_statement();  // `(...)` bindings of its variables, then ';'
}

// ------------------------------------------------------------------ entry points

void read_st(std::string_view text, FileId file, std::deque<std::string> &strings, Diagnostics &diag,
             Project &project) {
  FragmentPlace place = FragmentPlace::at(file, 0);
  StParser(text, place, strings, diag).file(project);
}

ast::ExprPtr parse_st_expression(std::string_view text, const FragmentPlace &place, std::deque<std::string> &strings,
                                 Diagnostics &diag) {
  std::size_t errors = diag.error_count();
  StParser p(text, place, strings, diag);
  ast::ExprPtr e = p.expression();
  if (e && !p.at_end()) p.error(p.range(p.tok()), fmt::format("unexpected {} after the expression", p.quoted()));
  if (diag.error_count() != errors) return nullptr;
  return e;
}

std::optional<ast::Block> parse_st_statements(std::string_view text, const FragmentPlace &place,
                                              std::deque<std::string> &strings, Diagnostics &diag) {
  std::size_t errors = diag.error_count();
  StParser p(text, place, strings, diag);
  ast::Block b = p.statements();
  p.resync();
  if (!p.at_end()) p.error(p.range(p.tok()), fmt::format("expected a statement, not {}", p.quoted()));
  if (diag.error_count() != errors) return std::nullopt;
  return b;
}

}  // namespace gfec::iec
