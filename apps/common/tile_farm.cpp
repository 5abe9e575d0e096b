#include "apps/common/tile_farm.hpp"

#include <cstring>
#include <deque>

namespace gcsim::apps {
namespace {

// An assignment as it travels (TileFarm::format); nullopt is the stop.
parix::Bytes encode(AssignmentFormat format, const std::optional<TileRun>& run) {
  const std::int32_t first = run ? run->first : -1, count = run ? run->count : 0;
  if (format == AssignmentFormat::single_tile) {
    parix::Bytes b(sizeof first);
    std::memcpy(b.data(), &first, sizeof first);
    return b;
  }
  parix::Bytes b(sizeof first + sizeof count);
  std::memcpy(b.data(), &first, sizeof first);
  std::memcpy(b.data() + sizeof first, &count, sizeof count);
  return b;
}

// The pool's next run, refused if the farm cannot send it (checked wherever a run is drawn, so
// also when node 0 renders it itself).
std::optional<TileRun> take_run(const TileFarm& farm) {
  std::optional<TileRun> run = farm.next_run();
  if (run && (run->first < 0 || run->count < 1))
    throw parix::ParixError("tile farm: the pool gave a run with no tiles or a negative first tile");
  if (run && farm.format == AssignmentFormat::single_tile && run->count != 1)
    throw parix::ParixError("tile farm: a single-tile farm was given a run of several tiles");
  return run;
}

std::optional<TileRun> decode(AssignmentFormat format, const parix::Bytes& b) {
  TileRun run;
  const std::size_t expected = format == AssignmentFormat::single_tile ? sizeof run.first : sizeof run.first + sizeof run.count;
  if (b.size() != expected) throw parix::ParixError("tile farm: malformed tile assignment");
  std::memcpy(&run.first, b.data(), sizeof run.first);
  if (format == AssignmentFormat::tile_run) std::memcpy(&run.count, b.data() + sizeof run.first, sizeof run.count);
  if (run.first < 0) return std::nullopt;
  return run;
}

// Renders a run's tiles in order; their records, concatenated.
void render_run(parix::Processor& p, const TileFarm& farm, const TileRun& run, parix::Bytes& records) {
  for (int t = run.first; t < run.first + run.count; ++t) {
    const parix::Bytes r = farm.render(p, t);
    records.insert(records.end(), r.begin(), r.end());
  }
}

// A worker: takes in every assignment that has arrived, blocking only when it has nothing to do,
// renders the runs in order and sends each run's records back.
void worker(parix::Processor& p, const TileFarm& farm) {
  parix::Link master = p.connect(0, farm.tag);
  std::deque<TileRun> queue;
  std::vector<parix::Request> sends;
  std::deque<parix::Bytes> results;  // alive until their sends complete
  bool stopped = false;
  parix::Request pending = p.irecv(master);
  parix::Bytes b;  // each assignment, received in place (take_into recycles the storage)
  for (;;) {
    while (!stopped && (pending.done() || queue.empty())) {
      p.wait(pending);
      pending.take_into(b);
      const std::optional<TileRun> run = decode(farm.format, b);
      if (!run) stopped = true;
      else queue.push_back(*run), pending = p.irecv(master);
    }
    if (queue.empty()) break;
    const TileRun run = queue.front();
    queue.pop_front();
    render_run(p, farm, run, results.emplace_back());
    sends.push_back(p.isend(master, results.back()));
  }
  for (auto& s : sends) p.wait(s);
}

// Node 0's side of the farm: what it has handed out to whom, and the sends in flight.
class Master {
 public:
  Master(parix::Processor& p, const TileFarm& farm)
      : p_(p), farm_(farm), links_(connect_root_to_all(p, farm.tag)), outstanding_(std::size_t(p.count()), 0),
        stop_sent_(std::size_t(p.count()), false) {}

  TileFarmStats run() {
    const int n = p_.count();
    for (int w = 1; w < n; ++w)
      for (int k = 0; k < farm_.prefetch && !stop_sent_[w]; ++k)
        if (!hand_out(w)) break;
    std::vector<parix::Request> recvs(static_cast<std::size_t>(n));
    for (int w = 1; w < n; ++w)
      if (outstanding_[w] > 0) recvs[w] = p_.irecv(links_[w]);
    parix::Bytes records;  // each run's records, received in place (take_into recycles the storage)
    for (;;) {
      std::vector<parix::Request*> waiting;
      std::vector<int> who;
      for (int w = 1; w < n; ++w)
        if (outstanding_[w] > 0) waiting.push_back(&recvs[w]), who.push_back(w);
      if (waiting.empty()) break;
      const int w = who[p_.wait_any(waiting)];
      recvs[w].take_into(records);
      --outstanding_[w];
      stats_.result_bytes += records.size();
      farm_.assemble(p_, records);
      if (!stop_sent_[w]) hand_out(w);
      if (outstanding_[w] > 0) recvs[w] = p_.irecv(links_[w]);
    }
    for (int w = 1; w < n; ++w)
      if (!stop_sent_[w]) send(w, std::nullopt);
    for (auto& s : sends_) p_.wait(s);
    return stats_;
  }

 private:
  // Sends worker w its next run; when the pool is dry, its stop (StopTiming::when_dry) or nothing.
  // False when the pool is dry.
  bool hand_out(int w) {
    const std::optional<TileRun> run = take_run(farm_);
    if (run) {
      ++outstanding_[w], ++stats_.assignments;
      send(w, run);
    } else if (farm_.stops == StopTiming::when_dry) {
      send(w, std::nullopt);
    }
    return run.has_value();
  }

  void send(int w, const std::optional<TileRun>& run) {
    if (!run) stop_sent_[w] = true;
    sent_.push_back(encode(farm_.format, run));
    sends_.push_back(p_.isend(links_[w], sent_.back()));
  }

  parix::Processor& p_;
  const TileFarm& farm_;
  std::vector<parix::Link> links_;
  std::vector<int> outstanding_;  // runs assigned to a worker and not yet returned
  std::vector<bool> stop_sent_;
  std::deque<parix::Bytes> sent_;  // alive until the sends complete
  std::vector<parix::Request> sends_;
  TileFarmStats stats_;
};

}  // namespace

std::vector<parix::Link> connect_root_to_all(parix::Processor& p, int tag) {
  std::vector<parix::Link> links(std::size_t(p.count()));
  std::vector<parix::Thread> openers;
  for (int w = 1; w < p.count(); ++w)
    openers.push_back(p.spawn([&links, w, tag](parix::Processor& q) { links[w] = q.connect(w, tag); }));
  for (auto& t : openers) t.join();
  return links;
}

TileFarmStats run_tile_farm(parix::Processor& p, const TileFarm& farm) {
  if (p.id() != 0) {
    worker(p, farm);
    return {};
  }
  // The master's own CPU-bound work runs on a thread (the node's second CPU) sharing the pool.
  parix::Thread local = p.spawn([&farm](parix::Processor& q) {
    for (std::optional<TileRun> run = take_run(farm); run; run = take_run(farm))
      for (int t = run->first; t < run->first + run->count; ++t) farm.assemble(q, farm.render(q, t));
  });
  const TileFarmStats stats = Master(p, farm).run();
  local.join();
  return stats;
}

}  // namespace gcsim::apps
