// The ids of the nodes in gfec's picture of a chart (the DOT and SVG back ends). The run viewer
// lights a node by its id, so the back end that writes the picture and every recording that
// names a node (gfec run --html, carbot-sim --html) spell the ids here, once. A sub-chart
// instance's nodes carry its prefix ("s0_" inside place 0, "s0_s2_" a level deeper), so one
// picture holds every instance without two nodes sharing an id.
#pragma once

#include <cstddef>
#include <string>

namespace gfec::chart_nodes {

/// Place or state `place` of the chart whose nodes carry `prefix` ("" for the compiled chart):
/// "p3", "s0_p1".
std::string place(const std::string &prefix, std::size_t place);
/// The transition bar `transition`: "t2".
std::string transition(const std::string &prefix, std::size_t transition);
/// The double lines where transition `transition` joins several places or forks into several.
std::string join(const std::string &prefix, std::size_t transition);
std::string fork(const std::string &prefix, std::size_t transition);
/// The prefix of the nodes of the instance that place `place` runs: "s0_".
std::string instance_prefix(const std::string &prefix, std::size_t place);
/// The frame (a Graphviz cluster) around that instance: "cluster_s0".
std::string instance_frame(const std::string &prefix, std::size_t place);

/// A plan's actor `actor` ("a1"), supervisor `supervisor` of that actor ("s1_0"), global
/// supervisor `global` ("g0") and constraint `constraint` ("c2").
std::string actor(std::size_t actor);
std::string supervisor(std::size_t actor, std::size_t supervisor);
std::string global_supervisor(std::size_t global);
std::string constraint(std::size_t constraint);

/// The note listing an sfc's or fsm's vars: "vars" (the run viewer shows their values beside it).
std::string vars();

}  // namespace gfec::chart_nodes
