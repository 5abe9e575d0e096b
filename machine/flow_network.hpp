#pragma once
// Flow-level network: after its latency, a message becomes a flow whose rate is the max-min fair
// share of the channels on its route (machine/max_min_solver.hpp). Rates change only when a flow
// starts or ends; the flows whose rate changed have their remaining bytes advanced and their
// completion rescheduled (stale completion events are recognised by a version number and ignored).
#include <cstdint>
#include <memory>
#include <vector>

#include "machine/max_min_solver.hpp"
#include "machine/network_model.hpp"

namespace gcsim::machine {

class FlowNetwork final : public NetworkModel {
 public:
  using NetworkModel::NetworkModel;
  std::string_view name() const override { return "flow"; }
  void transfer(int src, int dst, std::int64_t bytes, Kernel::Action&& on_arrival) override;

 private:
  // A message in flight, stored at its solver slot.
  struct Flow {
    std::uint64_t id = 0;       // order of the messages: simultaneous completions keep it
    std::int64_t bytes = 0;
    double remaining = 0;       // bytes still to send, as of `updated`
    double rate = 0;            // bytes per second while transmitting
    SimTime started = 0;
    SimTime updated = 0;
    std::uint64_t version = 0;  // of its pending completion event; unique across slot reuse
    Kernel::Action on_arrival;
  };
  void start_flow(int slot);
  void finish_flow(int slot, std::uint64_t version);
  // Advances and reschedules the flows whose rate the last solve changed, in message order.
  void reschedule();

  std::unique_ptr<MaxMinSolver> solver_;  // made at the first message, when the mesh is known
  std::vector<Flow> flows_;               // by solver slot
  std::vector<int> changed_;
  std::uint64_t next_id_ = 0;
  std::uint64_t next_version_ = 0;
};

}  // namespace gcsim::machine
