// Run under mpirun with N ranks: the same programs on the MPI backend and on the simulated backend
// with N processors; their results must be equal bit for bit. Each program captures its result on
// processor 0, which runs on rank 0 unless a placement moves it. Prints "P passed, F failed" on
// rank 0 and exits non-zero on a failure.
#include <mpi.h>

#include <cstdio>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

#include <map>

#include "apps/radiosity/builtin_scenes.hpp"
#include "apps/raytrace/builtin_scenes.hpp"
#include "apps/raytrace/parallel_render.hpp"
#include "apps/radiosity/parallel_radiosity.hpp"
#include "parix/collectives.hpp"
#include "parix/mpi/mpi_runtime.hpp"
#include "parix/sim/simulated_runtime.hpp"

using namespace gcsim;

namespace {

int passed = 0, failed = 0;

void expect(bool ok, const std::string& what) {
  if (parix::mpi_rank() != 0) return;
  std::printf("%s %s\n", ok ? "[ PASS ]" : "[ FAIL ]", what.c_str());
  (ok ? passed : failed) += 1;
}

parix::SimulationOptions options(int n, bool reversed) {
  parix::SimulationOptions o;
  o.config = machine::with_nodes(machine::published_machine_config(), n);
  if (reversed)
    for (int i = 0; i < n; ++i) o.placement.push_back(n - 1 - i);  // processor i on rank n-1-i
  return o;
}

// Both backends run program; the rank that ran processor 0 compares what it captured, and rank 0
// reports the verdict of all.
template <class T>
void compare(const std::string& name, const std::function<void(parix::Processor&, T&)>& program, bool reversed = false) {
  const int n = parix::mpi_size();
  T real{}, simulated{};
  int ran_processor_0 = 0;
  parix::run_mpi(options(n, reversed), [&](parix::Processor& p) {
    if (p.id() == 0) ran_processor_0 = 1;
    program(p, real);
  });
  int ok = 1;
  if (ran_processor_0) {
    parix::run_simulated(options(n, reversed), [&](parix::Processor& p) { program(p, simulated); });
    ok = real == simulated && real != T{};
  }
  int all_ok = 0, holders = 0, holder_rank = -1;
  const int my_rank_if_holder = ran_processor_0 ? parix::mpi_rank() : -1;
  MPI_Allreduce(&ok, &all_ok, 1, MPI_INT, MPI_LAND, MPI_COMM_WORLD);
  MPI_Allreduce(&ran_processor_0, &holders, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  MPI_Allreduce(&my_rank_if_holder, &holder_rank, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  expect(holders == 1 && holder_rank == (reversed ? n - 1 : 0),
         name + ": processor 0 ran on rank " + std::to_string(holder_rank) + " as placed");
  expect(all_ok && holders == 1, name + " on " + std::to_string(n) + " ranks" + (reversed ? ", placement reversed," : "") +
                                     " equals the simulated backend");
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

// Links belong to the node: threads open processor 0's links to every other processor and end;
// processor 0 then receives on them (the ray tracer's image assembly does this).
void links_opened_by_threads(parix::Processor& p, std::vector<int>& out) {
  if (p.id() != 0) {
    parix::Link root = p.connect(0, 13);
    p.send_value(root, 10 * p.id());
    return;
  }
  std::vector<parix::Link> links(std::size_t(p.count()));
  std::vector<parix::Thread> openers;
  for (int w = 1; w < p.count(); ++w)
    openers.push_back(p.spawn([&links, w](parix::Processor& q) { links[std::size_t(w)] = q.connect(w, 13); }));
  for (auto& t : openers) t.join();
  int sum = 1;
  for (int w = 1; w < p.count(); ++w) sum += p.recv_value<int>(links[std::size_t(w)]);
  out.push_back(sum);
}

// The ray tracer's parallel render of Whitted's scene (dynamic distribution: a master, workers
// and a worker thread on node 0): the image node 0 assembles.
void whitted_image(parix::Processor& p, std::vector<float>& out) {
  static const raytrace::Scene scene = raytrace::make_builtin_scene("whitted");
  static const geometry::Bvh bvh = geometry::build_bvh_by_clustering(scene);
  static const raytrace::ParallelRenderJob job = [] {
    raytrace::RenderSettings s;
    s.width = s.height = 40;
    s.shading = raytrace::Shading::whitted;
    return raytrace::ParallelRenderJob(scene, bvh, s, raytrace::Distribution::dynamic);
  }();
  static std::map<const void*, raytrace::ParallelRender> renders;  // one per run (per out)
  raytrace::ParallelRender& r = renders.try_emplace(&out, job.new_result(p.count())).first->second;
  job.program(p, r);
  if (p.id() != 0) return;
  for (const glm::vec3& c : r.image.pixels()) out.insert(out.end(), {c.r, c.g, c.b});
}

void cancelled_receives(parix::Processor& p, std::vector<int>& out) {
  // Each processor withdraws a receive from its predecessor before anything is sent: the
  // predecessor's message goes to the next receive instead. Connect order as in threads().
  if (p.count() == 1) return;
  const int next = (p.id() + 1) % p.count(), prev = (p.id() + p.count() - 1) % p.count();
  parix::Link to, from;
  if (p.id() % 2 == 0) to = p.connect(next, 9), from = p.connect(prev, 9);
  else from = p.connect(prev, 9), to = p.connect(next, 9);
  parix::Request withdrawn = p.irecv(from);
  const int cancelled = p.cancel(withdrawn) ? 1 : 0;
  p.wait(withdrawn);  // returns at once
  const int mine = 100 + p.id();
  parix::Request sent = p.isend(to, std::as_bytes(std::span(&mine, 1)));
  const int got = p.recv_value<int>(from);
  p.wait(sent);
  const int total = parix::allreduce_sum(p, 1000 * cancelled + got + static_cast<int>(withdrawn.take().size()));
  if (p.id() == 0) out.push_back(total);
}

// Not an equivalence: the MPI backend refuses to withdraw a send MPI still holds. A long message
// (past Open MPI's eager limit, so it waits for its receive, which is posted only after the
// cancel) makes cancel throw ParixError; the message is then delivered intact.
void refused_send_cancel() {
  int threw = 0, intact = 0;
  parix::run_mpi(options(parix::mpi_size(), false), [&](parix::Processor& p) {
    if (p.id() > 1) return;
    parix::Link data = p.connect(1 - p.id(), 11), signal = p.connect(1 - p.id(), 12);
    if (p.id() == 0) {
      parix::Request long_one = p.isend(data, parix::Bytes(1 << 20, std::byte{7}));
      try {
        p.cancel(long_one);
      } catch (const parix::ParixError&) {
        threw = 1;
      }
      p.send_value(signal, threw);
      p.wait(long_one);
    } else {
      p.recv_value<int>(signal);
      intact = p.recv(data) == parix::Bytes(1 << 20, std::byte{7});
    }
  });
  int all_threw = 0, all_intact = 0;
  MPI_Allreduce(&threw, &all_threw, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  MPI_Allreduce(&intact, &all_intact, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  expect(all_threw && all_intact, "cancelling a send in progress throws on MPI, and the message still arrives");
}

}  // namespace

int main() {
  parix::mpi_initialize();
  compare<std::vector<double>>("collectives", collectives);
  compare<std::vector<float>>("CORNELL radiosities", cornell_radiosities);
  compare<std::vector<int>>("node-local threads", threads);
  compare<std::vector<int>>("cancelled receives", cancelled_receives);
  compare<std::vector<int>>("links opened by threads", links_opened_by_threads);
  compare<std::vector<float>>("Whitted image, dynamic distribution", whitted_image);
  refused_send_cancel();
  compare<std::vector<double>>("collectives", collectives, true);
  compare<std::vector<int>>("node-local threads", threads, true);
  if (parix::mpi_rank() == 0) std::printf("%d passed, %d failed\n", passed, failed);
  return failed == 0 ? 0 : 1;
}
