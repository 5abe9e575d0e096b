#pragma once
// The simulated backend's request state: the activity behind a Request (parix/processor.hpp), with
// what only this runtime needs of it. States come from the run's RequestPool and go back to it.
#include <cstdint>

#include "parix/processor.hpp"

namespace gcsim::parix::detail {

class PayloadPool;
class RequestPool;

class SimRequest final : public RequestState {
 public:
  bool cpu_charged = false;         // the receive's CPU cost was paid
  std::int64_t sent_at = 0;         // when the received message's sender sent it (simulated ps)
  PayloadPool* payloads = nullptr;  // where take_into recycles storage (receives)
  RequestPool* home = nullptr;      // takes the state back when its last Request lets go

 private:
  void release() noexcept override;
  void recycle(Bytes&& storage) noexcept override;
};

// The state of a Request the simulated backend made (every Request it is given: an application
// makes none of its own).
inline SimRequest& sim_state(const Request& r) { return static_cast<SimRequest&>(*r.state()); }

}  // namespace gcsim::parix::detail
