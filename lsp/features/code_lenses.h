// textDocument/codeLens on a `.test` file: a "Run test" lens on each scenario test, whose
// command (kRunTestCommand, arguments [uri, test name]) runs `gfec test FILE --filter NAME`.
// Found from the compiler's tokens (`test "NAME"`), so the lenses stay while the file is broken.
#pragma once

#include <nlohmann/json.hpp>

#include <string>
#include <string_view>

namespace gfec::lsp {

/// The command id a lens carries; a client runs it itself or sends workspace/executeCommand.
inline constexpr const char *kRunTestCommand = "gfec.runTest";

nlohmann::json code_lenses(std::string_view text, const std::string &uri);

/// The outcome of kRunTestCommand: runs `gfec test PATH --filter NAME` (the running executable's
/// own gfec) and returns {passed, exitCode, output}; `output` is what it printed.
nlohmann::json run_test_command(const std::string &path, const std::string &name, double time_limit);

}  // namespace gfec::lsp
