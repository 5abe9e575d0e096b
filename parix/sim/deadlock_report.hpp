#pragma once
// The report of a deadlock: every processor blocked, no event pending. It names each blocked
// process (and thread), the call it is blocked in, the peer it waits for and since when.
#include <span>
#include <string>

#include "machine/sim_time.hpp"

namespace gcsim::parix {

struct BlockedProcess {
  int processor = -1;
  int thread = 0;              // 0: the processor's main thread
  const char* call = nullptr;  // "recv", "send", "connect", "wait", "join", ...
  int peer = -1;               // -1: no single peer
  machine::SimTime since = 0;
};

std::string deadlock_report(machine::SimTime now, std::span<const BlockedProcess> blocked);

}  // namespace gcsim::parix
