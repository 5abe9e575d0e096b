#include "apps/radiosity/progressive_solver.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <string>
#include <unordered_map>

#include "apps/radiosity/convergence.hpp"

namespace gcsim::radiosity {

ProgressiveState::ProgressiveState(const Scene& scene, const PathTransmittance* media, const std::vector<Rgb>* received)
    : scene_(&scene), media_(media) {
  element_b_.resize(scene.elements.size());
  unshot_.resize(scene.patches.size());
  for (std::size_t e = 0; e < scene.elements.size(); ++e) element_b_[e] = scene.surface_of_element(int(e)).exitance;
  for (std::size_t p = 0; p < scene.patches.size(); ++p) {
    const ScenePatch& sp = scene.patches[p];
    unshot_[p] = scene.surfaces[sp.surface].exitance;
    energy_.emitted += unshot_[p] * sp.area;
  }
  energy_.unshot = energy_.emitted;
  if (received) receive(*received);
  emitted_sum_ = channel_sum(energy_.unshot);
}

void ProgressiveState::receive(const std::vector<Rgb>& received) {
  if (received.size() != scene_->elements.size())
    throw std::invalid_argument("received power: one value per element expected, got " + std::to_string(received.size()) +
                                " for " + std::to_string(scene_->elements.size()) + " elements");
  // None at all changes no bit: the unshot sum is not recomputed in another order.
  if (std::ranges::all_of(received, [](const Rgb& r) { return r == Rgb(0.0); })) return;
  for (std::size_t e = 0; e < received.size(); ++e) {
    const SceneElement& el = scene_->elements[e];
    const Rgb rho = scene_->surfaces[scene_->patches[el.patch].surface].reflectance;
    const Rgb rad = rho * received[e] / el.area;
    element_b_[e] += rad;
    unshot_[el.patch] += rad * (el.area / scene_->patches[el.patch].area);
    energy_.injected += received[e];
    energy_.absorbed += (Rgb(1.0) - rho) * received[e];
  }
  energy_.unshot = total_unshot();
}

std::vector<int> ProgressiveState::select_shooters(int k, OpCounts& ops) const {
  std::vector<int> order;
  ops.patch_select += std::int64_t(unshot_.size());
  for (int p = 0; p < int(unshot_.size()); ++p)
    if (unshot_energy(p) > 0) order.push_back(p);
  auto larger = [&](int a, int b) {
    double ea = unshot_energy(a), eb = unshot_energy(b);
    return ea != eb ? ea > eb : a < b;
  };
  int n = std::min<int>(k, int(order.size()));
  std::partial_sort(order.begin(), order.begin() + n, order.end(), larger);
  order.resize(n);
  return order;
}

std::vector<int> ProgressiveState::select_in_index_order(int k, OpCounts& ops) {
  std::vector<int> out;
  const int n = int(unshot_.size());
  for (int looked = 0; looked < n && int(out.size()) < k; ++looked) {
    int p = (cursor_ + looked) % n;
    ++ops.patch_select;
    if (unshot_energy(p) > 0) out.push_back(p);
  }
  if (!out.empty()) cursor_ = (out.back() + 1) % n;
  return out;
}

ShootingOrder parse_shooting_order(const std::string& s) {
  if (s == "energy") return ShootingOrder::energy;
  if (s == "index") return ShootingOrder::index;
  if (s == "energy-then-index") return ShootingOrder::energy_then_index;
  throw std::invalid_argument("unknown shooting order '" + s + "': expected energy, index or energy-then-index");
}

const char* to_string(ShootingOrder o) {
  switch (o) {
    case ShootingOrder::energy: return "energy";
    case ShootingOrder::index: return "index";
    default: return "energy-then-index";
  }
}

void ProgressiveState::shoot(std::span<const int> shooters, std::span<const std::vector<double>> rows,
                             OpCounts& ops) {
  if (shooters.size() != rows.size()) throw std::invalid_argument("shoot: one form factor row per shooter");
  // Every shooter shoots what it had at the start of the step.
  std::vector<Rgb> delta(shooters.size());
  for (std::size_t k = 0; k < shooters.size(); ++k) {
    delta[k] = unshot_[shooters[k]];
    unshot_[shooters[k]] = Rgb(0.0);
  }
  for (std::size_t k = 0; k < shooters.size(); ++k) {
    const ScenePatch& sp = scene_->patches[shooters[k]];
    const std::vector<double>& f = rows[k];
    const Rgb shot = delta[k] * sp.area;  // delta B_i * A_i
    double caught = 0;
    for (std::size_t e = 0; e < f.size(); ++e) {
      if (f[e] == 0) continue;
      ++ops.element_update;
      const SceneElement& el = scene_->elements[e];
      const Rgb rho = scene_->surfaces[scene_->patches[el.patch].surface].reflectance;
      Rgb received = shot * f[e];                       // energy reaching element e
      if (media_) {
        ++ops.path_transmittance;
        const Rgb through = media_->between(sp.center, el.center);
        energy_.in_media += received * (Rgb(1.0) - through);
        received *= through;
      }
      const Rgb rad = rho * received / el.area;         // delta Rad = rho dB_i F_ie A_i / A_e
      element_b_[e] += rad;
      unshot_[el.patch] += rad * (el.area / scene_->patches[el.patch].area);
      energy_.absorbed += (Rgb(1.0) - rho) * received;
      caught += f[e];
    }
    energy_.escaped += shot * std::max(0.0, 1.0 - caught);
  }
  energy_.unshot = total_unshot();
  ++steps_;
}

Rgb ProgressiveState::total_unshot() const {
  Rgb u(0.0);
  for (std::size_t p = 0; p < unshot_.size(); ++p) u += unshot_[p] * scene_->patches[p].area;
  return u;
}

double ProgressiveState::shot_fraction() const {
  if (emitted_sum_ <= 0) return 1.0;
  return 1.0 - channel_sum(energy_.unshot) / emitted_sum_;
}

std::vector<Rgb> ProgressiveState::patch_radiosity() const {
  std::vector<Rgb> b(scene_->patches.size(), Rgb(0.0));
  for (std::size_t e = 0; e < element_b_.size(); ++e) {
    const SceneElement& el = scene_->elements[e];
    b[el.patch] += element_b_[e] * (el.area / scene_->patches[el.patch].area);
  }
  return b;
}

namespace {

// SolverOptions::row_memo_bytes: rows kept by shooter, each with the counts computing it added.
class RowMemo {
 public:
  RowMemo(std::int64_t bytes, std::size_t elements)
      : rows_left_(elements > 0 ? bytes / std::int64_t(elements * sizeof(double) + sizeof(OpCounts)) : 0) {}
  std::vector<double> row(HemicubeRenderer& hemicube, int shooter, OpCounts& ops) {
    if (const auto kept = kept_.find(shooter); kept != kept_.end()) {
      ops += kept->second.cost;
      return kept->second.row;
    }
    OpCounts cost;
    std::vector<double> row = hemicube.form_factor_row(shooter, cost);
    ops += cost;
    if (rows_left_ > 0) --rows_left_, kept_.emplace(shooter, Kept{row, cost});
    return row;
  }

