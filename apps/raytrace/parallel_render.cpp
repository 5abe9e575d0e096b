#include "apps/raytrace/parallel_render.hpp"

#include <algorithm>
#include <cstring>
#include <memory>
#include <stdexcept>

#include "apps/common/tile_farm.hpp"
#include "apps/raytrace/pixel_encoding.hpp"
#include "apps/raytrace/render.hpp"
#include "apps/raytrace/scene.hpp"
#include "apps/raytrace/tile_prefetch.hpp"
#include "apps/raytrace/tile_sample.hpp"
#include "apps/raytrace/tile_renderer.hpp"
#include "parix/backend.hpp"
#include "parix/collectives.hpp"

namespace gcsim::raytrace {

std::optional<Distribution> parse_distribution(std::string_view s) {
  if (s == "static") return Distribution::static_blocks;
  if (s == "interleaved") return Distribution::interleaved;
  if (s == "dynamic") return Distribution::dynamic;
  return std::nullopt;
}

std::string_view name_of(Distribution d) {
  switch (d) {
    case Distribution::static_blocks: return "static";
    case Distribution::interleaved: return "interleaved";
    case Distribution::dynamic: return "dynamic";
  }
  return "?";
}

namespace {

constexpr int kTileTag = 40;

void append(parix::Bytes& out, const void* data, std::size_t n) {
  const std::size_t at = out.size();
  out.resize(at + n);
  std::memcpy(out.data() + at, data, n);
}

// A tile's colours and hit ids while it is rendered, and its packed record.
std::int64_t tile_buffer_bytes(std::int64_t pixels) {
  return pixels * std::int64_t(sizeof(glm::vec3) + sizeof(std::int32_t) + 3) + std::int64_t(sizeof(std::int32_t));
}

// What one processor does with the tiles it is given: renders, charges the operations, and packs
// the pixels as [int32 tile][8-bit sRGB ...] records.
struct NodeWork {
  const Scene& scene;
  const Bvh& bvh;
  const RenderSettings& settings;
  Tiling tiling;
  ParallelRender& out;     // node 0: the image; every node: its own check slot (counters, hit ids)
  TileRenderer& renderer;  // this processor's own (state: row planes, classifier)
  TilePrefetch* prefetch = nullptr;  // --host-threads: tiles rendered ahead on the host
  int row_y0 = -1, row_y1 = -1;      // with prefetch: the row this node's tracer last filtered
  int pixel_row_stride = 1;          // the plan's sample: one pixel row in k traced, its counts scaled to the tile

  // The tile's pixels and counts, as this node's tracer gives them: rendered now, or taken from
  // the prefetch with its row's planes counted only if the row is new to this node (as the
  // tracer's own row state decides).
  void render_tile(const Tiling::Rect& rect, int tile, std::vector<glm::vec3>& colors, std::vector<std::int32_t>& prims,
                   TraceCounters& c) {
    if (!prefetch) {
      renderer.render_tile(rect.x0, rect.y0, rect.x1, rect.y1, colors, prims, c);
      return;
    }
    RenderedTile r = prefetch->take(tile, renderer);
    colors = std::move(r.colors);
    prims = std::move(r.prims);
    c = r.counters;
    if (rect.y0 != row_y0 || rect.y1 != row_y1) c += r.row_counters;
    row_y0 = rect.y0;
    row_y1 = rect.y1;
  }

  // One pixel row in pixel_row_stride, each traced as a one-row tile, the other rows left black;
  // returns the factor from the rows traced to the tile's (its counts are charged scaled by it).
  double render_rows(const Tiling::Rect& rect, std::vector<glm::vec3>& colors, std::vector<std::int32_t>& prims,
                     TraceCounters& c) {
    const int w = rect.x1 - rect.x0;
    int traced = 0;
    for (int y = rect.y0; y < rect.y1; y += pixel_row_stride, ++traced) {
      const std::size_t at = std::size_t(y - rect.y0) * std::size_t(w);
      renderer.render_tile(rect.x0, y, rect.x1, y + 1, std::span(colors).subspan(at, std::size_t(w)),
                           std::span(prims).subspan(at, std::size_t(w)), c);
    }
    return double(rect.y1 - rect.y0) / double(std::max(traced, 1));
  }

