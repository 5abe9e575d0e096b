#include "parix/sim/deadlock_report.hpp"

#include <sstream>
#include <string_view>

namespace gcsim::parix {

std::string deadlock_report(machine::SimTime now, std::span<const BlockedProcess> blocked) {
  std::ostringstream os;
  os << "deadlock at simulated time " << machine::to_milliseconds(now)
     << " ms: every processor is blocked and no event is pending\n";
  for (const BlockedProcess& p : blocked) {
    const std::string_view call = p.call ? p.call : "?";
    os << "  processor " << p.processor;
    if (p.thread > 0) os << " (thread " << p.thread << ")";
    os << ": blocked in " << call;
    if (p.peer >= 0) os << (call == "send" ? " to" : " on") << " processor " << p.peer;
    os << " since " << machine::to_milliseconds(p.since) << " ms\n";
  }
  return os.str();
}

}  // namespace gcsim::parix
