// A token ring on the simulated GC: node 0 starts a counter, every node adds one and passes it
// to the next, for --laps laps. Registered as the application "ring" of this program, so
// `gcsim-ring run ring --nodes 16` and `gcsim-ring sweep ring` work as for gcsim's own apps.
#include <cstdint>
#include <cstring>
#include <memory>

#include <fmt/format.h>

#include "apps/pipeline/app_registry.hpp"

namespace {

using namespace gcsim;

struct RingOutcome : pipeline::Outcome {
  std::int64_t token = -1;  // what came back to node 0 after the last lap
};

class Ring : public pipeline::Experiment {
 public:
  explicit Ring(int laps) : laps_(laps) {}
  std::unique_ptr<pipeline::Outcome> new_outcome(int) const override { return std::make_unique<RingOutcome>(); }
  parix::Program program(pipeline::Outcome& out) const override {
    std::int64_t* result = &pipeline::outcome_as<RingOutcome>(out).token;
    return [laps = laps_, result](parix::Processor& p) {
      const int n = p.count(), next = (p.id() + 1) % n, prev = (p.id() + n - 1) % n;
      if (n == 1) return void(*result = laps);
      // A link is tagged with its sender's id, so on two nodes the two directions stay apart.
      // Node 0 opens its links in the other order, or every node would wait for its neighbour.
      parix::Link to_next, from_prev;
      if (p.id() == 0) to_next = p.connect(next, p.id());
      from_prev = p.connect(prev, prev);
      if (p.id() != 0) to_next = p.connect(next, p.id());
      std::int64_t token = 0;
      for (int lap = 0; lap < laps; ++lap) {
        if (p.id() != 0 || lap > 0) std::memcpy(&token, p.recv(from_prev).data(), sizeof token);
        ++token;
        p.send(to_next, std::as_bytes(std::span(&token, 1)));
      }
      if (p.id() == 0) std::memcpy(&token, p.recv(from_prev).data(), sizeof token);
      if (p.id() == 0) *result = token;
    };
  }
  void report(const pipeline::Outcome& out, nlohmann::json& extra) const override {
    const std::int64_t token = pipeline::outcome_as<RingOutcome>(out).token;
    fmt::print("ring      token {} after {} laps\n", token, laps_);
    extra["ring"] = {{"token", token}, {"laps", laps_}};
  }

 private:
  int laps_;
};

const pipeline::AppRegistrar registrar{[] {
  pipeline::AppSpec s;
  s.name = "ring";
  s.summary = "A token passed around every node (an example built against an installed gcsim)";
  s.default_nodes = 8;
  s.options = [](CLI::App& cmd, pipeline::Verb) -> pipeline::ExperimentFactory {
    auto laps = std::make_shared<int>(10);
    cmd.add_option("--laps", *laps, "Times the token goes round")->check(CLI::Range(1, 100000))->capture_default_str();
    return [laps] { return std::make_unique<Ring>(*laps); };
  };
  return s;
}()};

}  // namespace