 private:
  struct Kept {
    std::vector<double> row;
    OpCounts cost;
  };
  std::int64_t rows_left_;
  std::unordered_map<int, Kept> kept_;
};

}  // namespace

SolveResult solve_progressive(const Scene& scene, const SolverOptions& o, OpCounts* ops_out,
                              const std::function<void(const StepRecord&, const ProgressiveState&)>& on_step) {
  if (o.shooters < 1) throw std::invalid_argument("shooters per step must be at least 1");
  check_energy_can_be_absorbed(scene, o.hemicube);
  SolveResult r{ProgressiveState(scene, o.media, o.received), {}, false};
  HemicubeRenderer hemicube(scene, o.hemicube);
  RowMemo memo(o.row_memo_bytes, scene.elements.size());
  OpCounts local;
  OpCounts& ops = ops_out ? *ops_out : local;
  while (r.state.shot_fraction() < o.energy && r.state.steps() < o.max_steps) {
    std::vector<int> shooters = sorts_this_step(o, r.state.shot_fraction())
                                    ? r.state.select_shooters(o.shooters, ops)
                                    : r.state.select_in_index_order(o.shooters, ops);
    if (shooters.empty()) break;
    std::vector<std::vector<double>> rows;
    for (int s : shooters) rows.push_back(memo.row(hemicube, s, ops));
    r.state.shoot(shooters, rows, ops);
    StepRecord rec{r.state.steps(), r.state.shot_fraction(), shooters};
    if (on_step) on_step(rec, r.state);
    r.steps.push_back(std::move(rec));
  }
  r.converged = r.state.shot_fraction() >= o.energy;
  return r;
}

}  // namespace gcsim::radiosity
