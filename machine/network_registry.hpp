#pragma once
// The network models a run may name: name -> factory. Each model registers itself from its own
// file with a namespace-scope NetworkModelRegistrar, so adding one is one new file (a NetworkModel
// subclass and its registrar line); the machine-file parser, make_network_model(), --model and its
// help text all read this list. tests/networks/fixed is a test-only model added that way.
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
  int order = 100;  // help texts list models by order, then name: analytic 10, flow 20, packet 30
};

// Adds a model when its file is linked (a namespace-scope constant in that file).
struct NetworkModelRegistrar {
  explicit NetworkModelRegistrar(NetworkModelEntry entry);
};

// Every registered model, in the order help texts list them. A machine file without
// [network] model uses "analytic".
const std::vector<NetworkModelEntry>& network_models();
// Their names, e.g. for CLI::IsMember.
std::vector<std::string> network_model_names();
// "analytic, flow, packet": for error messages.
std::string network_model_list();
bool is_network_model(std::string_view name);

}  // namespace gcsim::machine