  parix::Bytes render(parix::Processor& p, int tile) {
    const auto rect = tiling.rect(tile);
    const parix::MemoryReservation buffers = p.reserve_memory(tile_buffer_bytes(rect.pixels()), "image tile");
    std::vector<glm::vec3> colors(rect.pixels());
    std::vector<std::int32_t> prims(rect.pixels());
    TraceCounters c;
    // The plan's row sample runs without host threads (a prefetched tile is whole).
    double scale = 1.0;
    if (pixel_row_stride > 1 && !prefetch) scale = render_rows(rect, colors, prims, c);
    else render_tile(rect, tile, colors, prims, c);
    std::vector<parix::OpCount> ops;
    for (const auto& [name, count] : c.ops())
      if (count > 0) ops.push_back({name, scale == 1.0 ? count : std::llround(double(count) * scale)});
    p.compute(ops);
    out.per_node[p.id()] += c;
    ++out.tiles_per_node[p.id()];
    ++out.tiles_rendered;
    if (out.on_tile) out.on_tile(out.tiles_rendered, out.tiles_total);
    out.node_prims[p.id()].push_back({tile, std::move(prims)});  // check-only: not sent, merged after the run
    parix::Bytes b;
    const std::int32_t t = tile;
    append(b, &t, sizeof t);
    for (const glm::vec3& c : colors)
      for (int k = 0; k < 3; ++k) b.push_back(static_cast<std::byte>(encode_srgb8(c[k])));
    return b;
  }

