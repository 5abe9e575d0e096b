#include "parix/sim/sim_request.hpp"

#include <utility>

#include "parix/sim/payload_pool.hpp"
#include "parix/sim/request_pool.hpp"

namespace gcsim::parix::detail {

void SimRequest::release() noexcept { home->recycle(this); }

// Back to the run's pool (a receive), else freed now.
void SimRequest::recycle(Bytes&& storage) noexcept {
  if (payloads) payloads->give(std::move(storage));
  else Bytes().swap(storage);
}

}  // namespace gcsim::parix::detail
