#include "apps/raytrace/tile_prefetch.hpp"

#include <stdexcept>

namespace gcsim::raytrace {

TilePrefetch::TilePrefetch(const Scene& scene, const Bvh& bvh, const RenderSettings& settings, const Tiling& tiling,
                           std::vector<int> order, int workers)
    : scene_(scene), bvh_(bvh), settings_(settings), tiling_(tiling), order_(std::move(order)),
      slots_(std::size_t(tiling.count())) {
  if (workers < 1) throw std::invalid_argument("TilePrefetch: at least one worker thread");
  if (!usable(settings_.algorithm)) throw std::invalid_argument("TilePrefetch: B1's beams depend on the rays traced before");
  for (int i = 0; i < workers; ++i) renderers_.push_back(std::make_unique<TileRenderer>(scene_, bvh_, settings_));
  for (int i = 0; i < workers; ++i) threads_.emplace_back([this, r = renderers_[std::size_t(i)].get()] { work(*r); });
}

TilePrefetch::~TilePrefetch() {
  {
    std::lock_guard<std::mutex> held(lock_);
    stopping_ = true;
  }
  threads_.clear();  // joins
}

std::int64_t TilePrefetch::tiles_by_workers() const {
  std::lock_guard<std::mutex> held(lock_);
  return by_workers_;
}

RenderedTile TilePrefetch::render(int tile, TileRenderer& r) const {
  if (tile < 0 || tile >= tiling_.count()) throw std::out_of_range("TilePrefetch: no such tile");
  const Tiling::Rect rect = tiling_.rect(tile);
  const std::size_t pixels = std::size_t(rect.x1 - rect.x0) * std::size_t(rect.y1 - rect.y0);
  RenderedTile out{std::vector<glm::vec3>(pixels), std::vector<std::int32_t>(pixels), {}, {}};
  r.render_tile(rect.x0, rect.y0, rect.x1, rect.y1, out.colors, out.prims, out.counters, &out.row_counters);
  return out;
}

int TilePrefetch::claim() {
  while (next_ < order_.size()) {
    const int t = order_[next_++];
    if (slots_[std::size_t(t)].state != State::pending) continue;  // a node took it first
    slots_[std::size_t(t)].state = State::running;
    return t;
  }
  return -1;
}

RenderedTile TilePrefetch::take(int tile, TileRenderer& own) {
  std::unique_lock<std::mutex> held(lock_);
  Slot& s = slots_.at(std::size_t(tile));
  if (s.state == State::pending) {  // no worker has it: render it here
    s.state = State::running;
    held.unlock();
    RenderedTile out = render(tile, own);
    held.lock();
    s.state = State::done;
    return out;
  }
  // A worker has it: render the next pending tiles here meanwhile (they keep for their nodes).
  while (s.state != State::done) {
    const int other = claim();
    if (other < 0) {
      tile_done_.wait(held, [&] { return s.state == State::done; });
      break;
    }
    held.unlock();
    RenderedTile done = render(other, own);
    held.lock();
    slots_[std::size_t(other)].tile = std::move(done);
    slots_[std::size_t(other)].state = State::done;
  }
  if (s.failure) std::rethrow_exception(s.failure);
  return std::move(s.tile);
}

void TilePrefetch::work(TileRenderer& renderer) {
  std::unique_lock<std::mutex> held(lock_);
  for (;;) {
    if (stopping_) return;
    const int t = claim();
    if (t < 0) return;  // every tile is handed out: this worker is done
    held.unlock();
    RenderedTile done;
    std::exception_ptr failure;
    try {
      done = render(t, renderer);
    } catch (...) {
      failure = std::current_exception();
    }
    held.lock();
    slots_[std::size_t(t)].tile = std::move(done);
    slots_[std::size_t(t)].failure = failure;
    slots_[std::size_t(t)].state = State::done;
    ++by_workers_;
    tile_done_.notify_all();
  }
}

}  // namespace gcsim::raytrace