  // Node 0 unpacks tile records into the image (charged as memory copies).
  void assemble(parix::Processor& p, std::span<const std::byte> records) {
    std::size_t at = 0;
    while (at + sizeof(std::int32_t) <= records.size()) {
      std::int32_t t;
      std::memcpy(&t, records.data() + at, sizeof t);
      at += sizeof t;
      if (t < 0 || t >= tiling.count()) throw parix::ParixError("raytrace: corrupt tile record");
      const auto rect = tiling.rect(t);
      const std::size_t bytes = std::size_t(rect.pixels()) * 3;
      if (records.size() - at < bytes) throw parix::ParixError("raytrace: truncated tile record");
      const std::byte* px = records.data() + at;
      for (int y = rect.y0; y < rect.y1; ++y)
        for (int x = rect.x0; x < rect.x1; ++x, px += 3)
          out.image.at(x, y) = glm::vec3(decode_srgb8(std::uint8_t(px[0])), decode_srgb8(std::uint8_t(px[1])),
                                         decode_srgb8(std::uint8_t(px[2])));
      at += bytes;
      p.compute("memcpy_byte", static_cast<std::int64_t>(bytes));
    }
  }
};

void run_static(parix::Processor& p, NodeWork& work, Distribution d) {
  const int n = p.count(), me = p.id(), tiles = work.tiling.count();
  std::vector<int> my_tiles;
  if (d == Distribution::static_blocks) {
    const int begin = int(std::int64_t(tiles) * me / n), end = int(std::int64_t(tiles) * (me + 1) / n);
    for (int t = begin; t < end; ++t) my_tiles.push_back(t);
  } else {
    for (int t = me; t < tiles; t += n) my_tiles.push_back(t);
  }
  // The packed pixels of every tile this node renders, held until they are sent.
  std::int64_t record_bytes = 0;
  for (int t : my_tiles) record_bytes += std::int64_t(sizeof(std::int32_t)) + 3 * std::int64_t(work.tiling.rect(t).pixels());
  const parix::MemoryReservation records = p.reserve_memory(record_bytes, "rendered tiles");
  parix::Bytes mine;
  for (int t : my_tiles) {
    parix::Bytes b = work.render(p, t);
    mine.insert(mine.end(), b.begin(), b.end());
  }
  // Every node sends its pixels straight to node 0, which takes them in as they arrive.
  if (me != 0) {
    parix::Link root = p.connect(0, kTileTag);
    p.send(root, mine);
    return;
  }
  work.assemble(p, mine);
  if (n == 1) return;
  std::vector<parix::Link> links = apps::connect_root_to_all(p, kTileTag);
  std::vector<parix::Request> recvs(n);
  std::vector<parix::Request*> waiting;
  std::vector<int> who;
  for (int w = 1; w < n; ++w) recvs[w] = p.irecv(links[w]);
  for (int left = n - 1; left > 0; --left) {
    waiting.clear();
    who.clear();
    for (int w = 1; w < n; ++w)
      if (recvs[w].valid()) {
        waiting.push_back(&recvs[w]);
        who.push_back(w);
      }
    const int w = who[p.wait_any(waiting)];
    work.assemble(p, recvs[w].take());
    recvs[w] = parix::Request{};
  }
}

// Guided self-scheduling: a request is answered with a run of consecutive tiles of one row, about
// 1/(4N) of what is left (at least one, at most kRunTiles). Early runs are long, so there are few messages and
// neighbouring tiles share their row planes (2.2.1); the last runs are single tiles, so the
// nodes finish together.
// next: a position in order (the tiles to hand out, whole rows of them, by index). scale: image
// tiles per tile of order (a sample's runs sized as the whole image's would be there).
std::optional<apps::TileRun> next_run(int& next, const std::vector<int>& order, int tiles_x, int nodes, double scale) {
  const int tiles = int(order.size());
  if (next >= tiles) return std::nullopt;
  const int first = order[std::size_t(next)], left_in_row = tiles_x - first % tiles_x;
  int consecutive = 1;  // a run is consecutive tiles of one row (a sample's order skips some)
  while (consecutive < std::min(left_in_row, kRunTiles) && next + consecutive < tiles &&
         order[std::size_t(next + consecutive)] == first + consecutive)
    ++consecutive;
  const int count = std::clamp(int(double(tiles - next) * scale) / (4 * nodes), 1, consecutive);
  next += count;
  return apps::TileRun{first, count};
}

// The tile farm (apps/common/tile_farm.hpp) with the guided runs: each assignment is a run (int32
// first and count), a worker asking when the pool is dry gets its stop at once, and a run's
// records travel in one message; two runs ahead per worker, so none idles during a round trip.
void run_dynamic(parix::Processor& p, NodeWork& work, const std::vector<int>& order, double scale) {
  const int n = p.count(), tiles_x = work.tiling.tiles_x();
  int next = 0;  // node 0's pool
  apps::TileFarm farm{.tag = kTileTag, .prefetch = 2, .format = apps::AssignmentFormat::tile_run,
                      .stops = apps::StopTiming::when_dry};
  farm.next_run = [&]() { return next_run(next, order, tiles_x, n, scale); };
  farm.render = [&work](parix::Processor& q, int t) { return work.render(q, t); };
  farm.assemble = [&work](parix::Processor& q, std::span<const std::byte> records) { work.assemble(q, records); };
  apps::run_tile_farm(p, farm);
}

}  // namespace

ParallelRenderJob::ParallelRenderJob(const Scene& scene, const Bvh& bvh, const RenderSettings& settings,
                                     Distribution distribution)
    : scene_(scene), bvh_(bvh), settings_(settings), distribution_(distribution) {
  if (uses_subtree(settings_.algorithm)) pairs_ = std::make_shared<const PreparedChildPairs>(bvh_);
  for (int t = 0; t < Tiling{settings_.width, settings_.height, settings_.tile}.count(); ++t) order_.push_back(t);
}

ParallelRender ParallelRenderJob::new_result(int nodes) const {
  ParallelRender out;
  out.image = apps::Image(settings_.width, settings_.height);
  out.per_node.assign(nodes, TraceCounters{});
  out.tiles_per_node.assign(nodes, 0);
  out.node_prims.assign(nodes, {});
  out.tiles_total = Tiling{settings_.width, settings_.height, settings_.tile}.count();
  return out;
}

std::unique_ptr<TilePrefetch> ParallelRenderJob::make_prefetch(int nodes, int host_threads) const {
  if (host_threads <= 1 || !TilePrefetch::usable(settings_.algorithm)) return nullptr;
  const Tiling tiling{settings_.width, settings_.height, settings_.tile};
  // The order tiles are handed out in: by index, except static blocks, which the nodes render side by side.
  std::vector<int> order;
  const int tiles = tiling.count();
  if (distribution_ == Distribution::static_blocks) {
    for (int i = 0; int(order.size()) < tiles; ++i)
      for (int n = 0; n < nodes; ++n) {
        const int begin = int(std::int64_t(tiles) * n / nodes), end = int(std::int64_t(tiles) * (n + 1) / nodes);
        if (begin + i < end) order.push_back(begin + i);
      }
  } else {
    for (int t = 0; t < tiles; ++t) order.push_back(t);
  }
  return std::make_unique<TilePrefetch>(scene_, bvh_, settings_, tiling, std::move(order), host_threads - 1);
}

void ParallelRenderJob::program(parix::Processor& p, ParallelRender& out, TilePrefetch* prefetch) const {
  // What each node holds: the scene and the tree; node 0 the image.
  const parix::MemoryReservation scene = p.reserve_memory(scene_bytes(), "scene");
  const parix::MemoryReservation image = p.reserve_memory(p.id() == 0 ? image_bytes() : 0, "image");
  // Built here, by the processor that uses it (on the heap: fiber stacks are small).
  const auto renderer = std::make_unique<TileRenderer>(scene_, bvh_, settings_, pairs_.get());
  NodeWork work{scene_, bvh_, settings_, Tiling{settings_.width, settings_.height, settings_.tile}, out, *renderer, prefetch};
  work.pixel_row_stride = pixel_row_stride_;
  if (distribution_ == Distribution::dynamic) run_dynamic(p, work, order_, schedule_scale_);
  else run_static(p, work, distribution_);
}

void ParallelRenderJob::sample_tiles(int stride) {
  if (distribution_ != Distribution::dynamic) throw std::invalid_argument("raytrace: only a dynamic render samples tiles");
  const Tiling tiling{settings_.width, settings_.height, settings_.tile};
  order_ = sampled_tiles(tiling, stride, kRunTiles);
  schedule_scale_ = order_.empty() ? 1.0 : double(tiling.count()) / double(order_.size());
}

void ParallelRenderJob::sample_pixel_rows(int stride) { pixel_row_stride_ = std::max(stride, 1); }

int ParallelRenderJob::tiles_rendered_per_run() const {
  return int(order_.size());
}

std::int64_t ParallelRenderJob::scene_bytes() const {
  return std::int64_t(scene_.spheres.size()) * sizeof(Sphere) + std::int64_t(scene_.triangles.size()) * sizeof(Triangle) +
         std::int64_t(bvh_.nodes.size()) * sizeof(BvhNode) + std::int64_t(bvh_.prim_bounds.size()) * sizeof(Bounds3);
}

std::int64_t ParallelRenderJob::tile_bytes() const {
  return tile_buffer_bytes(std::int64_t(settings_.tile) * settings_.tile);
}

void ParallelRenderJob::finish(ParallelRender& out) const {
  out.counters = TraceCounters{};
  for (const auto& c : out.per_node) out.counters += c;
  const Tiling tiling{settings_.width, settings_.height, settings_.tile};
  out.prim_ids.assign(std::size_t(settings_.width) * settings_.height, -1);
  for (const auto& tiles : out.node_prims)
    for (const auto& [tile, prims] : tiles) {
      const auto rect = tiling.rect(tile);
      const int w = rect.x1 - rect.x0;
      for (int y = rect.y0; y < rect.y1; ++y)
        for (int x = rect.x0; x < rect.x1; ++x)
          out.prim_ids[std::size_t(y) * settings_.width + x] = prims[std::size_t(y - rect.y0) * w + (x - rect.x0)];
    }
  out.node_prims.clear();
}

ParallelRender render_parallel(const Scene& scene, const Bvh& bvh, const RenderSettings& settings, Distribution distribution,
                               const parix::SimulationOptions& options, int host_threads) {
  const ParallelRenderJob job(scene, bvh, settings, distribution);
  ParallelRender out = job.new_result(options.config.nodes);
  const std::unique_ptr<TilePrefetch> prefetch = job.make_prefetch(options.config.nodes, host_threads);
  out.run = parix::run({"simulated", options}, [&](parix::Processor& p) { job.program(p, out, prefetch.get()); });
  if (prefetch) out.tiles_by_workers = prefetch->tiles_by_workers();
  job.finish(out);
  return out;
}

}  // namespace gcsim::raytrace
