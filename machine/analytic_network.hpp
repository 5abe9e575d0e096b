#pragma once
// Contention-free network: every message takes set-up + latency + per-hop latency + size/bandwidth.
#include "machine/network_model.hpp"
#include "machine/route_cache.hpp"

namespace gcsim::machine {

class AnalyticNetwork final : public NetworkModel {
 public:
  explicit AnalyticNetwork(NetworkContext ctx) : NetworkModel(ctx), routes_(ctx.interconnect) {}
  std::string_view name() const override { return "analytic"; }
  void transfer(int src, int dst, std::int64_t bytes, Kernel::Action&& on_arrival) override;

 protected:
  void settle() override;

 private:
  void transfer_slow(int src, int dst, std::int64_t bytes, Kernel::Action&& on_arrival);
  // A traced run records every channel of every message as it goes: routed each time.
  void transfer_traced(int src, int dst, std::int64_t bytes, Kernel::Action&& on_arrival);
  // Untraced runs add a message's bytes and busy time to its pair's entry only (no route walk).
  RouteCache routes_;
  std::vector<int> route_;
  // The last size serialised: a flow of equal messages divides once.
  std::int64_t last_bytes_ = -1;
  SimTime last_serialization_ = 0;
};

}  // namespace gcsim::machine
