// The `gcsim bench ring` workload written for SimGrid's S4U API, to compare kernel throughput:
// N actors in a ring, each sends `size` bytes to its right neighbour and receives from its left,
// `iterations` times (put_async, get, wait). The platform has one link per ring neighbour pair
// with the GC's channel bandwidth and latency. Prints simulated messages per wall-clock second.
// Built only when SimGrid (Debian libsimgrid-dev) is installed; see tests/bench/compare_ring.sh.
#include <simgrid/s4u.hpp>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace sg4 = simgrid::s4u;

static void ring_actor(int id, int n, int iterations, double size) {
  sg4::Mailbox* right = sg4::Mailbox::by_name("mb" + std::to_string((id + 1) % n));
  sg4::Mailbox* mine = sg4::Mailbox::by_name("mb" + std::to_string(id));
  static int payload = 0;
  for (int i = 0; i < iterations; ++i) {
    sg4::CommPtr c = right->put_async(&payload, static_cast<uint64_t>(size));
    mine->get<int>();
    c->wait();
  }
}

int main(int argc, char** argv) {
  sg4::Engine e(&argc, argv);
  const int n = argc > 1 ? std::atoi(argv[1]) : 64;
  const int iterations = argc > 2 ? std::atoi(argv[2]) : 2000;
  const double size = argc > 3 ? std::atof(argv[3]) : 64;

  sg4::NetZone* zone = sg4::create_full_zone("gc");
  std::vector<sg4::Host*> hosts;
  for (int i = 0; i < n; ++i) hosts.push_back(zone->create_host("node" + std::to_string(i), 80e6));
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    if (j == i) continue;
    sg4::Link* l = zone->create_link("link" + std::to_string(i), 4 * 35e6 / 16)->set_latency(65e-6)->seal();
    zone->add_route(hosts[i]->get_netpoint(), hosts[j]->get_netpoint(), nullptr, nullptr, {sg4::LinkInRoute(l)}, true);
  }
  zone->seal();
  for (int i = 0; i < n; ++i) sg4::Actor::create("ring" + std::to_string(i), hosts[i], ring_actor, i, n, iterations, size);

  const auto start = std::chrono::steady_clock::now();
  e.run();
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double messages = static_cast<double>(n) * iterations;
  std::printf("simgrid ring of %d actors, %d iterations of %.0f bytes: %.0f messages\n", n, iterations, size, messages);
  std::printf("simulated %.6f s   wall %.6f s\n", sg4::Engine::get_clock(), wall);
  std::printf("rate      %.0f simulated messages per wall second\n", messages / wall);
  return 0;
}
