#pragma once
// Host threads for one simulated run (--host-threads T). The form factors of a hemicube cell are a
// function of the shooter's projection and the cell alone, and in a loop every cell of every
// shooter is needed by exactly one replica. So T - 1 worker threads compute the cells ahead, on
// the host, as soon as the first replica has the loop's projection, while the simulation goes on
// on its own thread. A replica takes its cells: a cell no worker has started it computes itself,
// a cell a worker is computing it waits for. Each cell's operations are counted by the replica
// that takes it, exactly as if it had computed the cell, so radiosities, simulated times and traces
// are the same for every T (tests); only the host's wall time changes.
//
// The kernel and the replicas' fibers stay on one host thread: only this pure work moves. One per
// simulated run (with_shared_projections makes it); under MPI every rank computes its own cells.
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <utility>
#include <vector>

#include "apps/common/work_ahead.hpp"
#include "apps/radiosity/cell_assignment.hpp"
#include "apps/radiosity/hemicube.hpp"

namespace gcsim::radiosity {

// The host threads are the shared work-ahead pool (apps/common/work_ahead.hpp): each (loop,
// shooter) adds its cells to it as one batch of items, in the order the replicas will take them.
class CellPrefetch {
 public:
  // workers: host threads besides the simulation's (host threads - 1), at least 1; `assignment`
  // and `side_faces`: which cells each replica takes, so the workers compute them in the order
  // they are asked for.
  explicit CellPrefetch(int workers, CellAssignment assignment = CellAssignment::cyclic,
                        SideFaces side_faces = SideFaces::half);
  ~CellPrefetch() = default;  // the workers finish the cell in hand and stop
  CellPrefetch(const CellPrefetch&) = delete;
  CellPrefetch& operator=(const CellPrefetch&) = delete;

  // The form factors of `cell` for the projection `renderer` holds (project or use_projection
  // first), in loop `step` of a run on `nodes` replicas where replica r takes cells_of(assignment,
  // r, nodes, cells, side_faces); adds the cell's operations to `ops`. Every cell of a (step, shooter) must be taken once.
  CellFormFactors take(HemicubeRenderer& renderer, const Scene& scene, int step, int cell, int nodes, OpCounts& ops);

  int workers() const { return worker_count_; }
  std::int64_t cells_by_workers() const { return ahead_ ? ahead_->by_workers() : 0; }

 private:
  struct ComputedCell {
    CellFormFactors ff;
    OpCounts ops;  // counted by the replica that takes the cell
  };
  struct Batch {  // one (step, shooter): items first .. first + cells - 1
    std::shared_ptr<const HemicubeProjection> projection;
    std::int64_t first = 0;
    int left = 0;  // cells not yet taken by a replica
  };
  using Key = std::pair<int, int>;  // (step, shooter)
  using Ahead = apps::WorkAhead<ComputedCell, std::int64_t>;

  void start_workers(const Scene& scene, const HemicubeOptions& options);
  // The batch's first item, registering the batch (and expecting its cells) on its first cell.
  std::int64_t first_item(const HemicubeRenderer& renderer, int step, int nodes);
  // Item `item` with `own` if it holds the item's projection, else with `other` switched to it.
  ComputedCell compute(std::int64_t item, HemicubeRenderer& own, HemicubeRenderer& other);

  const int worker_count_;
  const CellAssignment assignment_;
  const SideFaces side_faces_;
  mutable std::mutex lock_;  // the batches: workers look up an item's projection
  std::map<Key, std::int64_t> first_of_;
  std::map<std::int64_t, Batch> batches_;  // by first item
  std::int64_t next_item_ = 0;
  // One per worker and one for a replica helping with another batch's cells, made on the
  // simulation's thread.
  std::vector<std::unique_ptr<HemicubeRenderer>> renderers_;
  std::unique_ptr<Ahead> ahead_;  // last: its workers stop before the renderers go
};

}  // namespace gcsim::radiosity
