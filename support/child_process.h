// Running a tool (dot, the C compiler, gfec, a test harness) as a child process that cannot
// outlive the run that started it (docs/security.md, "Child processes and signals").
//
// Every child is started without a shell in a process group of its own (POSIX_SPAWN_SETPGROUP),
// so that stopping it stops what it started too (cc's cc1, as and ld), and is registered until
// it has been reaped. A time limit, a signal taken by the waiting thread, or stop_all() from a
// signal-watching thread ends the whole group: SIGTERM first, so that a compiler driver removes
// its temporary files, then SIGKILL after a short grace. After stop_all() no new child starts.
//
// What this cannot promise: a SIGKILL of the parent itself leaves its children running (they
// are in their own groups); the caller's callers kill process groups, not just pids, for that.
//
// Self-contained (POSIX and the standard library only) so carbot-sim builds it on its own.
#pragma once

#include <string>
#include <vector>

namespace gfec::child_process {

struct Spawn {
  std::vector<std::string> argv;  ///< argv[0] is looked up on PATH
  std::string stdin_path;         ///< "" = inherited
  std::string stdout_path;        ///< "" = inherited (or stdout_fd)
  std::string stderr_path;        ///< "" = inherited; "&1" = wherever stdout goes
  int stdout_fd = -1;             ///< a pipe's write end for stdout, or -1 (closed in the child otherwise)
  double time_limit = 0;          ///< seconds of wall-clock time; 0 = none
  /// The calling thread has SIGINT, SIGTERM and SIGHUP blocked and no other thread waits for
  /// them: one arriving while the child runs stops the child and ends the wait (Result::signal).
  bool take_signals = false;
};

struct Result {
  enum class How { Exited, Killed, NotStarted, TimedOut, Interrupted };
  How how = How::NotStarted;
  int code = 0;       ///< Exited: the exit status; Killed: the signal
  int signal = 0;     ///< Interrupted: the signal taken (for the caller to re-raise)
  std::string error;  ///< NotStarted: why
  bool ok() const { return how == How::Exited && code == 0; }
};

/// Starts `spawn.argv` in its own process group; returns its pid, or -1 with `error` set. The
/// child gets an empty signal mask (its parent may block signals in every thread).
int start(const Spawn &spawn, std::string &error);

/// Waits for a child start() returned, within `time_limit` seconds (0: none), taking SIGINT,
/// SIGTERM and SIGHUP if `take_signals`. A child past its limit or interrupted is stopped
/// (its group: SIGTERM, then SIGKILL) and reaped before this returns.
Result wait(int pid, double time_limit = 0, bool take_signals = false);

/// start() then wait().
Result run(const Spawn &spawn);

/// Stops every registered child's process group (SIGTERM, up to `grace` seconds for them to
/// go, then SIGKILL) and refuses to start any more. For a thread that has taken a signal, or a
/// watchdog; not async-signal-safe (it takes a lock).
void stop_all(double grace = 1.0);

/// "failed: exited with status 2", "was killed by signal 9 (Killed)", ... for messages.
std::string describe(const Result &result);

}  // namespace gfec::child_process
