#include "machine/network_registry.hpp"

#include "machine/analytic_network.hpp"
#include "machine/flow_network.hpp"
#include "machine/packet_network.hpp"

namespace gcsim::machine {
namespace {

template <typename Model>
std::unique_ptr<NetworkModel> make(NetworkContext ctx) {
  return std::make_unique<Model>(ctx);
}

}  // namespace

const std::vector<NetworkModelEntry>& network_models() {
  // One line per model. The first is the default of a machine file without [network] model.
  static const std::vector<NetworkModelEntry> models = {
      {"analytic", "latency + size / bandwidth, no contention", make<AnalyticNetwork>},
      {"flow", "channels shared max-min fairly among the messages crossing them", make<FlowNetwork>},
      {"packet", "packets queue for each channel of their route (cut-through)", make<PacketNetwork>},
  };
  return models;
}

std::vector<std::string> network_model_names() {
  std::vector<std::string> names;
  for (const auto& m : network_models()) names.emplace_back(m.name);
  return names;
}

std::string network_model_list() {
  std::string list;
  for (const auto& m : network_models()) list += (list.empty() ? "" : ", ") + std::string(m.name);
  return list;
}

bool is_network_model(std::string_view name) {
  for (const auto& m : network_models()) {
    if (m.name == name) return true;
  }
  return false;
}

}  // namespace gcsim::machine
