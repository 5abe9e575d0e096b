#include "apps/media/tile_farm.hpp"

#include <cstring>
#include <deque>
#include <vector>

namespace gcsim::media {
namespace {

constexpr int kTileTag = 41;
constexpr int kPrefetch = 2;  // tiles a worker holds, so it never idles for a round trip

// A worker: takes assignments (int32 tile, −1 to stop), renders them in order and sends each record
// back as [int32 tile][record].
void worker(parix::Processor& p, const TileFarm& farm) {
  parix::Link master = p.connect(0, kTileTag);
  std::deque<std::int32_t> queue;
  std::vector<parix::Request> sends;
  std::vector<parix::Bytes> records;  // alive until their sends complete
  bool stopped = false;
  parix::Request pending = p.irecv(master);
  parix::Bytes b;  // each assignment, received in place (take_into recycles the storage)
  for (;;) {
    while (!stopped && (pending.done() || queue.empty())) {
      p.wait(pending);
      pending.take_into(b);
      std::int32_t t;
      if (b.size() != sizeof t) throw parix::ParixError("media: malformed tile assignment");
      std::memcpy(&t, b.data(), sizeof t);
      if (t < 0) stopped = true;
      else queue.push_back(t), pending = p.irecv(master);
    }
    if (queue.empty()) break;
    const std::int32_t t = queue.front();
    queue.pop_front();
    const parix::Bytes r = farm.render(p, t);
    parix::Bytes& out = records.emplace_back(sizeof t + r.size());
    std::memcpy(out.data(), &t, sizeof t);
    if (!r.empty()) std::memcpy(out.data() + sizeof t, r.data(), r.size());
    sends.push_back(p.isend(master, out));
  }
  for (auto& s : sends) p.wait(s);
}

// Node 0 opens its links to every worker at once (one thread each), so the set-up times overlap.
std::vector<parix::Link> connect_to_workers(parix::Processor& p) {
  std::vector<parix::Link> links(static_cast<std::size_t>(p.count()));
  std::vector<parix::Thread> openers;
  for (int w = 1; w < p.count(); ++w)
    openers.push_back(p.spawn([&links, w](parix::Processor& q) { links[w] = q.connect(w, kTileTag); }));
  for (auto& t : openers) t.join();
  return links;
}

}  // namespace

TileFarmStats run_tile_farm(parix::Processor& p, const TileFarm& farm) {
  if (p.id() != 0) {
    worker(p, farm);
    return {};
  }
  TileFarmStats stats;
  const int n = p.count();
  int next = 0;
  // The master's own CPU-bound work runs on a thread (the node's second CPU) sharing the tile pool.
  parix::Thread local = p.spawn([&](parix::Processor& q) {
    while (next < farm.tiles) {
      const int t = next++;
      const parix::Bytes r = farm.render(q, t);
      farm.assemble(q, t, r);
    }
  });
  std::vector<parix::Link> links = connect_to_workers(p);
  std::vector<int> outstanding(static_cast<std::size_t>(n), 0);
  std::vector<std::int32_t> sent;  // alive until the sends complete
  sent.reserve(static_cast<std::size_t>(farm.tiles + n));
  std::vector<parix::Request> sends;
  auto assign = [&](int w) {
    sent.push_back(next < farm.tiles ? next++ : -1);
    if (sent.back() >= 0) ++outstanding[w], ++stats.assignments;
    sends.push_back(p.isend(links[w], std::as_bytes(std::span(&sent.back(), 1))));
  };
  for (int w = 1; w < n; ++w)
    for (int k = 0; k < kPrefetch && next < farm.tiles; ++k) assign(w);
  std::vector<parix::Request> recvs(static_cast<std::size_t>(n));
  for (int w = 1; w < n; ++w)
    if (outstanding[w] > 0) recvs[w] = p.irecv(links[w]);
  parix::Bytes record;  // each tile's record, received in place (take_into recycles the storage)
  for (;;) {
    std::vector<parix::Request*> waiting;
    std::vector<int> who;
    for (int w = 1; w < n; ++w)
      if (outstanding[w] > 0) waiting.push_back(&recvs[w]), who.push_back(w);
    if (waiting.empty()) break;
    const int w = who[p.wait_any(waiting)];
    recvs[w].take_into(record);
    --outstanding[w];
    std::int32_t t;
    if (record.size() < sizeof t) throw parix::ParixError("media: truncated tile record");
    std::memcpy(&t, record.data(), sizeof t);
    if (t < 0 || t >= farm.tiles) throw parix::ParixError("media: tile record names no tile");
    stats.result_bytes += record.size();
    farm.assemble(p, t, std::span(record).subspan(sizeof t));
    if (next < farm.tiles) assign(w);
    if (outstanding[w] > 0) recvs[w] = p.irecv(links[w]);
  }
  for (int w = 1; w < n; ++w) assign(w);  // every worker's stop
  for (auto& s : sends) p.wait(s);
  local.join();
  return stats;
}

}  // namespace gcsim::media
