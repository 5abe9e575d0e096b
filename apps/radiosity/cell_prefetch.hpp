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
#include <condition_variable>
#include <map>
#include <memory>
#include <mutex>
#include <thread>
#include <utility>
#include <vector>

#include "apps/radiosity/cell_assignment.hpp"
#include "apps/radiosity/hemicube.hpp"

namespace gcsim::radiosity {

class CellPrefetch {
 public:
  // workers: host threads besides the simulation's (host threads - 1), at least 1; `assignment`
  // and `side_faces`: which cells each replica takes, so the workers compute them in the order
  // they are asked for.
  explicit CellPrefetch(int workers, CellAssignment assignment = CellAssignment::cyclic,
                        SideFaces side_faces = SideFaces::half);
  ~CellPrefetch();  // the workers finish the cell in hand and stop
  CellPrefetch(const CellPrefetch&) = delete;
  CellPrefetch& operator=(const CellPrefetch&) = delete;

  // The form factors of `cell` for the projection `renderer` holds (project or use_projection
  // first), in loop `step` of a run on `nodes` replicas where replica r takes cells_of(assignment,
  // r, nodes, cells, side_faces); adds the cell's operations to `ops`. Every cell of a (step, shooter) must be taken once.
  CellFormFactors take(HemicubeRenderer& renderer, const Scene& scene, int step, int cell, int nodes, OpCounts& ops);

  int workers() const { return int(threads_.size()); }
  std::int64_t cells_by_workers() const;  // so far: cells a worker computed before a replica asked

 private:
  enum class State { pending, running, done };
  struct Cell {
    State state = State::pending;
    CellFormFactors ff;
    OpCounts ops;
    std::exception_ptr failure;
  };
  struct Batch {
    std::shared_ptr<const HemicubeProjection> projection;
    std::vector<int> order;  // cells in the order the replicas are expected to take them
    std::size_t next = 0;    // order[next...]: not yet handed to a worker
    std::vector<Cell> cells;
    int left = 0;            // cells not yet taken by a replica
  };
  using Key = std::pair<int, int>;  // (step, shooter)

  Batch& batch_for(const HemicubeRenderer& renderer, int step, int nodes);
  void start_workers(const Scene& scene, const HemicubeOptions& options);
  void work(HemicubeRenderer& renderer);
  void help_while_running(HemicubeRenderer& renderer, Batch& b, Cell& needed, std::unique_lock<std::mutex>& held);
  // A pending cell for a worker, marked running, or null (with its batch's projection).
  std::pair<Cell*, int> claim(std::shared_ptr<const HemicubeProjection>& projection);

  const int worker_count_;
  const CellAssignment assignment_;
  const SideFaces side_faces_;
  mutable std::mutex lock_;
  std::condition_variable work_ready_, cell_done_;
  std::map<Key, Batch> batches_;
  bool stopping_ = false;
  std::int64_t by_workers_ = 0;
  std::vector<std::unique_ptr<HemicubeRenderer>> renderers_;  // one per worker, made on the simulation's thread
  std::vector<std::jthread> threads_;
};

}  // namespace gcsim::radiosity
