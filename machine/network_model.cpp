#include "machine/network_model.hpp"

#include <stdexcept>
#include <string>


namespace gcsim::machine {

SimTime NetworkModel::serialization(std::int64_t bytes) const {
  if (bytes <= 0) return 0;
  return from_seconds(static_cast<double>(bytes) / channel_bandwidth_);
}

void NetworkModel::account(const std::vector<int>& route, std::int64_t bytes, SimTime start, SimTime end) {
  if (channel_bytes_.empty()) {
    channel_bytes_.assign(ctx_.interconnect.channel_count(), 0);
    channel_busy_.assign(ctx_.interconnect.channel_count(), 0);
  }
  const bool per_channel_trace = ctx_.trace && ctx_.trace->level() == TraceLevel::full;  // asked once a message
  for (int ch : route) {
    channel_bytes_[ch] += bytes;
    channel_busy_[ch] += end - start;
    if (per_channel_trace) {
      const ChannelEnds e = ctx_.interconnect.channel_ends(ch);
      ctx_.trace->record({TraceKind::link, e.from, e.to, start, end, bytes, ch, "link"});
    }
  }
}

std::unique_ptr<NetworkModel> make_network_model(std::string_view name, NetworkContext ctx) {
  for (const auto& m : network_models()) {
    if (m.name == name) return m.make(ctx);
  }
  throw std::invalid_argument("unknown network model '" + std::string(name) + "' (expected one of: " +
                              network_model_list() + ")");
}

}  // namespace gcsim::machine
