// The live trace's wire format (docs/live.md): what a C engine built with --trace writes each tick
// and what `gfec monitor` reads. Both sides take the layout of a frame's values from here, so the
// engine and its decoder cannot disagree on which value is which.
#pragma once

#include "model.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace gfec::trace {

constexpr std::uint8_t kSync0 = 0xA7;  ///< every frame begins with these two bytes
constexpr std::uint8_t kSync1 = 0x5E;
constexpr std::uint8_t kVersion = 1;
constexpr std::uint8_t kFlagFull = 0x01;         ///< the frame holds every value, else only changes
constexpr std::size_t kHeaderBytes = 14;         ///< sync, version, flags, length, fingerprint, tick
constexpr std::size_t kCrcBytes = 4;             ///< CRC-32 of the header and the payload
constexpr std::uint32_t kDefaultFullEvery = 32;  ///< a full frame at least every this many ticks

/// A sub-chart instance's values in a frame.
struct InstanceSlots {
  std::string path;       ///< "Search", "Search.Grab"
  model::ChartId chart;   ///< the chart it runs
  std::size_t first = 0;  ///< its first value's index
  std::size_t places = 0;
};

/// Which value of a frame is which: the compiled chart's places' activation, then every
/// sub-chart instance's (depth first in declaration order), then an fsm's status (0 running,
/// 1 succeeded, 2 failed), then a team machine's agent number and its reports (state + 1, 0 for
/// none) by agent.
struct Layout {
  model::ChartId chart;
  bool fsm = false;
  std::size_t places = 0;  ///< the compiled chart's
  std::vector<InstanceSlots> instances;
  std::ptrdiff_t status = -1;  ///< the fsm status value's index, -1 for an sfc
  std::ptrdiff_t agent = -1;   ///< a team machine's agent number's index, -1 for no team
  std::size_t team = 0;        ///< a team machine's agents (its reports follow the agent number)
  std::size_t values = 0;      ///< how many values a full frame holds
  /// FNV-1a of the layout's description (the chart's kind and name, every place's and
  /// transition's name in order, the instances, the team): a stream from a chart whose frames
  /// mean something else is refused.
  std::uint32_t fingerprint = 0;
  /// The longest frame: every value changed, as an index (at most 3 bytes) and a value (at most 5).
  std::size_t max_payload() const { return values * 8; }
  std::size_t max_frame() const { return kHeaderBytes + max_payload() + kCrcBytes; }
};

Layout layout_of(const model::Model &model, model::ChartId chart);

/// CRC-32 (IEEE 802.3, reflected, as zlib's crc32), bit by bit as the engine computes it.
std::uint32_t crc32(const std::uint8_t *data, std::size_t n);

}  // namespace gfec::trace
