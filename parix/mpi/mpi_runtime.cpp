#include "parix/mpi/mpi_runtime.hpp"

#include <mpi.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <deque>

#include <fmt/format.h>

#include "machine/interconnect.hpp"
#include "machine/interconnect_registry.hpp"
#include "parix/mpi/mpi_processor.hpp"
#include "parix/placement.hpp"

namespace gcsim::parix {
namespace {

// Little binary writer/reader for what the ranks send to the root at the end of a run.
struct Writer {
  Bytes out;
  template <class T>
  void put(const T& v) {
    const auto* b = reinterpret_cast<const std::byte*>(&v);
    out.insert(out.end(), b, b + sizeof(T));
  }
  void put_string(std::string_view s) {
    put<std::int64_t>(static_cast<std::int64_t>(s.size()));
    const auto* b = reinterpret_cast<const std::byte*>(s.data());
    out.insert(out.end(), b, b + s.size());
  }
};

struct Reader {
  const std::byte* at;
  template <class T>
  T get() {
    T v;
    std::memcpy(&v, at, sizeof(T));
    at += sizeof(T);
    return v;
  }
  std::string get_string() {
    const auto n = get<std::int64_t>();
    std::string s(reinterpret_cast<const char*>(at), static_cast<std::size_t>(n));
    at += n;
    return s;
  }
};

Bytes pack(const mpi::RankState& s, SimTime finish) {
  Writer w;
  const ProcessorStats& p = s.stats;
  for (SimTime t : {finish, p.compute, p.comm, p.connect}) w.put(t);
  for (std::int64_t v : {p.messages_sent, p.bytes_sent, p.connections}) w.put(v);
  w.put<std::int64_t>(static_cast<std::int64_t>(p.ops.size()));
  for (const auto& [op, n] : p.ops) w.put_string(op), w.put(n);
  w.put<std::int64_t>(static_cast<std::int64_t>(s.records.size()));
  for (const auto& r : s.records) {
    w.put(static_cast<int>(r.kind)), w.put(r.proc), w.put(r.peer), w.put(r.start), w.put(r.end), w.put(r.bytes), w.put(r.id),
        w.put(r.thread);
    w.put_string(r.label);
  }
  return std::move(w.out);
}

void unpack(const std::byte* data, ProcessorStats& p, std::vector<machine::TraceRecord>& records,
            std::deque<std::string>& labels) {
  Reader r{data};
  p.finish = r.get<SimTime>(), p.compute = r.get<SimTime>(), p.comm = r.get<SimTime>(), p.connect = r.get<SimTime>();
  p.messages_sent = r.get<std::int64_t>(), p.bytes_sent = r.get<std::int64_t>(), p.connections = r.get<std::int64_t>();
  for (auto n = r.get<std::int64_t>(); n > 0; --n) {
    std::string op = r.get_string();
    p.ops[op] = r.get<std::int64_t>();
  }
  for (auto n = r.get<std::int64_t>(); n > 0; --n) {
    machine::TraceRecord t;
    t.kind = static_cast<machine::TraceKind>(r.get<int>());
    t.proc = r.get<int>(), t.peer = r.get<int>(), t.start = r.get<SimTime>(), t.end = r.get<SimTime>();
    t.bytes = r.get<std::int64_t>(), t.id = r.get<std::int64_t>(), t.thread = r.get<int>();
    labels.push_back(r.get_string());
    t.label = labels.back();
    records.push_back(t);
  }
}

// Every rank's packed part, concatenated on the root (empty elsewhere), with offsets.
std::vector<Bytes> gather_parts(const Bytes& mine, int size) {
  int n = static_cast<int>(mine.size());
  std::vector<int> sizes(static_cast<std::size_t>(size)), offsets(static_cast<std::size_t>(size));
  MPI_Gather(&n, 1, MPI_INT, sizes.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  int total = 0;
  for (int i = 0; i < size; ++i) offsets[i] = total, total += sizes[i];
  Bytes all(static_cast<std::size_t>(mpi_rank() == 0 ? total : 0));
  MPI_Gatherv(mine.data(), n, MPI_BYTE, all.data(), sizes.data(), offsets.data(), MPI_BYTE, 0, MPI_COMM_WORLD);
  std::vector<Bytes> parts;
  if (mpi_rank() == 0)
    for (int i = 0; i < size; ++i) parts.emplace_back(all.begin() + offsets[i], all.begin() + offsets[i] + sizes[i]);
  return parts;
}

void write_trace(const SimulationOptions& o, const machine::MachineConfig& c, std::vector<machine::TraceRecord>& records) {
  std::sort(records.begin(), records.end(), [](const auto& a, const auto& b) {
    return a.start != b.start ? a.start < b.start : a.proc < b.proc;
  });
  const std::unique_ptr<machine::Interconnect> interconnect = machine::make_interconnect(c);
  machine::TraceWriter trace(o.trace, c.nodes, *interconnect);
  for (const auto& r : records) trace.record(r);
  trace.close();
}

}  // namespace

void mpi_initialize() {
  int initialized = 0;
  MPI_Initialized(&initialized);
  if (initialized) return;
  int provided = 0;
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_MULTIPLE, &provided);
  if (provided < MPI_THREAD_MULTIPLE) {
    std::fprintf(stderr, "gcsim: error: this MPI does not allow threads to call it at once (MPI_THREAD_MULTIPLE)\n");
    MPI_Abort(MPI_COMM_WORLD, 2);
  }
  std::atexit([] {
    int finalized = 0;
    MPI_Finalized(&finalized);
    if (!finalized) MPI_Finalize();
  });
}

int mpi_rank() {
  int r = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &r);
  return r;
}

