#pragma once
// How long a message takes to cross the physical interconnect. Every model shares one interface so a run
// can name the fidelity it wants; they agree exactly for a message alone on an idle network.
//   analytic: set-up + latency + per-hop latency + size / channel bandwidth; no contention.
//   flow:     the same latency, but each channel's bandwidth is shared max-min fairly among the
//             messages crossing it at the same time (rates recomputed when a message starts or ends).
//   packet:   messages cut into packets that queue for each channel of their route (cut-through).
#include <cstdint>
#include <memory>
#include <string_view>
#include <vector>

#include "machine/kernel.hpp"
#include "machine/machine_config.hpp"
#include "machine/network_registry.hpp"
#include "machine/interconnect.hpp"
#include "machine/trace.hpp"

namespace gcsim::machine {

struct NetworkContext {
  Kernel& kernel;
  const Interconnect& interconnect;  // the physical network's routes (machine/mesh.hpp for the GC)
  const MachineConfig& config;
  TraceWriter* trace;  // may be null
};

class NetworkModel {
 public:
  explicit NetworkModel(NetworkContext ctx)
      : ctx_(ctx), channel_bandwidth_(ctx.config.channel_bandwidth(ctx.interconnect.directions())) {}
  virtual ~NetworkModel() = default;
  virtual std::string_view name() const = 0;

  // Starts moving bytes from node src to node dst now; on_arrival runs when the last byte is there.
  virtual void transfer(int src, int dst, std::int64_t bytes, Kernel::Action&& on_arrival) = 0;

  // Set-up plus latency for a message over `hops` hops (zero hops: set-up only).
  // Inline: the analytic model asks it once per message.
  SimTime latency(int hops) const {
    const MachineConfig& c = ctx_.config;
    if (hops <= 0) return c.message_setup;
    return c.message_setup + c.network_latency + SimTime(hops - 1) * c.hop_latency;
  }
  // Time to push bytes through one channel at full bandwidth.
  SimTime serialization(std::int64_t bytes) const;
  // What a message alone on the network takes.
  SimTime uncontended_time(int hops, std::int64_t bytes) const { return latency(hops) + (hops > 0 ? serialization(bytes) : 0); }

  std::uint64_t messages() const { return messages_; }
  // Bytes and busy time per channel (indexed like the interconnect's channels); a model that defers its
  // accounting settles it first.
  const std::vector<std::int64_t>& channel_bytes() {
    settle();
    return channel_bytes_;
  }
  const std::vector<SimTime>& channel_busy() {
    settle();
    return channel_busy_;
  }

 protected:
  // Adds what the model holds back to channel_bytes_ and channel_busy_.
  virtual void settle() {}
  void account(const std::vector<int>& route, std::int64_t bytes, SimTime start, SimTime end);
  NetworkContext ctx_;
  double channel_bandwidth_;  // bytes per second of one directed channel
  std::uint64_t messages_ = 0;
  std::vector<std::int64_t> channel_bytes_;
  std::vector<SimTime> channel_busy_;
};

// The factory of a model constructed from its context, for its registrar:
//   const NetworkModelRegistrar registrar{{"mine", "one-line summary", network_model_factory<Mine>}};
template <class Model>
std::unique_ptr<NetworkModel> network_model_factory(NetworkContext ctx) {
  return std::make_unique<Model>(ctx);
}

// Builds the model registered under name (machine/network_registry.hpp).
// Throws std::invalid_argument listing the valid names if name is unknown.
std::unique_ptr<NetworkModel> make_network_model(std::string_view name, NetworkContext ctx);

}  // namespace gcsim::machine
