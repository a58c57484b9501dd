#include "afp/threaded_executor.h"

#include <atomic>
#include <mutex>
#include <stdexcept>
#include <thread>

#include "level.h"
#include "thread_watchers.h"
#include "waker.h"

namespace afp {

using Clock = std::chrono::steady_clock;

// The executor is the services of every level it runs: plan time is the
// steady clock since the run began.
struct ThreadedExecutor::Impl final : detail::Services {
  Impl(Plan& to_run, Configuration& config, TraceObserver* trace, ThreadedOptions timing)
      : Services(config, trace), plan(to_run), options(timing) {}

  Duration now() const override { return Clock::now() - origin; }
  std::unique_ptr<detail::Watchers> make_watchers() override {
    return std::make_unique<detail::ThreadWatchers>(*this, waker, options.supervisor_period);
  }

  // Checks, in the caller's thread, that the plan can run and runs only once.
  void prepare() {
    if (prepared) throw std::logic_error("a ThreadedExecutor runs its plan once");
    plan.validate();
    prepared = true;
  }

  // The main loop (docs/runtime.md 1), one actor step per period or per wake-up.
  // Nothing escapes it: under start() an exception would reach std::terminate, under run()
  // it would leave the status NotStarted. A trace hook that throws fails the run.
  Status execute() {
    origin = Clock::now();  // before any supervisor thread exists, so they read it race-free
    Status result = Status::Failed;
    std::string message;
    auto failure = detail::capture([&] {
      detail::Level level(plan, *this);
      level.begin();
      if (level.status() == Status::Running && !trace_error()) status.store(Status::Running);
      while (level.status() == Status::Running && !trace_error()) {
        waker.wait_for(options.actor_period);
        if (stop_requested.load()) level.abort();
        else level.advance();
      }
      if (level.status() == Status::Running) level.abort();  // the trace hook failed
      result = level.status();
      message = level.error();
    });
    if (failure) message = *failure, result = Status::Failed;
    if (trace_error()) message = "trace observer: " + *trace_error(), result = Status::Failed;
    {
      std::lock_guard lock(error_mutex);
      error = message;
    }
    status.store(result);  // after the error, so that a Failed status has its message
    return result;
  }

  Plan& plan;
  const ThreadedOptions options;
  Clock::time_point origin;
  detail::Waker waker;
  std::atomic<bool> stop_requested{false};
  std::atomic<Status> status{Status::NotStarted};
  mutable std::mutex error_mutex;
  std::string error;
  bool prepared = false;  // only the owner's thread touches it
  std::thread thread;
};

ThreadedExecutor::ThreadedExecutor(Plan& plan, Configuration& config, TraceObserver* trace, ThreadedOptions options)
    : impl_(std::make_unique<Impl>(plan, config, trace, options)) {
  plan.declare_into(config);
}

ThreadedExecutor::~ThreadedExecutor() {
  request_stop();
  wait();
}

Status ThreadedExecutor::run() {
  impl_->prepare();
  return impl_->execute();
}

void ThreadedExecutor::start() {
  impl_->prepare();
  impl_->thread = std::thread([this] { impl_->execute(); });
}

void ThreadedExecutor::request_stop() {
  impl_->stop_requested.store(true);
  impl_->waker.notify();
}

Status ThreadedExecutor::wait() {
  if (impl_->thread.joinable()) impl_->thread.join();
  return status();
}

Status ThreadedExecutor::status() const { return impl_->status.load(); }

std::string ThreadedExecutor::error() const {
  std::lock_guard lock(impl_->error_mutex);
  return impl_->error;
}

}  // namespace afp
