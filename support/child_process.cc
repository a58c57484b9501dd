#include "child_process.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <mutex>
#include <spawn.h>
#include <string>
#include <sys/wait.h>
#include <thread>
#include <time.h>
#include <unistd.h>
#include <vector>

extern char **environ;

namespace gfec::child_process {

namespace {

// The children not yet reaped, each the leader of its own process group. Spawning and
// registering happen under the lock that stop_all() takes, so no child can start unseen.
std::mutex g_mutex;
std::vector<pid_t> g_children;
bool g_stopping = false;

void forget(pid_t pid) {
  std::lock_guard<std::mutex> lock(g_mutex);
  for (auto it = g_children.begin(); it != g_children.end(); ++it)
    if (*it == pid) {
      g_children.erase(it);
      return;
    }
}

double now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

/// True once `pid` has ended (it stays a zombie, so its group id cannot be reused yet).
bool has_ended(pid_t pid) {
  siginfo_t info{};
  return ::waitid(P_PID, static_cast<id_t>(pid), &info, WEXITED | WNOHANG | WNOWAIT) == 0 && info.si_pid == pid;
}

/// SIGTERM to the group, up to `grace` seconds for its leader to end, then SIGKILL to what is
/// left of the group; the leader is not reaped here.
void stop_group(pid_t pid, double grace) {
  ::kill(-pid, SIGTERM);
  const double until = now() + grace;
  while (!has_ended(pid) && now() < until) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  ::kill(-pid, SIGKILL);
}

Result reap(pid_t pid) {
  Result r;
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {}
  forget(pid);
  if (WIFEXITED(status)) {
    r.how = Result::How::Exited;
    r.code = WEXITSTATUS(status);
  } else {
    r.how = Result::How::Killed;
    r.code = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
  }
  return r;
}

}  // namespace

int start(const Spawn &spawn, std::string &error) {
  if (spawn.argv.empty()) {
    error = "no command";
    return -1;
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  if (!spawn.stdin_path.empty()) posix_spawn_file_actions_addopen(&actions, 0, spawn.stdin_path.c_str(), O_RDONLY, 0);
  if (!spawn.stdout_path.empty())
    posix_spawn_file_actions_addopen(&actions, 1, spawn.stdout_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  else if (spawn.stdout_fd >= 0) posix_spawn_file_actions_adddup2(&actions, spawn.stdout_fd, 1);
  if (spawn.stderr_path == "&1") posix_spawn_file_actions_adddup2(&actions, 1, 2);
  else if (!spawn.stderr_path.empty())
    posix_spawn_file_actions_addopen(&actions, 2, spawn.stderr_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  if (spawn.stdout_fd > 2) posix_spawn_file_actions_addclose(&actions, spawn.stdout_fd);
  posix_spawnattr_t attr;
  posix_spawnattr_init(&attr);
  sigset_t none;
  sigemptyset(&none);
  posix_spawnattr_setsigmask(&attr, &none);
  posix_spawnattr_setpgroup(&attr, 0);
  posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETPGROUP);
  std::vector<char *> args;
  for (const std::string &a : spawn.argv) args.push_back(const_cast<char *>(a.c_str()));
  args.push_back(nullptr);
  pid_t pid = -1;
  int rc = 0;
  {
    std::lock_guard<std::mutex> lock(g_mutex);
    if (g_stopping) rc = ECANCELED;
    else {
      rc = posix_spawnp(&pid, args[0], &actions, &attr, args.data(), environ);
      if (rc == 0) g_children.push_back(pid);
    }
  }
  posix_spawnattr_destroy(&attr);
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0) {
    error = rc == ECANCELED ? "the run is being stopped" : std::strerror(rc);
    return -1;
  }
  return pid;
}

Result wait(int pid, double time_limit, bool take_signals) {
  if (time_limit <= 0 && !take_signals) return reap(pid);
  sigset_t signals;
  sigemptyset(&signals);
  for (int s : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&signals, s);
  const double deadline = time_limit > 0 ? now() + time_limit : 0;
  long pause_ns = 1000000;  // 1 ms, doubling to 50 ms: short tools end quickly, long ones cost little
  for (;;) {
    if (has_ended(pid)) return reap(pid);
    if (deadline > 0 && now() >= deadline) {
      stop_group(pid, 0.5);
      Result r = reap(pid);
      r.how = Result::How::TimedOut;
      return r;
    }
    timespec pause{0, pause_ns};
    pause_ns = std::min(pause_ns * 2, 50000000L);
    if (take_signals) {
      const int sig = ::sigtimedwait(&signals, nullptr, &pause);
      if (sig > 0) {
        stop_group(pid, 0.5);
        Result r = reap(pid);
        r.how = Result::How::Interrupted;
        r.signal = sig;
        return r;
      }
    } else {
      ::nanosleep(&pause, nullptr);
    }
  }
}

Result run(const Spawn &spawn) {
  Result r;
  const int pid = start(spawn, r.error);
  if (pid < 0) return r;
  return wait(pid, spawn.time_limit, spawn.take_signals);
}

void stop_all(double grace) {
  std::vector<pid_t> children;
  {
    std::lock_guard<std::mutex> lock(g_mutex);
    g_stopping = true;
    children = g_children;
  }
  for (pid_t pid : children) ::kill(-pid, SIGTERM);
  const double until = now() + grace;
  for (pid_t pid : children)
    while (::kill(-pid, 0) == 0 && !has_ended(pid) && now() < until)
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
  for (pid_t pid : children) ::kill(-pid, SIGKILL);
}

std::string describe(const Result &r) {
  switch (r.how) {
  case Result::How::Exited: return "exited with status " + std::to_string(r.code);
  case Result::How::Killed: return "was killed by signal " + std::to_string(r.code) + " (" + strsignal(r.code) + ")";
  case Result::How::NotStarted: return "could not be started (" + r.error + ")";
  case Result::How::TimedOut: return "was stopped at its time limit";
  case Result::How::Interrupted: return "was stopped by signal " + std::to_string(r.signal);
  }
  return "?";
}

}  // namespace gfec::child_process
