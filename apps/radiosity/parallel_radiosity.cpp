#include "apps/radiosity/parallel_radiosity.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include <fmt/format.h>

#include "apps/radiosity/convergence.hpp"
#include "apps/radiosity/received_form_factors.hpp"

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

struct Proposal {
  double energy;
  std::int32_t patch;
};

}  // namespace

std::int64_t replica_bytes(const Scene& scene) {
  return std::int64_t(scene.elements.size()) * 176 + std::int64_t(scene.patches.size()) * 120 +
         std::int64_t(scene.vertices.size()) * 24;
}

ParallelOptions with_shared_projections(ParallelOptions o) {
  o.shared_projections = o.share_projections ? std::make_shared<ProjectionCache>() : nullptr;
  o.cell_prefetch = o.host_threads > 1 ? std::make_shared<CellPrefetch>(o.host_threads - 1, o.cell_assignment, o.side_faces) : nullptr;
  return o;
}

ParallelOptions with_shared_projections(ParallelOptions o, const parix::RunOptions& run) {
  if (run.backend == "simulated") o.host_threads = run.host_threads;
  return with_shared_projections(std::move(o));
}

HemicubeOptions hemicube_of(const ParallelOptions& o) {
  HemicubeOptions hc = o.solver.hemicube;
  if (o.algorithm == ParallelAlgorithm::hemicube_hierarchical) hc.hierarchical_levels = o.hierarchical_levels;
  return hc;
}

namespace {

// One processor's part of the parallel progressive solver (thesis 4.4): each loop chooses the
// shooters, computes this node's share of their form factors, exchanges the shares, and every
// replica shoots alike. Operations are charged at the same points in every variant, so the
// simulated time depends only on the options.
class RadiosityNode {
 public:
  RadiosityNode(parix::Processor& p, const Scene& scene, const ParallelOptions& o)
      : p_(p), o_(o), scene_(scene), id_(p.id()), n_(p.count()), np_(int(scene.patches.size())), ne_(int(scene.elements.size())),
        renderer_(scene, hemicube_of(o), o.shared_projections ? &o.shared_projections->samples_per_side() : nullptr),
        cells_(renderer_.cell_count()), state_(scene, o.solver.media, o.solver.received) {
    coll_.algo = o.bcast;
    coll_.connect_per_message = !o.keep_links;
    if (o.solver.shooters < 1) throw std::invalid_argument("shooters per step must be at least 1");
  }

  void solve() {
    if (o_.solver.received && !o_.solver.received->empty()) {
      // Each element took its received power before the first shot (ProgressiveState's receive).
      ops_.element_update += std::int64_t(o_.solver.received->size());
      ops_.charge(p_);
    }
    while (state_.shot_fraction() < o_.solver.energy && state_.steps() < o_.solver.max_steps) {
      const std::vector<int> shooters = choose_shooters();
      if (shooters.empty()) break;
      exchange_form_factors(shooters);
      shoot(shooters);
    }
    ops_.charge(p_);
  }

  void write(ParallelOutcome& outcome) {
    outcome.element_radiosity = state_.element_radiosity();
    outcome.steps = std::move(steps_);
    outcome.energy = state_.energy();
    outcome.converged = state_.shot_fraction() >= o_.solver.energy;
    outcome.exchanged_bytes = exchanged_;
  }

  ParallelOutcome* snapshots_to = nullptr;  // node 0's outcome, for --snapshot loops

 private:
  // 1. The shooters of this loop, identical on every node.
  std::vector<int> choose_shooters() {
    const int k = o_.solver.shooters;
    if (!sorts_this_step(o_.solver, state_.shot_fraction())) {
      // 4.4.1: index order needs no exchange; every replica knows the next patches.
      std::vector<int> shooters = state_.select_in_index_order(k, ops_);
      ops_.charge(p_);
      return shooters;
    }
    if (o_.aggregate) {
      std::vector<int> shooters = state_.select_shooters(k, ops_);
      ops_.charge(p_);
      return shooters;
    }
    return propose_and_merge(k);
  }

  // Each node proposes its own K best; the K best of all proposals are the global K best.
  std::vector<int> propose_and_merge(int k) {
    std::vector<int> own;
    ops_.patch_select += (np_ - id_ + n_ - 1) / n_;
    for (int q = id_; q < np_; q += n_)
      if (state_.unshot_energy(q) > 0) own.push_back(q);
    auto larger = [&](int a, int b) {
      double ea = state_.unshot_energy(a), eb = state_.unshot_energy(b);
      return ea != eb ? ea > eb : a < b;
    };
    const int m = std::min<int>(k, int(own.size()));
    std::partial_sort(own.begin(), own.begin() + m, own.end(), larger);
    std::vector<Proposal> mine;
    for (int i = 0; i < m; ++i) mine.push_back({state_.unshot_energy(own[i]), own[i]});
    ops_.charge(p_);
    std::vector<Proposal> merged = parix::allgather_concatenated<Proposal>(p_, std::span<const Proposal>(mine), coll_);
    exchanged_ += std::int64_t(mine.size() * sizeof(Proposal));
    std::sort(merged.begin(), merged.end(), [](const Proposal& a, const Proposal& b) {
      return a.energy != b.energy ? a.energy > b.energy : a.patch < b.patch;
    });
    ops_.patch_select += std::int64_t(merged.size());
    std::vector<int> shooters;
    for (int i = 0; i < std::min<int>(k, int(merged.size())); ++i) shooters.push_back(merged[i].patch);
    return shooters;
  }

