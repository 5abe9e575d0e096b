// A test-only application: node 0 sends a message to every other node, which sends it back.
// It exists to prove that an application is one folder: nothing outside tests/apps/ping names it.
#include <cstdint>
#include <memory>

#include <fmt/format.h>

#include "apps/pipeline/app_registry.hpp"

namespace {

using namespace gcsim;

struct PingFlags {
  std::int64_t bytes = 64;
  int rounds = 1;
};

struct PingOutcome : pipeline::Outcome {
  int round_trips = 0;  // counted by node 0 from the echoes it received
};

class PingExperiment : public pipeline::Experiment {
 public:
  explicit PingExperiment(PingFlags f) : f_(f) {}
  std::unique_ptr<pipeline::Outcome> new_outcome(int) const override { return std::make_unique<PingOutcome>(); }
  parix::Program program(pipeline::Outcome& out) const override {
    int* trips = &pipeline::outcome_as<PingOutcome>(out).round_trips;
    return [this, trips](parix::Processor& p) {
      const parix::Bytes message(std::size_t(f_.bytes));
      for (int r = 0; r < f_.rounds; ++r) {
        if (p.id() != 0) {
          parix::Link root = p.connect(0);
          p.send(root, p.recv(root));
          continue;
        }
        for (int peer = 1; peer < p.count(); ++peer) {
          parix::Link l = p.connect(peer);
          p.send(l, message);
          if (p.recv(l).size() == message.size()) ++*trips;
        }
      }
    };
  }
  void report(const pipeline::Outcome& out, nlohmann::json& extra) const override {
    const int trips = pipeline::outcome_as<PingOutcome>(out).round_trips;
    fmt::print("ping      {} round trips of {} bytes\n", trips, f_.bytes);
    extra["ping"] = {{"round_trips", trips}, {"bytes", f_.bytes}};
  }

 private:
  PingFlags f_;
};

pipeline::AppSpec ping_app() {
  pipeline::AppSpec s;
  s.name = "ping";
  s.summary = "Node 0 pings every other node (a test-only application)";
  s.default_nodes = 2;
  s.options = [](CLI::App& cmd, pipeline::Verb) -> pipeline::ExperimentFactory {
    auto f = std::make_shared<PingFlags>();
    cmd.add_option("--bytes", f->bytes, "Bytes per message")->check(CLI::Range(0, 1 << 24))->capture_default_str();
    cmd.add_option("--rounds", f->rounds, "Times node 0 pings every node")->check(CLI::Range(1, 1000))->capture_default_str();
    return [f] { return std::make_unique<PingExperiment>(*f); };
  };
  return s;
}

const pipeline::AppRegistrar registrar{ping_app()};

}  // namespace