int mpi_size() {
  int n = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &n);
  return n;
}

MpiRunResult run_mpi(const SimulationOptions& options, const std::function<void(Processor&)>& program) {
  mpi_initialize();
  const int size = mpi_size();
  const int nodes = options.config.nodes;
  if (nodes != size)
    throw ParixError(fmt::format("the MPI backend runs one processor per rank: {} ranks (mpirun -np {}) but {} nodes "
                                 "(expected --nodes {} or mpirun -np {})", size, size, nodes, size, nodes));
  const machine::MachineConfig& config = options.config;
  mpi::RankState state;
  state.rank = mpi_rank();
  state.size = size;
  // Processor i runs on rank placement[i], as it would run on node placement[i] when simulated.
  state.rank_of = checked_placement(options.placement, size);
  std::vector<int> processor_of_rank(static_cast<std::size_t>(size));
  for (int i = 0; i < size; ++i) processor_of_rank[static_cast<std::size_t>(state.rank_of[i])] = i;
  state.processor = processor_of_rank[static_cast<std::size_t>(state.rank)];
  state.memory = machine::NodeMemory(config.memory_bytes, options.memory_limit);
  state.tracing = !options.trace.path.empty() && options.trace.level != machine::TraceLevel::summary;
  MPI_Barrier(MPI_COMM_WORLD);
  const auto wall_start = std::chrono::steady_clock::now();
  state.epoch = wall_start;
  try {
    mpi::MpiProcessor p(state, 0);
    program(p);
  } catch (const std::exception& e) {
    // The other ranks would wait for this one forever: say what happened and end the job.
    std::fprintf(stderr, "gcsim: error: processor %d (rank %d): %s\n", state.processor, state.rank, e.what());
    MPI_Abort(MPI_COMM_WORLD, 1);
  }
  if (state.failure) {
    try {
      std::rethrow_exception(state.failure);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "gcsim: error: processor %d (rank %d, a spawned thread): %s\n", state.processor, state.rank,
                   e.what());
    }
    MPI_Abort(MPI_COMM_WORLD, 1);
  }
  const SimTime finish = state.now();
  state.stats.compute = std::max<SimTime>(0, finish - state.stats.comm);  // the rest of the time was the work
  const std::vector<Bytes> parts = gather_parts(pack(state, finish), size);
  MpiRunResult out;
  out.root = state.rank == 0;
  out.result.clock = Clock::wall;
  out.result.model = "mpi (wall-clock)";
  out.result.config_name = config.name;
  out.result.nodes = size;
  if (!out.root) {
    out.result.processors.push_back(state.stats);
    return out;
  }
  std::vector<machine::TraceRecord> records;
  std::deque<std::string> labels;
  out.result.processors.resize(static_cast<std::size_t>(size));
  for (int r = 0; r < size; ++r)
    unpack(parts[r].data(), out.result.processors[static_cast<std::size_t>(processor_of_rank[r])], records, labels);
  for (const auto& p : out.result.processors) out.result.makespan = std::max(out.result.makespan, p.finish);
  if (!options.trace.path.empty()) write_trace(options, config, records);
  out.result.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  return out;
}

}  // namespace gcsim::parix
