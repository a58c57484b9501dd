#include "arbiter.h"

#include <utility>

namespace afp::detail {

std::uint64_t Arbiter::open() {
  std::lock_guard lock(mutex_);
  winner_.reset();
  open_ = true;
  return ++epoch_;
}

std::optional<std::uint64_t> Arbiter::current() const {
  std::lock_guard lock(mutex_);
  if (!open_) return std::nullopt;
  return epoch_;
}

bool Arbiter::claim(std::uint64_t epoch, Claim claim) {
  {
    std::lock_guard lock(mutex_);
    if (!open_ || epoch != epoch_) return false;
    open_ = false;
    winner_ = std::move(claim);
  }
  waker_.notify();
  return true;
}

void Arbiter::fail(Claim failure) {
  {
    std::lock_guard lock(mutex_);
    if (failure_) return;
    failure_ = std::move(failure);
  }
  waker_.notify();
}

std::optional<Claim> Arbiter::take() {
  std::lock_guard lock(mutex_);
  return take_locked();
}

std::optional<Claim> Arbiter::close() {
  std::lock_guard lock(mutex_);
  open_ = false;
  return take_locked();
}

std::optional<Claim> Arbiter::take_locked() {
  if (failure_) return std::exchange(failure_, std::nullopt);
  return std::exchange(winner_, std::nullopt);
}

}  // namespace afp::detail
