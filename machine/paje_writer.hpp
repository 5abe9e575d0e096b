#pragma once
// Paje export of a trace, for ViTE (Debian package vite) and the pajeng tools (pj_dump,
// pj_validate). Paje wants its events in time order; a run emits its records as intervals end,
// so the export sorts them and is written from the trace CSV when the run closes its trace.
// Layout (traces/README.md has the full description):
//   Machine container "gc" > one Node container per processor ("P3 (3,0)")
//                          > at level full, one Channel container per used channel of the interconnect, in its source node
//   Node state "Activity": compute, send, recv, wait, connect (PajePushState / PajePopState)
//   Channel variable "transfers": messages occupying the channel (PajeAddVariable / PajeSubVariable)
//   Link "Message" from the sending to the receiving Node, key = message id
// Times are simulated milliseconds written exactly (nine decimals: picoseconds).
#include <string>

#include "machine/trace_csv.hpp"

namespace gcsim::machine {

// Throws std::runtime_error when the file cannot be written.
void write_paje(const TraceCsv& trace, const std::string& path);

}  // namespace gcsim::machine
