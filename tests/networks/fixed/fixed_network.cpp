// A test-only network model: every message takes one millisecond, whatever its size and route.
// It exists to prove that a network model is one file: nothing outside tests/networks/fixed names
// it, yet `--model fixed` and [network] model = "fixed" work for every application.
#include "machine/network_model.hpp"

namespace gcsim::machine {
namespace {

class FixedNetwork final : public NetworkModel {
 public:
  static constexpr SimTime kMessageTime = kMillisecond;
  explicit FixedNetwork(NetworkContext ctx) : NetworkModel(ctx) {}
  std::string_view name() const override { return "fixed"; }
  void transfer(int, int, std::int64_t, Kernel::Action&& on_arrival) override {
    ++messages_;
    ctx_.kernel.after(kMessageTime, std::move(on_arrival));
  }
};

const NetworkModelRegistrar fixed_registrar{
    {"fixed", "every message takes 1 ms (a test-only model)", network_model_factory<FixedNetwork>}};

}  // namespace
}  // namespace gcsim::machine
