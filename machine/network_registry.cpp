#include "machine/network_registry.hpp"

#include "machine/registry.hpp"

namespace gcsim::machine {

namespace {
Registry<NetworkModelEntry>& network_registry() { return Registry<NetworkModelEntry>::instance(); }
}  // namespace

NetworkModelRegistrar::NetworkModelRegistrar(NetworkModelEntry entry) { network_registry().add(std::move(entry)); }

const std::vector<NetworkModelEntry>& network_models() { return network_registry().entries(); }
std::vector<std::string> network_model_names() { return network_registry().names(); }
std::string network_model_list() { return network_registry().list(); }
bool is_network_model(std::string_view name) { return network_registry().find(name) != nullptr; }

}  // namespace gcsim::machine
