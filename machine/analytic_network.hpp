#pragma once
// Contention-free network: every message takes set-up + latency + per-hop latency + size/bandwidth.
#include "machine/network_model.hpp"

namespace gcsim::machine {

class AnalyticNetwork final : public NetworkModel {
 public:
  using NetworkModel::NetworkModel;
  std::string_view name() const override { return "analytic"; }
  void transfer(int src, int dst, std::int64_t bytes, Kernel::Action&& on_arrival) override;

 private:
  std::vector<int> route_;
};

}  // namespace gcsim::machine
