#include "chart_nodes.h"

namespace gfec::chart_nodes {

namespace {
std::string id(const std::string &prefix, const char *kind, std::size_t n) { return prefix + kind + std::to_string(n); }
}  // namespace

std::string place(const std::string &prefix, std::size_t place) { return id(prefix, "p", place); }
std::string transition(const std::string &prefix, std::size_t transition) { return id(prefix, "t", transition); }
std::string join(const std::string &prefix, std::size_t transition) { return id(prefix, "join", transition); }
std::string fork(const std::string &prefix, std::size_t transition) { return id(prefix, "fork", transition); }
std::string instance_prefix(const std::string &prefix, std::size_t place) { return id(prefix, "s", place) + "_"; }
std::string instance_frame(const std::string &prefix, std::size_t place) { return "cluster_" + id(prefix, "s", place); }

std::string actor(std::size_t actor) { return id("", "a", actor); }
std::string supervisor(std::size_t actor, std::size_t supervisor) {
  return id("", "s", actor) + "_" + std::to_string(supervisor);
}
std::string global_supervisor(std::size_t global) { return id("", "g", global); }
std::string constraint(std::size_t constraint) { return id("", "c", constraint); }
std::string vars() { return "vars"; }

}  // namespace gfec::chart_nodes
