#pragma once
// Flow-level network: after its latency, a message becomes a flow whose rate is the max-min fair
// share of the channels on its route (progressive filling). Rates change only when a flow starts
// or ends, and only for the flows connected to it through shared channels (the lazy max-min of
// SimGrid: a change re-solves its connected component, nothing else); those have their remaining
// bytes advanced and, if their rate changed, their completion rescheduled (stale completion
// events are recognised by a version number and ignored).
#include <cstdint>
#include <map>
#include <vector>

#include "machine/network_model.hpp"

namespace gcsim::machine {

class FlowNetwork final : public NetworkModel {
 public:
  using NetworkModel::NetworkModel;
  std::string_view name() const override { return "flow"; }
  void transfer(int src, int dst, std::int64_t bytes, Kernel::Action&& on_arrival) override;

  std::size_t active_flows() const { return flows_.size(); }

 private:
  struct Flow {
    std::uint64_t id = 0;
    std::vector<int> route;
    std::int64_t bytes = 0;
    double remaining = 0;       // bytes still to send, as of `updated`
    double rate = 0;            // bytes per second while transmitting
    bool transmitting = false;  // past its latency phase
    SimTime started = 0;
    SimTime updated = 0;
    std::uint64_t version = 0;
    Kernel::Action on_arrival;
    // Scratch of the solver (reshare): the solve that last visited it, its new rate.
    std::uint64_t visited = 0;
    bool assigned = false;
    double new_rate = 0;
  };
  void start_flow(std::uint64_t id);
  void finish_flow(std::uint64_t id, std::uint64_t version);
  // Recomputes the rates of the transmitting flows that share a channel, directly or through
  // other flows, with any channel in `channels`.
  void reshare(const std::vector<int>& channels);
  void collect_component(const std::vector<int>& seed);
  void fill_progressively();

  using Flows = std::map<std::uint64_t, Flow>;
  // A flow for id in flows_, in the node (and route storage) of a finished flow when there is one.
  Flow& new_flow(std::uint64_t id);

  Flows flows_;                                 // ordered by id: deterministic iteration
  std::vector<std::vector<Flow*>> on_channel_;  // transmitting flows per channel
  std::uint64_t next_id_ = 0;
  // Finished flows' map nodes, their routes' storage included: reused, so a message allocates nothing.
  std::vector<Flows::node_type> spare_flows_;

  // The solver's scratch, kept between solves so that a solve allocates nothing.
  std::uint64_t solve_ = 0;                    // number of the current solve
  std::vector<std::uint64_t> channel_visited_;  // per channel: the solve that last visited it
  std::vector<double> left_;                   // per channel: capacity not yet given out
  std::vector<int> unassigned_;                // per channel: flows without a rate yet
  std::vector<int> component_channels_;
  std::vector<Flow*> component_flows_;
  std::vector<int> frontier_;
  std::vector<int> live_;                      // shared channels with flows still to fix
};

}  // namespace gcsim::machine
