// The PARIX API from a program's own main(), built with pkg-config against an installed gcsim:
// every node greets node 0 on the simulated GC.
#include <cstdio>
#include "machine/machine_config.hpp"
#include "parix/backend.hpp"
using namespace gcsim;
int main() {
  parix::RunOptions o;
  o.simulation.config = machine::with_nodes(machine::default_machine_config(), 4);
  int greeted = 0;
  const parix::RunResult r = parix::run(o, [&](parix::Processor& p) {
    if (p.id() != 0) { parix::Link l = p.connect(0); p.send(l, parix::Bytes(8)); return; }
    for (int i = 1; i < p.count(); ++i) { parix::Link l = p.connect(i); p.recv(l); ++greeted; }
  });
  std::printf("greeted %d, simulated %.6f s\n", greeted, r.simulated_seconds());
}
