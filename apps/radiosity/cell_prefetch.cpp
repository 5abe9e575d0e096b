#include "apps/radiosity/cell_prefetch.hpp"

#include <stdexcept>

namespace gcsim::radiosity {

CellPrefetch::CellPrefetch(int workers, CellAssignment assignment, SideFaces side_faces)
    : worker_count_(workers), assignment_(assignment), side_faces_(side_faces) {
  if (workers < 1) throw std::invalid_argument("CellPrefetch: at least one worker thread");
}

CellPrefetch::~CellPrefetch() {
  {
    std::lock_guard<std::mutex> held(lock_);
    stopping_ = true;
  }
  work_ready_.notify_all();
  threads_.clear();  // joins
}

std::int64_t CellPrefetch::cells_by_workers() const {
  std::lock_guard<std::mutex> held(lock_);
  return by_workers_;
}

// The renderers are made here, on the simulation's thread, before any worker runs.
void CellPrefetch::start_workers(const Scene& scene, const HemicubeOptions& options) {
  for (int i = 0; i < worker_count_; ++i) renderers_.push_back(std::make_unique<HemicubeRenderer>(scene, options));
  for (int i = 0; i < worker_count_; ++i) threads_.emplace_back([this, r = renderers_[i].get()] { work(*r); });
}

CellPrefetch::Batch& CellPrefetch::batch_for(const HemicubeRenderer& renderer, int step, int nodes) {
  const Key key{step, renderer.projection()->shooter};
  if (auto it = batches_.find(key); it != batches_.end()) return it->second;
  Batch& b = batches_[key];
  b.projection = renderer.projection();
  const int cells = renderer.cell_count();
  b.cells.resize(std::size_t(cells));
  b.left = cells;
  // Replicas run their loops in id order on the simulation's thread, each taking its cells in turn.
  for (int r = 0; r < nodes; ++r)
    for (int c : cells_of(assignment_, r, nodes, cells, side_faces_)) b.order.push_back(c);
  work_ready_.notify_all();
  return b;
}

CellFormFactors CellPrefetch::take(HemicubeRenderer& renderer, const Scene& scene, int step, int cell, int nodes,
                                   OpCounts& ops) {
  if (threads_.empty()) start_workers(scene, renderer.options());
  std::unique_lock<std::mutex> held(lock_);
  const Key key{step, renderer.projection()->shooter};
  Batch& b = batch_for(renderer, step, nodes);
  Cell& c = b.cells.at(std::size_t(cell));
  CellFormFactors out;
  if (c.state == State::pending) {  // no worker has it: compute it here, as without prefetching
    c.state = State::running;
    held.unlock();
    out = renderer.cell_form_factors(cell, ops);
    held.lock();
  } else {
    help_while_running(renderer, b, c, held);
    if (c.failure) std::rethrow_exception(c.failure);
    out = std::move(c.ff);
    ops += c.ops;
  }
  c.state = State::done;
  if (--b.left == 0) batches_.erase(key);
  return out;
}

// While a worker computes the cell a replica needs, the replica's thread computes the batch's next
// pending cells (its renderer holds the same projection) instead of sleeping.
void CellPrefetch::help_while_running(HemicubeRenderer& renderer, Batch& b, Cell& needed, std::unique_lock<std::mutex>& held) {
  while (needed.state != State::done) {
    Cell* other = nullptr;
    int cell = -1;
    while (b.next < b.order.size() && !other) {
      cell = b.order[b.next++];
      if (b.cells[std::size_t(cell)].state == State::pending) other = &b.cells[std::size_t(cell)];
    }
    if (!other) {
      cell_done_.wait(held, [&] { return needed.state == State::done; });
      return;
    }
    other->state = State::running;
    held.unlock();
    OpCounts ops;
    CellFormFactors ff;
    std::exception_ptr failure;  // another replica's cell: a failure goes to that replica
    try {
      ff = renderer.cell_form_factors(cell, ops);
    } catch (...) {
      failure = std::current_exception();
    }
    held.lock();
    other->ff = std::move(ff);
    other->ops = ops;
    other->failure = failure;
    other->state = State::done;
    cell_done_.notify_all();
  }
}

std::pair<CellPrefetch::Cell*, int> CellPrefetch::claim(std::shared_ptr<const HemicubeProjection>& projection) {
  for (auto& [key, b] : batches_) {
    while (b.next < b.order.size()) {
      const int cell = b.order[b.next++];
      Cell& c = b.cells[std::size_t(cell)];
      if (c.state != State::pending) continue;  // a replica took it first
      c.state = State::running;
      projection = b.projection;
      return {&c, cell};
    }
  }
  return {nullptr, -1};
}

void CellPrefetch::work(HemicubeRenderer& renderer) {
  std::unique_lock<std::mutex> held(lock_);
  for (;;) {
    if (stopping_) return;  // a run that ended early leaves cells nobody will take
    std::shared_ptr<const HemicubeProjection> projection;
    auto [c, cell] = claim(projection);
    if (!c) {
      work_ready_.wait(held);
      continue;
    }
    held.unlock();
    CellFormFactors ff;
    OpCounts ops;
    std::exception_ptr failure;
    try {
      OpCounts projecting;  // counted by the replica that projected, not here
      if (renderer.projection() != projection) renderer.use_projection(projection, projecting);
      ff = renderer.cell_form_factors(cell, ops);
    } catch (...) {
      failure = std::current_exception();
    }
    held.lock();
    // The batch stays while this cell is running: it is erased only once every cell was taken.
    c->ff = std::move(ff);
    c->ops = ops;
    c->failure = failure;
    c->state = State::done;
    ++by_workers_;
    cell_done_.notify_all();
  }
}

}  // namespace gcsim::radiosity
