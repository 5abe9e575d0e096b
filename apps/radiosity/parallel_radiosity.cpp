#include "apps/radiosity/parallel_radiosity.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include <fmt/format.h>

#include "apps/radiosity/convergence.hpp"

namespace gcsim::radiosity {

ParallelAlgorithm parse_parallel_algorithm(const std::string& s) {
  if (s == "hemicube-fixed") return ParallelAlgorithm::hemicube_fixed;
  if (s == "hemicube-hierarchical") return ParallelAlgorithm::hemicube_hierarchical;
  if (s == "patch") return ParallelAlgorithm::patch;
  throw std::invalid_argument(
      fmt::format("unknown parallel algorithm '{}': expected hemicube-fixed, hemicube-hierarchical or patch", s));
}

const char* to_string(ParallelAlgorithm a) {
  switch (a) {
    case ParallelAlgorithm::hemicube_fixed: return "hemicube-fixed";
    case ParallelAlgorithm::hemicube_hierarchical: return "hemicube-hierarchical";
    default: return "patch";
  }
}

namespace {

// Byte packing of plain values.
struct Writer {
  parix::Bytes bytes;
  template <class T>
  void put(const T& v) {
    std::size_t at = bytes.size();
    bytes.resize(at + sizeof(T));
    std::memcpy(bytes.data() + at, &v, sizeof(T));
  }
};
struct Reader {
  const parix::Bytes& bytes;
  std::size_t at = 0;
  template <class T>
  T get() {
    if (at + sizeof(T) > bytes.size()) throw std::runtime_error("radiosity: truncated message");
    T v;
    std::memcpy(&v, bytes.data() + at, sizeof(T));
    at += sizeof(T);
    return v;
  }
};

struct Proposal {
  double energy;
  std::int32_t patch;
};

// Per shooter, per cell: the cell's sparse form factor sums.
void put_cell(Writer& w, const CellFormFactors& c) {
  w.put<std::int32_t>(c.cell);
  w.put<std::int32_t>(std::int32_t(c.element.size()));
  for (std::size_t k = 0; k < c.element.size(); ++k) {
    w.put<std::int32_t>(c.element[k]);
    w.put<double>(c.value[k]);
  }
}
CellFormFactors get_cell(Reader& r) {
  CellFormFactors c;
  c.cell = r.get<std::int32_t>();
  int n = r.get<std::int32_t>();
  c.element.resize(n);
  c.value.resize(n);
  for (int k = 0; k < n; ++k) {
    c.element[k] = r.get<std::int32_t>();
    c.value[k] = r.get<double>();
  }
  return c;
}

}  // namespace

std::int64_t replica_bytes(const Scene& scene) {
  return std::int64_t(scene.elements.size()) * 176 + std::int64_t(scene.patches.size()) * 120 +
         std::int64_t(scene.vertices.size()) * 24;
}

ParallelOptions with_shared_projections(ParallelOptions o) {
  o.shared_projections = o.share_projections ? std::make_shared<ProjectionCache>() : nullptr;
  return o;
}

HemicubeOptions hemicube_of(const ParallelOptions& o) {
  HemicubeOptions hc = o.solver.hemicube;
  if (o.algorithm == ParallelAlgorithm::hemicube_hierarchical) hc.hierarchical_levels = o.hierarchical_levels;
  return hc;
}

void radiosity_program(parix::Processor& p, const Scene& scene, const ParallelOptions& o, ParallelOutcome* outcome) {
  // Refused before any work (every replica decides alike): a closed scene that never absorbs.
  check_energy_can_be_absorbed(scene, o.solver.hemicube);
  const int id = p.id(), n = p.count();
  const int np = int(scene.patches.size()), ne = int(scene.elements.size());
  // Declared before the host builds them, so that a node too small fails at once.
  const parix::MemoryReservation replica = p.reserve_memory(replica_bytes(scene), "scene replica");

  const HemicubeOptions hc = hemicube_of(o);
  const parix::MemoryReservation buffers = p.reserve_memory(hemicube_buffer_bytes(hc), "hemicube");
  HemicubeRenderer renderer(scene, hc);
  const int cells = renderer.cell_count();

  parix::CollectiveOptions coll;
  coll.algo = o.bcast;
  coll.connect_per_message = !o.keep_links;

  ProgressiveState state(scene);
  OpCounts ops;
  std::vector<StepRecord> steps;
  std::int64_t exchanged = 0;
  const int k_shooters = o.solver.shooters;
  if (k_shooters < 1) throw std::invalid_argument("shooters per step must be at least 1");

  while (state.shot_fraction() < o.solver.energy && state.steps() < o.solver.max_steps) {
    // 1. Choose the shooters.
    std::vector<int> shooters;
    if (!sorts_this_step(o.solver, state.shot_fraction())) {
      // 4.4.1: index order needs no exchange; every replica knows the next patches.
      shooters = state.select_in_index_order(k_shooters, ops);
      ops.charge(p);
    } else if (o.aggregate) {
      shooters = state.select_shooters(k_shooters, ops);
      ops.charge(p);
    } else {
      // Each node proposes its own K best; the K best of all proposals are the global K best.
      std::vector<Proposal> mine;
      {
        std::vector<int> own;
        ops.patch_select += (np - id + n - 1) / n;
        for (int q = id; q < np; q += n)
          if (state.unshot_energy(q) > 0) own.push_back(q);
        auto larger = [&](int a, int b) {
          double ea = state.unshot_energy(a), eb = state.unshot_energy(b);
          return ea != eb ? ea > eb : a < b;
        };
        int m = std::min<int>(k_shooters, int(own.size()));
        std::partial_sort(own.begin(), own.begin() + m, own.end(), larger);
        for (int i = 0; i < m; ++i) mine.push_back({state.unshot_energy(own[i]), own[i]});
      }
      ops.charge(p);
      auto all = parix::allgather_vectors<Proposal>(p, std::span<const Proposal>(mine), coll);
      exchanged += std::int64_t(mine.size() * sizeof(Proposal));
      std::vector<Proposal> merged;
      for (auto& v : all) merged.insert(merged.end(), v.begin(), v.end());
      std::sort(merged.begin(), merged.end(), [](const Proposal& a, const Proposal& b) {
        return a.energy != b.energy ? a.energy > b.energy : a.patch < b.patch;
      });
      ops.patch_select += std::int64_t(merged.size());
      for (int i = 0; i < std::min<int>(k_shooters, int(merged.size())); ++i) shooters.push_back(merged[i].patch);
    }
    if (shooters.empty()) break;

    // 2. This node's share of the form factors, and 3. the all-node exchange. Unaggregated, as in
    // the thesis, every shooter's delta form factors are exchanged on their own; aggregated, one
    // exchange carries every shooter's.
    std::vector<std::vector<CellFormFactors>> by_cell(shooters.size(), std::vector<CellFormFactors>(cells));
    auto compute_share = [&](std::size_t k, Writer& w) {
      int s = shooters[k];
      const bool patch_mode = o.algorithm == ParallelAlgorithm::patch;
      if (patch_mode && s % n != id) return;
      if (o.shared_projections) o.shared_projections->project(renderer, state.steps(), s, ops);
      else renderer.project(s, ops);
      for (int c = patch_mode ? 0 : id; c < cells; c += patch_mode ? 1 : n) {
        w.put<std::int32_t>(std::int32_t(k));
        put_cell(w, renderer.cell_form_factors(c, ops));
      }
    };
    auto absorb = [&](const std::vector<parix::Bytes>& all) {
      for (const parix::Bytes& b : all) {
        Reader r{b};
        while (r.at < b.size()) {
          int k = r.get<std::int32_t>();
          CellFormFactors c = get_cell(r);
          if (k < 0 || k >= int(shooters.size()) || c.cell < 0 || c.cell >= cells)
            throw std::runtime_error("radiosity: malformed form factor message");
          by_cell[k][c.cell] = std::move(c);
        }
      }
    };
    auto exchange = [&](Writer& w, int owner) {
      exchanged += std::int64_t(w.bytes.size());
      ops.charge(p);
      if (owner >= 0) {
        // Patch partition: the shooter's owner has the whole row; it broadcasts it.
        absorb({parix::broadcast(p, owner, owner == id ? std::move(w.bytes) : parix::Bytes{}, coll)});
      } else {
        absorb(parix::allgather(p, w.bytes, coll));
      }
    };
    if (o.aggregate) {
      Writer w;
      for (std::size_t k = 0; k < shooters.size(); ++k) compute_share(k, w);
      exchange(w, -1);
    } else {
      for (std::size_t k = 0; k < shooters.size(); ++k) {
        Writer w;
        compute_share(k, w);
        exchange(w, o.algorithm == ParallelAlgorithm::patch ? shooters[k] % n : -1);
      }
    }

    // 4. Every node assembles the rows, adding cells in the fixed cell order, and shoots.
    std::vector<std::vector<double>> rows(shooters.size(), std::vector<double>(ne, 0.0));
    for (std::size_t k = 0; k < shooters.size(); ++k)
      for (int c = 0; c < cells; ++c) {
        const CellFormFactors& cf = by_cell[k][c];
        ops.form_factor_sum += std::int64_t(cf.element.size());
        for (std::size_t i = 0; i < cf.element.size(); ++i) rows[k][cf.element[i]] += cf.value[i];
      }
    state.shoot(shooters, rows, ops);
    ops.charge(p);
    StepRecord rec{state.steps(), state.shot_fraction(), shooters};
    if (id == 0) {
      steps.push_back(std::move(rec));
      if (o.on_loop) o.on_loop(state.steps(), state.shot_fraction());
      if (outcome && std::find(o.snapshot_loops.begin(), o.snapshot_loops.end(), state.steps()) != o.snapshot_loops.end())
        outcome->snapshots.emplace_back(state.steps(), state.element_radiosity());
    }
  }
  ops.charge(p);
  if (id == 0 && outcome) {
    outcome->element_radiosity = state.element_radiosity();
    outcome->steps = std::move(steps);
    outcome->energy = state.energy();
    outcome->converged = state.shot_fraction() >= o.solver.energy;
    outcome->exchanged_bytes = exchanged;
  }
}

}  // namespace gcsim::radiosity
