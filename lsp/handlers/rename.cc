// textDocument/prepareRename and textDocument/rename: the name at the cursor and every place
// its declaration is written (occurrences.h: other files too, open or not). A keyword, a
// built-in function or a place with no resolved name is refused with a RequestFailed error;
// a new name that is not an identifier (or is a keyword or built-in) with InvalidParams.
#include "handlers/navigation.h"
#include "lexer.h"
#include "methods.h"
#include "occurrences.h"

namespace gfec::lsp::handlers {

using nlohmann::json;

namespace {

/// The name at the request's position; a RequestError when there is none to rename.
At renamable(Session &s, const json &params) {
  At at = name_at_request(s, params);
  if (!at.name) throw no_name_error(at.doc, at.doc.offset_at(read_position(params.at("position"))), "renamed");
  if (is_builtin(at.doc.text_of(at.name->at)))
    throw RequestError{error_code::kRequestFailed, "a built-in function cannot be renamed"};
  return at;
}

/// Throws unless `name` is one identifier token of chart text that may be declared.
void check_new_name(const std::string &name) {
  SourceManager sources;
  Diagnostics diag;
  FileId file = sources.add("<new name>", name);
  Lexer lexer(sources, file, diag);
  Token first = lexer.next();
  const bool one_token = lexer.next().kind == Tok::End && !diag.has_errors();
  if (first.kind == Tok::Ident && one_token && first.text.size() == name.size()) {
    if (is_builtin(name))
      throw RequestError{error_code::kInvalidParams, "'" + name + "' is a built-in function: choose another name"};
    return;
  }
  if (one_token && first.kind != Tok::Ident && !name.empty() && std::isalpha(static_cast<unsigned char>(name[0])))
    throw RequestError{error_code::kInvalidParams, "'" + name + "' is a keyword: choose another name"};
  throw RequestError{error_code::kInvalidParams, "'" + name + "' is not a name (letters, digits and '_')"};
}

}  // namespace

json prepare_rename(Session &s, const json &params) {
  At at = renamable(s, params);
  return {{"range", at.doc.range(at.name->at)}, {"placeholder", std::string(at.doc.text_of(at.name->at))}};
}

json rename(Session &s, const json &params) {
  const std::string new_name = params.at("newName").get<std::string>();
  At at = renamable(s, params);
  check_new_name(new_name);
  const std::string old_name(at.doc.text_of(at.name->at));
  json changes = json::object();
  for (const Occurrence &o : occurrences(s, key_of(at.doc, at.name->decl), old_name)) {
    if (!changes.contains(o.uri)) changes[o.uri] = json::array();
    changes[o.uri].push_back({{"range", o.range}, {"newText", new_name}});
  }
  return {{"changes", changes}};
}

void advertise_rename(json &caps) { caps["renameProvider"] = {{"prepareProvider", true}}; }

}  // namespace gfec::lsp::handlers
