#include "apps/radiosity/cell_prefetch.hpp"

#include <iterator>
#include <stdexcept>

namespace gcsim::radiosity {

CellPrefetch::CellPrefetch(int workers, CellAssignment assignment, SideFaces side_faces)
    : worker_count_(workers), assignment_(assignment), side_faces_(side_faces) {
  if (workers < 1) throw std::invalid_argument("CellPrefetch: at least one worker thread");
}

// The renderers are made here, on the simulation's thread, before any worker runs.
void CellPrefetch::start_workers(const Scene& scene, const HemicubeOptions& options) {
  for (int i = 0; i <= worker_count_; ++i) renderers_.push_back(std::make_unique<HemicubeRenderer>(scene, options));
  std::vector<Ahead::Compute> computes;
  for (int i = 0; i < worker_count_; ++i)
    computes.push_back([this, r = renderers_[std::size_t(i)].get()](std::int64_t item) { return compute(item, *r, *r); });
  ahead_ = std::make_unique<Ahead>(std::move(computes));
}

std::int64_t CellPrefetch::first_item(const HemicubeRenderer& renderer, int step, int nodes) {
  std::vector<std::int64_t> order;
  std::int64_t first = 0;
  {
    std::lock_guard<std::mutex> held(lock_);
    const Key key{step, renderer.projection()->shooter};
    if (auto it = first_of_.find(key); it != first_of_.end()) return it->second;
    const int cells = renderer.cell_count();
    first = next_item_;
    next_item_ += cells;
    first_of_[key] = first;
    batches_[first] = {renderer.projection(), first, cells};
    // Replicas run their loops in id order on the simulation's thread, each taking its cells in turn.
    for (int r = 0; r < nodes; ++r)
      for (int c : cells_of(assignment_, r, nodes, cells, side_faces_)) order.push_back(first + c);
    for (int c = 0; c < cells; ++c) order.push_back(first + c);  // any the assignment leaves out: last
  }
  ahead_->expect(order);
  return first;
}

CellPrefetch::ComputedCell CellPrefetch::compute(std::int64_t item, HemicubeRenderer& own, HemicubeRenderer& other) {
  std::shared_ptr<const HemicubeProjection> projection;
  int cell = 0;
  {
    std::lock_guard<std::mutex> held(lock_);  // the batch stays until every one of its cells was taken
    const auto at = std::prev(batches_.upper_bound(item));
    projection = at->second.projection;
    cell = int(item - at->first);
  }
  HemicubeRenderer& r = own.projection() == projection ? own : other;
  if (r.projection() != projection) {
    OpCounts projecting;  // counted by the replica that projected, not here
    r.use_projection(projection, projecting);
  }
  ComputedCell out;
  out.ff = r.cell_form_factors(cell, out.ops);
  return out;
}

CellFormFactors CellPrefetch::take(HemicubeRenderer& renderer, const Scene& scene, int step, int cell, int nodes,
                                   OpCounts& ops) {
  if (!ahead_) start_workers(scene, renderer.options());
  const std::int64_t first = first_item(renderer, step, nodes);
  if (cell < 0 || cell >= renderer.cell_count()) throw std::out_of_range("CellPrefetch: no such cell");
  // A cell nobody started is computed here, with the replica's own renderer, as without
  // prefetching; while a worker finishes it, the replica computes the next pending cells (of
  // another batch with the spare renderer, so its own keeps its projection).
  ComputedCell c = ahead_->take(first + cell, [&](std::int64_t item) { return compute(item, renderer, *renderers_.back()); });
  ops += c.ops;
  {
    std::lock_guard<std::mutex> held(lock_);
    Batch& b = batches_.at(first);
    if (--b.left == 0) {
      first_of_.erase({step, b.projection->shooter});
      batches_.erase(first);
    }
  }
  return std::move(c.ff);
}

}  // namespace gcsim::radiosity
