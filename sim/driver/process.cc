#include "driver/process.h"

#include "child_process.h"

namespace carbot::driver {

int run_process(const std::vector<std::string>& argv, std::string& error) {
  // In a process group of its own (support/child_process.h): when the run is stopped (--timeout,
  // SIGINT, SIGTERM, SIGHUP), main.cc's watchdog stops the group, so cc's cc1, as and ld, or
  // gfec and its dot, do not outlive carbot-sim. The child gets an empty signal mask (carbot-sim
  // blocks those signals in its threads) and so stops and cleans up on a signal itself.
  gfec::child_process::Spawn spawn;
  spawn.argv = argv;
  const gfec::child_process::Result r = gfec::child_process::run(spawn);
  using How = gfec::child_process::Result::How;
  if (r.how == How::Exited) return r.code;
  error = r.how == How::NotStarted ? "cannot run " + argv[0] + ": " + r.error
                                   : argv[0] + " " + gfec::child_process::describe(r);
  return -1;
}

std::string show_command(const std::vector<std::string>& argv) {
  std::string line;
  for (const std::string& a : argv) {
    if (!line.empty()) line += ' ';
    const bool plain = !a.empty() && a.find_first_of(" \t'\"\\$") == std::string::npos;
    line += plain ? a : "'" + a + "'";
  }
  return line;
}

}  // namespace carbot::driver
