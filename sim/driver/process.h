// Running a tool (gfec, the C compiler) as a child process: no shell, so no quoting issues.
#pragma once

#include <string>
#include <vector>

namespace carbot::driver {

/// Runs argv[0] with its arguments, stdout and stderr going to ours. Returns the exit status,
/// or -1 if it could not be started or died of a signal (`error` then says why).
int run_process(const std::vector<std::string>& argv, std::string& error);

/// The command line as a person would type it, for messages.
std::string show_command(const std::vector<std::string>& argv);

}  // namespace carbot::driver
