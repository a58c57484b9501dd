#include <string>

#include "services.h"

namespace afp::detail {
namespace {

Claim failure(const Watch& watch, std::string error) {
  Claim claim;
  claim.supervisor = watch.rules->supervisor;
  claim.failed = true;
  claim.error = std::move(error);
  return claim;
}

}  // namespace

std::optional<Claim> start_watch(const Watch& watch, Services& services) {
  Shadow discarded;
  Context ctx(services, discarded);
  if (auto error = capture([&] { watch.supervisor->start(ctx); })) return failure(watch, *error);
  return std::nullopt;
}

std::optional<Claim> check_watch(const Watch& watch, Services& services) {
  Claim claim;
  claim.supervisor = watch.rules->supervisor;
  Context ctx(services, claim.outputs);
  CheckResult result = no_event;
  if (auto error = capture([&] { result = watch.supervisor->check(ctx); })) return failure(watch, *error);
  if (!result.raised()) return std::nullopt;
  auto rule = watch.rules->reactions.find(result.event());
  if (rule == watch.rules->reactions.end())
    return failure(watch, "no rule for event " + std::to_string(result.event()));
  if (rule->second.kind == Target::Kind::Ignore) return std::nullopt;
  claim.event = result.event();
  claim.target = rule->second;
  return claim;
}

void stop_watch(const Watch& watch) {
  (void)capture([&] { watch.supervisor->stop(); });
}

}  // namespace afp::detail
