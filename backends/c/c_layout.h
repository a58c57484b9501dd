// How an sfc's engine is laid out. Small charts get GFE's readable form: every tick visits every
// transition and every place, one block each. Above a size (or when asked) the scalable form
// visits only what is active, so a tick costs what the active part of the chart costs:
//
//   sequential  one initial place and every transition one place to one place: exactly one place
//               is ever active, so the state is its number and a tick is a switch on it (the
//               machine a person writes by hand);
//   sparse      anything else: activation counters, a bitset of the active places with summary
//               levels (finding the next active place skips empty words), and the transitions
//               tried from the active places in declaration order.
//
// The counters of the sparse form are as narrow as a structural bound on the activation allows
// (docs/c-engine.md). The bound is not proven here: the analyses record it in the model once for
// every chart (model::Chart::activation, compiler/analysis/activation_bounds.h) and the layout
// reads it.
#pragma once

#include "backend.h"
#include "model.h"

#include <cstdint>
#include <vector>

namespace gfec::c_backend {

/// Charts with more places than this get the scalable form unless told otherwise.
constexpr std::size_t kReadableMaxPlaces = 64;

/// The sequential form of a chart (and an fsm) with more places than this is split (docs/c-engine.md, "Large
/// charts"): each switch on the active place becomes file-local part functions of kPartPlaces
/// places each, called through a table. One function with a case per place costs gcc -O2 time and
/// memory that grow faster than the chart (docs/performance.md); the parts keep each function small.
constexpr std::size_t kSplitAbovePlaces = 1024;
constexpr std::size_t kPartPlaces = 256;

/// A set of numbers 0..n-1 as 32-bit words (level 0) with summary levels above it: bit j of
/// level k+1 says that word j of level k is not empty. The top level is one word.
struct BitLevels {
  std::vector<std::uint32_t> from;  ///< where each level's words begin; from.back() is the total
  std::uint32_t levels() const { return static_cast<std::uint32_t>(from.size() - 1); }
  std::uint32_t words() const { return from.back(); }
  std::uint32_t words_at(std::size_t level) const { return from[level + 1] - from[level]; }
};
BitLevels bit_levels(std::size_t n);

struct Layout {
  enum class Form { Readable, Sequential, Sparse };
  Form form = Form::Readable;

  // ---- bounds (the sparse form sizes its counters by them)
  model::ActivationBound activation;  ///< the chart's, as the analyses proved it (model::Chart::activation)
  int counter_bits = 32;              ///< 8, 16 or 32: the narrowest type that holds activation.place
  bool saturate = true;               ///< not bounded: counters stop at UINT32_MAX instead of wrapping

  // ---- the sequential form
  std::size_t part_places = 0;  ///< 0: one run function; else the switches' parts of this many places

  // ---- the sparse form
  int index_bits = 32;                               ///< 8, 16 or 32: a type for place numbers (lists of places)
  IdMap<model::TransitionId, model::PlaceId> owner;  ///< by transition: the input place whose visit tries it
  bool place_driven = false;                         ///< owners never decrease in declaration order (see c_layout.cc)
  BitLevels active;                                  ///< the active places
  BitLevels candidates;                              ///< !place_driven: the transitions to try this tick
  std::size_t add_capacity = 0;                      ///< places that fired transitions produce into, per tick
  std::size_t watch_capacity = 0;                    ///< watched places that lose (or gain) activation per tick
  /// The lists of watched places that fell to 0 and that rose from 0 in a tick, each at least 1
  /// long when watch_capacity is not 0 (C has no empty arrays): a place falls to 0 only if a
  /// transition consumes from it, and rises only if one produces into it.
  std::size_t lost_capacity = 0, gained_capacity = 0;
  std::vector<bool> watched;  ///< by place: runs exit or entry code, or resets a timer
};

/// Decides the form for `chart` as `requested`, and everything that form needs. `watched`, by
/// place: the place runs exit or entry code or resets a timer when its activation changes.
Layout plan_layout(const model::Chart &chart, EngineForm requested, std::vector<bool> watched);

/// "uint8_t", "uint16_t" or "uint32_t".
const char *uint_type(int bits);

}  // namespace gfec::c_backend
