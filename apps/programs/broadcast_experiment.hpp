#pragma once
// The thesis's broadcast experiment (section 4.4.2): one all-node broadcast, in which every node's
// data is collected at the root and the root sends it back to every node. A connection is opened
// for every message, and every message carries exactly `bytes` bytes (the data is not merged on
// the way, matching the measured tables); bytes = 0 opens the connections and sends nothing, the
// tables' "connect only" column.
#include <cstdint>
#include <string>

#include "machine/node_memory.hpp"

#include "parix/collectives.hpp"
#include "parix/processor.hpp"

namespace gcsim::programs {

void all_node_broadcast(parix::Processor& p, std::int64_t bytes, parix::BcastAlgo algo);

// --size: a whole number of bytes with an optional binary unit (16KB = 16384); a clear error for a
// negative, malformed or too large size.
std::int64_t parse_message_size(const std::string& text);

// Before the run: one node's data and message copy against its memory (enforce: fails naming
// processor 0's holdings and the node's memory), then every node's against the host's memory.
void check_broadcast_resources(std::int64_t bytes, int nodes, std::int64_t node_bytes, machine::MemoryLimit limit);

// Thesis tables 4.6 (sequential) and 4.7 (tree): milliseconds for N = 2..64 and the four sizes.
struct ThesisBroadcastRow {
  int nodes;
  double ms[4];  // connect only, 1 KB, 4 KB, 16 KB
};
inline constexpr std::int64_t kThesisBroadcastSizes[4] = {0, 1024, 4096, 16384};
inline constexpr ThesisBroadcastRow kThesisSequentialBroadcast[] = {
    {2, {1.58, 2.01, 2.81, 6.54}},   {4, {4.79, 5.61, 8.41, 19.6}},  {8, {21.8, 23.0, 27.7, 48.8}},
    {16, {40.4, 47.0, 57.4, 111}},   {32, {111, 137, 143, 267}},     {64, {282, 343, 380, 586}},
};
inline constexpr ThesisBroadcastRow kThesisTreeBroadcast[] = {
    {2, {1.59, 1.88, 2.82, 6.54}},  {4, {3.89, 4.65, 5.93, 14.6}},  {8, {19.0, 19.9, 22.8, 33.8}},
    {16, {34.9, 36.6, 40.4, 54.7}}, {32, {75.3, 74.7, 78.1, 79.1}}, {64, {103, 105, 104, 137}},
};

}  // namespace gcsim::programs
