#include "afp/configuration.h"

#include <algorithm>

namespace afp {
namespace {

// The entry's slot in a (const or not) map; the caller holds the mutex.
template <class Map>
auto& find(Map& entries, std::string_view name) {
  auto it = entries.find(name);
  if (it == entries.end()) throw ConfigError("unknown configuration entry '" + std::string(name) + "'");
  return it->second;
}

}  // namespace

void Shadow::write(std::string_view entry, Value value) {
  auto same = [&](const auto& w) { return w.first == entry; };
  auto it = std::find_if(writes_.begin(), writes_.end(), same);
  if (it != writes_.end()) it->second = std::move(value);
  else writes_.emplace_back(std::string(entry), std::move(value));
}

void Configuration::declare(const std::string& name, Type type) { declare(name, default_value(type)); }

void Configuration::declare(const std::string& name, const Value& initial) {
  std::lock_guard lock(mutex_);
  auto [it, inserted] = entries_.emplace(name, initial);
  if (!inserted && it->second.type() != initial.type())
    throw ConfigError("configuration entry '" + name + "' declared as " + to_string(initial.type()) + " but it is " +
                      to_string(it->second.type()));
}

bool Configuration::contains(std::string_view name) const {
  std::lock_guard lock(mutex_);
  return entries_.find(name) != entries_.end();
}

Type Configuration::type_of(std::string_view name) const {
  std::lock_guard lock(mutex_);
  return find(entries_, name).type();
}

Value Configuration::value(std::string_view name) const {
  std::lock_guard lock(mutex_);
  return find(entries_, name);
}

void Configuration::set(std::string_view name, const Value& value) {
  std::lock_guard lock(mutex_);
  Value& slot = find(entries_, name);
  slot = convert(value, slot.type());  // converts first, so a failure leaves the entry unchanged
}

void Configuration::commit(const Shadow& shadow) {
  std::lock_guard lock(mutex_);
  for (const auto& [name, value] : shadow.writes()) find(entries_, name) = value;
}

std::vector<std::string> Configuration::names() const {
  std::lock_guard lock(mutex_);
  std::vector<std::string> out;
  for (const auto& entry : entries_) out.push_back(entry.first);
  return out;
}

}  // namespace afp
