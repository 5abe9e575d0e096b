#pragma once
// Flow-level network: after its latency, a message becomes a flow whose rate is the max-min fair
// share of the channels on its route (progressive filling). Rates change only when a flow starts
// or ends; then remaining bytes are advanced and completion events rescheduled (stale ones are
// recognised by a version number and ignored).
#include <cstdint>
#include <map>
#include <vector>

#include "machine/network_model.hpp"

namespace gcsim::machine {

class FlowNetwork final : public NetworkModel {
 public:
  using NetworkModel::NetworkModel;
  std::string_view name() const override { return "flow"; }
  void transfer(int src, int dst, std::int64_t bytes, Kernel::Action on_arrival) override;

  std::size_t active_flows() const { return flows_.size(); }

 private:
  struct Flow {
    std::vector<int> route;
    std::int64_t bytes;
    double remaining;           // bytes still to send
    double rate = 0;            // bytes per second while transmitting
    bool transmitting = false;  // past its latency phase
    SimTime started = 0;
    std::uint64_t version = 0;
    Kernel::Action on_arrival;
  };
  void start_flow(std::uint64_t id);
  void finish_flow(std::uint64_t id, std::uint64_t version);
  void advance_to_now();
  void reshare();

  std::map<std::uint64_t, Flow> flows_;  // ordered by id: deterministic iteration
  std::uint64_t next_id_ = 0;
  SimTime last_update_ = 0;
};

}  // namespace gcsim::machine
