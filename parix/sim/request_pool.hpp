#pragma once
// Request states for the simulated runtime without a malloc per send and receive: states are made
// in chunks and kept on a free list; a Request's last reference hands its state back here
// (SimRequest::home), which resets it for the next send or receive. The pool lives in the Simulation and
// must outlive every request of its run (they are held by the run's fibers, processes -- each keeps
// its blocking receive's for reuse -- and messages, all gone before it ends).
#include <cstddef>
#include <memory>
#include <vector>

#include "parix/processor.hpp"
#include "parix/sim/sim_request.hpp"

namespace gcsim::parix::detail {

class RequestPool {
 public:
  RequestPool() = default;
  RequestPool(const RequestPool&) = delete;
  RequestPool& operator=(const RequestPool&) = delete;
  ~RequestPool() = default;

  // A fresh state (running, fields at their defaults), held by the returned Request.
  Request take() {
    if (free_count_ == 0) grow();
    return Request(free_[--free_count_]);
  }
  void recycle(SimRequest* s) noexcept {
    std::destroy_at(s);  // frees data a receive still held, as deleting it did
    std::construct_at(s)->home = this;
    free_[free_count_++] = s;  // room for every state made
  }

 private:
  static constexpr std::size_t kPerChunk = 256;
  [[gnu::noinline, gnu::cold]] void grow() {  // out of line: take() inlines to a few instructions
    auto& chunk = chunks_.emplace_back(std::make_unique<SimRequest[]>(kPerChunk));
    free_.resize(chunks_.size() * kPerChunk);
    for (std::size_t i = kPerChunk; i-- > 0;) {
      chunk[i].home = this;
      free_[free_count_++] = &chunk[i];
    }
  }
  std::vector<std::unique_ptr<SimRequest[]>> chunks_;
  std::vector<SimRequest*> free_;  // a stack of free_count_ states, sized for all of them
  std::size_t free_count_ = 0;
};

}  // namespace gcsim::parix::detail
