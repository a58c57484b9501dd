// textDocument/codeLens on a `.test` file (features/code_lenses.h) and workspace/executeCommand
// for its command, gfec.runTest [uri, name]: `gfec test FILE --filter NAME` on the saved file,
// whose result ({passed, exitCode, output}) is the command's result and a window/showMessage.
#include "code_lenses.h"

#include "methods.h"
#include "uri.h"

namespace gfec::lsp::handlers {

using nlohmann::json;

namespace {

/// How long one test run may take, in seconds (a chart's harness is compiled and run).
constexpr double kTestTimeLimit = 300;

bool is_test_file(const std::string &path) { return path.size() > 5 && path.compare(path.size() - 5, 5, ".test") == 0; }

}  // namespace

void advertise_code_lens(json &caps) {
  caps["codeLensProvider"] = {{"resolveProvider", false}};
  caps["executeCommandProvider"] = {{"commands", {kRunTestCommand}}};
}

json code_lens(Session &s, const json &params) {
  const std::string uri = document_uri(params);
  const Document &doc = s.open_document(uri);
  if (!is_test_file(doc.path)) return json::array();
  return lsp::code_lenses(doc.text, uri);
}

json execute_command(Session &s, const json &params) {
  const std::string command = params.at("command").get<std::string>();
  if (command != kRunTestCommand) throw RequestError{error_code::kInvalidParams, "no command '" + command + "'"};
  const json &args = params.at("arguments");
  const std::string uri = args.at(0).get<std::string>(), name = args.at(1).get<std::string>();
  json result = run_test_command(path_of_uri(uri), name, kTestTimeLimit);
  s.notify("window/showMessage", {{"type", result["passed"].get<bool>() ? 3 : 1},
                                  {"message", std::string("gfec test: \"") + name +
                                                  (result["passed"].get<bool>() ? "\" passed" : "\" failed")}});
  return result;
}

}  // namespace gfec::lsp::handlers
