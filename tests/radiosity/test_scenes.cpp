#include "test_scenes.hpp"

#include "apps/radiosity/entity_builder.hpp"
#include "parix/backend.hpp"
#include "tests/support/published_machine.hpp"

namespace gcsim::radiosity::testing {

Scene lit_room(double s, double gap, double rho) {
  EntityBuilder b("lit room");
  int wall = b.surface(Rgb(rho, rho * 0.9, rho * 0.8));
  int red = b.surface(Rgb(0.7, 0.1, 0.1));
  int light = b.surface(Rgb(0.5), Rgb(10, 10, 9));
  b.quad({{0, 0, 0}, {s, 0, 0}, {s, 0, s}, {0, 0, s}}, {0, 1, 0}, 3, 3, 2, 2, wall);
  b.quad({{0, s, 0}, {s, s, 0}, {s, s, s}, {0, s, s}}, {0, -1, 0}, 2, 2, 1, 1, wall);
  b.quad({{0, 0, 0}, {0, s, 0}, {0, s, s}, {0, 0, s}}, {1, 0, 0}, 2, 2, 1, 1, red);
  b.quad({{s, 0, 0}, {s, s, 0}, {s, s, s}, {s, 0, s}}, {-1, 0, 0}, 2, 2, 1, 1, wall);
  b.quad({{0, 0, s}, {s, 0, s}, {s, s, s}, {0, s, s}}, {0, 0, -1}, 2, 2, 1, 1, wall);
  // Open towards -z, like the Cornell box.
  double l0 = 0.4 * s, l1 = 0.6 * s, ly = s * (1 - 1e-4);
  b.quad({{l0, ly, l0}, {l1, ly, l0}, {l1, ly, l1}, {l0, ly, l1}}, {0, -1, 0}, 1, 1, 1, 1, light);
  b.box_separate({0.2 * s, 0, 0.5 * s}, {0.4 * s, 0.3 * s, 0.7 * s}, EntityBuilder::kTop | EntityBuilder::kSides,
                 [&](EntityBuilder::Face) { return wall; });
  double y = gap * s;
  b.quad({{0.55 * s, y, 0.2 * s}, {0.85 * s, y, 0.2 * s}, {0.85 * s, y, 0.5 * s}, {0.55 * s, y, 0.5 * s}}, {0, 1, 0},
         1, 1, 2, 2, red);
  World w;
  w.name = "lit room";
  w.entities.push_back(b.take());
  w.instances.push_back({0, {}});
  return flatten(w);
}

ParallelOptions quick_parallel_options(parix::BcastAlgo bcast) {
  ParallelOptions o;
  o.solver.hemicube.resolution = 32;
  o.solver.hemicube.cells_per_side = 4;
  o.solver.energy = 0.9;
  o.bcast = bcast;
  return o;
}

SimulatedRun run_published(const Scene& scene, const ParallelOptions& o, int nodes) {
  SimulatedRun r;
  r.result = parix::run({"simulated", test_support::published_machine(nodes)},
                        [&](parix::Processor& p) { radiosity_program(p, scene, o, &r.out); });
  return r;
}

}  // namespace gcsim::radiosity::testing
