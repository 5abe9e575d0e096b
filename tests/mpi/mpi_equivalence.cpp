// Run under mpirun with N ranks: the same programs on the MPI backend and, on rank 0, on the
// simulated backend with N processors; their results must be equal bit for bit. Prints
// "P passed, F failed" and exits non-zero on a failure.
#include <cstdio>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

#include "apps/radiosity/builtin_scenes.hpp"
#include "apps/radiosity/parallel_radiosity.hpp"
#include "parix/collectives.hpp"
#include "parix/mpi_runtime.hpp"
#include "parix/simulated_runtime.hpp"

using namespace gcsim;

namespace {

int passed = 0, failed = 0;

void expect(bool ok, const std::string& what) {
  if (parix::mpi_rank() != 0) return;
  std::printf("%s %s\n", ok ? "[ PASS ]" : "[ FAIL ]", what.c_str());
  (ok ? passed : failed) += 1;
}

parix::SimulationOptions options(int n) {
  parix::SimulationOptions o;
  o.config = machine::with_nodes(machine::default_machine_config(), n);
  o.nodes = n;
  return o;
}

// Both backends run program; rank 0 compares what it captured.
template <class T>
void compare(const std::string& name, const std::function<void(parix::Processor&, T&)>& program) {
  const int n = parix::mpi_size();
  T real{}, simulated{};
  const parix::MpiRunResult r = parix::run_mpi(options(n), [&](parix::Processor& p) { program(p, real); });
  if (!r.root) return;
  parix::run_simulated(options(n), [&](parix::Processor& p) { program(p, simulated); });
  expect(real == simulated, name + " on " + std::to_string(n) + " ranks equals the simulated backend");
}

void collectives(parix::Processor& p, std::vector<double>& out) {
  const double mine = 1.0 / (p.id() + 3);
  const auto all = parix::allgather_vectors<double>(p, std::span(&mine, 1));
  const double sum = parix::allreduce_sum(p, mine);
  parix::CollectiveOptions seq;
  seq.algo = parix::BcastAlgo::sequential;
  parix::Bytes b(8);
  std::memcpy(b.data(), &sum, 8);
  const parix::Bytes back = parix::broadcast(p, p.count() - 1, p.id() == p.count() - 1 ? b : parix::Bytes{}, seq);
  parix::barrier(p);
  if (p.id() != 0) return;
  for (const auto& v : all) out.push_back(v.at(0));
  out.push_back(sum);
  double echoed;
  std::memcpy(&echoed, back.data(), 8);
  out.push_back(echoed);
}

void cornell_radiosities(parix::Processor& p, std::vector<float>& out) {
  static const radiosity::Scene scene = radiosity::flatten(radiosity::load_scene_world("cornell"));
  radiosity::ParallelOptions o;
  o.solver.hemicube.resolution = 32;
  o.solver.energy = 0.9;
  radiosity::ParallelOutcome result;
  radiosity::radiosity_program(p, scene, o, p.id() == 0 ? &result : nullptr);
  if (p.id() != 0) return;
  for (const auto& b : result.element_radiosity)
    for (int c = 0; c < 3; ++c) out.push_back(static_cast<float>(b[c]));
}

void threads(parix::Processor& p, std::vector<int>& out) {
  // A node-local thread talks to the next processor's thread while the processors talk too.
  const int next = (p.id() + 1) % p.count(), prev = (p.id() + p.count() - 1) % p.count();
  int got_by_thread = -1;
  parix::Thread t = p.spawn([&](parix::Processor& q) {
    if (p.count() == 1) return;
    // Even processors connect forwards first, odd ones backwards, so that the connects pair up
    // instead of waiting round the ring (with two processors both links join the same pair).
    parix::Link to, from;
    if (p.id() % 2 == 0) to = q.connect(next, 7), from = q.connect(prev, 7);
    else from = q.connect(prev, 7), to = q.connect(next, 7);
    q.isend(to, std::as_bytes(std::span(&next, 1)));
    got_by_thread = q.recv_value<int>(from);
  });
  t.join();
  const int total = parix::allreduce_sum(p, got_by_thread);
  if (p.id() == 0) out.push_back(total);
}

}  // namespace

int main() {
  parix::mpi_initialize();
  compare<std::vector<double>>("collectives", collectives);
  compare<std::vector<float>>("CORNELL radiosities", cornell_radiosities);
  compare<std::vector<int>>("node-local threads", threads);
  if (parix::mpi_rank() == 0) std::printf("%d passed, %d failed\n", passed, failed);
  return failed == 0 ? 0 : 1;
}
