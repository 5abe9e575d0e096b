#pragma once
// Progressive refinement on the simulated GC (thesis chapter 4). Every node holds a replica of the
// scene and of the solver state (as the thesis does, section 4.3.2), so after each exchange all nodes
// apply the same shots in the same order and stay identical. The variants:
//   hemicube-fixed (4.3)        each node proposes its K patches with the most unshot energy, the K
//                               largest overall shoot, every node Z-buffers its share of the hemicube
//                               cells (cell c belongs to node c mod N), the per-cell form factor sums
//                               are exchanged by an all-node broadcast, every node updates.
//   hemicube-hierarchical (4.5) the same with the adaptive hemicube (cells on element borders split
//                               into four, recursively).
//   patch (4.2.2)               patches belong to nodes (p mod N); the owner of a shooter computes
//                               its whole hemicube; the rows are exchanged. The conventional baseline.
// Unaggregated, a loop has K + 1 all-node exchanges: the proposals, then each shooter's delta form
// factors (for the patch partition: a broadcast from the shooter's owner); with ff_exchange
// together, 2: the proposals, then every shooter's form factors in one exchange.
// --aggregate (4.4.3, unfinished in the thesis) makes it one exchange of larger messages: the
// proposals are dropped (every replica can select the shooters itself) and all shooters' form
// factors travel together. keep_links reuses one link per peer instead of a connection per message.
// Form factors are summed cell by cell in the fixed cell order, so every node count gives radiosities
// bit-identical to the sequential solver with the same K.
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "apps/radiosity/cell_prefetch.hpp"
#include "apps/radiosity/form_factor_exchange.hpp"
#include "apps/radiosity/form_factor_merge.hpp"
#include "apps/radiosity/progressive_solver.hpp"
#include "apps/radiosity/projection_cache.hpp"
#include "parix/backend.hpp"
#include "parix/collectives.hpp"
#include "parix/processor.hpp"

namespace gcsim::radiosity {

enum class ParallelAlgorithm { hemicube_fixed, hemicube_hierarchical, patch };
ParallelAlgorithm parse_parallel_algorithm(const std::string& s);  // throws std::invalid_argument
const char* to_string(ParallelAlgorithm a);

struct ParallelOptions {
  SolverOptions solver;
  ParallelAlgorithm algorithm = ParallelAlgorithm::hemicube_fixed;
  parix::BcastAlgo bcast = parix::BcastAlgo::sequential;
  bool aggregate = false;
  bool keep_links = false;      // reuse links between exchanges instead of connecting per message
  int hierarchical_levels = 3;  // for hemicube-hierarchical
  CellAssignment cell_assignment = CellAssignment::cyclic;  // which cells each node computes
  SideFaces side_faces = SideFaces::half;                  // the mesh those shares are cut from
  FormFactorMerge merge = FormFactorMerge::own_cells;       // how the received parts are added up
  FormFactorExchange ff_exchange = FormFactorExchange::per_shooter;  // one exchange per shooter, or one for all
  std::vector<int> snapshot_loops;  // processor 0 keeps the radiosities after these loops
  std::function<void(int loop, double shot_fraction)> on_loop;  // processor 0 calls it after every loop (progress)
  // Computation sampling (projection_cache.hpp): the replicas of one simulated run share each
  // shooter's projection on the host. Null: every replica projects for itself. Identical results
  // and simulated times either way; give each run its own cache (with_shared_projections).
  bool share_projections = true;  // what the user asked; a run's program makes the cache
  std::shared_ptr<ProjectionCache> shared_projections;
  // Host threads (cell_prefetch.hpp): above 1, workers compute the hemicube cells ahead of the
  // replicas. Identical results, simulated times and traces for any count; the simulated backend
  // only (with_shared_projections makes the workers of one run).
  int host_threads = 1;
  std::shared_ptr<CellPrefetch> cell_prefetch;
};

// What processor 0 reports at the end of a run.
struct ParallelOutcome {
  std::vector<Rgb> element_radiosity;
  std::vector<StepRecord> steps;
  EnergyBalance energy;
  bool converged = false;
  std::int64_t exchanged_bytes = 0;  // bytes processor 0 contributed to the exchanges
  std::vector<std::pair<int, std::vector<Rgb>>> snapshots;  // (loop, element radiosities)
};

// Node memory of the replica of the environment and of the solver state every node holds.
std::int64_t replica_bytes(const Scene& scene);
// The hemicube options a run of `options` renders with (the hierarchical algorithm's levels set).
HemicubeOptions hemicube_of(const ParallelOptions& options);

// `options` for one simulated run: a fresh projection cache if options.share_projections, and
// host_threads - 1 cell workers if host_threads > 1.
ParallelOptions with_shared_projections(ParallelOptions options);
// The same for one run of a command: with the run's host threads on the simulated backend (under
// MPI each rank computes its own cells).
ParallelOptions with_shared_projections(ParallelOptions options, const parix::RunOptions& run);

// The SPMD program: run it on every processor; processor 0 fills *outcome.
void radiosity_program(parix::Processor& p, const Scene& scene, const ParallelOptions& options,
                       ParallelOutcome* outcome);
// The same solve, returning this node's own replica (the element radiosities every node holds,
// identical on all; steps and snapshots only on node 0): for programs that go on to use it.
ParallelOutcome solve_replica(parix::Processor& p, const Scene& scene, const ParallelOptions& options);

}  // namespace gcsim::radiosity