  // 2. This node's share of the form factors, and 3. the all-node exchange: every shooter's delta
  // form factors on their own, or (aggregated, or exchanged together) one exchange for all.
  void exchange_form_factors(const std::vector<int>& shooters) {
    received_.reset(int(shooters.size()), cells_);
    const bool patch_mode = o_.algorithm == ParallelAlgorithm::patch;
    if (o_.aggregate || o_.ff_exchange == FormFactorExchange::together) {
      parix::Bytes w;
      for (std::size_t k = 0; k < shooters.size(); ++k) compute_share(shooters, k, w);
      exchange(w, -1, int(shooters.size()));
    } else {
      for (std::size_t k = 0; k < shooters.size(); ++k) {
        parix::Bytes w;
        compute_share(shooters, k, w);
        exchange(w, patch_mode ? shooters[k] % n_ : -1, 1);
      }
    }
  }

  void compute_share(const std::vector<int>& shooters, std::size_t k, parix::Bytes& w) {
    const int s = shooters[k];
    const bool patch_mode = o_.algorithm == ParallelAlgorithm::patch;
    if (patch_mode && s % n_ != id_) return;
    if (o_.shared_projections) o_.shared_projections->project(renderer_, state_.steps(), s, ops_);
    else renderer_.project(s, ops_);
    // Patch partition: the shooter's owner computes every cell.
    for (int c : cells_of(o_.cell_assignment, patch_mode ? 0 : id_, patch_mode ? 1 : n_, cells_, o_.side_faces))
      put_cell_form_factors(w, std::int32_t(k), cell(c, patch_mode));
  }

  CellFormFactors cell(int c, bool patch_mode) {
    if (!o_.cell_prefetch || patch_mode) return renderer_.cell_form_factors(c, ops_);
    return o_.cell_prefetch->take(renderer_, scene_, state_.steps(), c, n_, ops_);
  }

  // owner >= 0 (patch partition): the shooter's owner has the whole row and broadcasts it.
  // Otherwise every node's part of `shooters` shooters, merged as o_.merge says.
  void exchange(parix::Bytes& w, int owner, int shooters) {
    exchanged_ += std::int64_t(w.size());
    ops_.charge(p_);
    if (owner >= 0) {
      received_.absorb(parix::broadcast(p_, owner, owner == id_ ? std::move(w) : parix::Bytes{}, coll_));
      return;
    }
    received_.absorb(parix::allgather_views(p_, w, coll_));
    if (const std::int64_t adds = merge_additions(o_.merge, n_, cells_, ne_); adds > 0)
      p_.compute_in_comm("form_factor_merge", adds * shooters);
  }

  // 4. Every node assembles the rows, adding cells in the fixed cell order, and shoots.
  void shoot(const std::vector<int>& shooters) {
    std::vector<std::vector<double>> rows(shooters.size(), std::vector<double>(ne_, 0.0));
    ops_.form_factor_sum += received_.add_rows(rows);
    state_.shoot(shooters, rows, ops_);
    ops_.charge(p_);
    if (id_ != 0) return;
    steps_.push_back(StepRecord{state_.steps(), state_.shot_fraction(), shooters});
    if (o_.on_loop) o_.on_loop(state_.steps(), state_.shot_fraction());
    if (snapshots_to && std::ranges::find(o_.snapshot_loops, state_.steps()) != o_.snapshot_loops.end())
      snapshots_to->snapshots.emplace_back(state_.steps(), state_.element_radiosity());
  }

  parix::Processor& p_;
  const ParallelOptions& o_;
  const Scene& scene_;
  const int id_, n_, np_, ne_;
  HemicubeRenderer renderer_;
  const int cells_;
  parix::CollectiveOptions coll_;
  ProgressiveState state_;
  OpCounts ops_;
  ReceivedFormFactors received_;  // this loop's form factors, from every node
  std::vector<StepRecord> steps_;
  std::int64_t exchanged_ = 0;
};

}  // namespace

namespace {

// One node's solve: its replica written to `mine`; node 0 also records the snapshots there.
void solve_on(parix::Processor& p, const Scene& scene, const ParallelOptions& o, ParallelOutcome& mine) {
  // Refused before any work (every replica decides alike): a closed scene that never absorbs.
  check_energy_can_be_absorbed(scene, o.solver.hemicube);
  // Declared before the host builds them, so that a node too small fails at once.
  const parix::MemoryReservation replica = p.reserve_memory(replica_bytes(scene), "scene replica");
  const parix::MemoryReservation buffers = p.reserve_memory(hemicube_buffer_bytes(hemicube_of(o)), "hemicube");
  RadiosityNode node(p, scene, o);
  if (p.id() == 0) node.snapshots_to = &mine;
  node.solve();
  node.write(mine);
}

}  // namespace

void radiosity_program(parix::Processor& p, const Scene& scene, const ParallelOptions& o, ParallelOutcome* outcome) {
  ParallelOutcome local;
  solve_on(p, scene, o, p.id() == 0 && outcome ? *outcome : local);
}

ParallelOutcome solve_replica(parix::Processor& p, const Scene& scene, const ParallelOptions& o) {
  ParallelOutcome mine;
  solve_on(p, scene, o, mine);
  return mine;
}

}  // namespace gcsim::radiosity
