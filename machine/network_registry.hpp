#pragma once
// The one list of network models a run may name: name -> factory. The machine-file parser,
// make_network_model() and the command line all read it, so adding a model is one new file
// (a NetworkModel subclass) plus one line in network_registry.cpp.
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace gcsim::machine {

class NetworkModel;
struct NetworkContext;

struct NetworkModelEntry {
  std::string_view name;
  std::string_view summary;  // one line, for help texts
  std::function<std::unique_ptr<NetworkModel>(NetworkContext)> make;
};

// Every registered model, in the order help texts list them.
const std::vector<NetworkModelEntry>& network_models();
// Their names, e.g. for CLI::IsMember.
std::vector<std::string> network_model_names();
// "analytic, flow, packet": for error messages.
std::string network_model_list();
bool is_network_model(std::string_view name);

}  // namespace gcsim::machine
