#include "apps/radiosity/accuracy.hpp"

#include <chrono>
#include <cmath>

#include "apps/radiosity/gauss_seidel.hpp"
#include "apps/radiosity/hemicube.hpp"
#include "parix/host/interruption.hpp"

namespace gcsim::radiosity {

namespace {
machine::SimTime simulated_time(const OpCounts& ops, const machine::MachineConfig& m) {
  machine::SimTime t = 0;
  for (const auto& o : ops.named())
    if (o.count > 0) t += machine::op_time(m, o.op, o.count);
  return t;
}
}  // namespace

double simulated_seconds(const OpCounts& ops, const machine::MachineConfig& m) {
  return machine::to_seconds(simulated_time(ops, m));
}

double now_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

void stop_if_interrupted(const OpCounts& ops, const machine::MachineConfig& m) {
  if (!parix::host::interruption_requested()) return;
  parix::RunResult reached;
  reached.nodes = 1;
  reached.makespan = simulated_time(ops, m);
  throw parix::host::Interrupted(std::move(reached));
}

namespace {
template <class Row>
void hand_over(std::vector<Row>& rows, const Row& row, const std::function<void(const Row&)>& on_row) {
  rows.push_back(row);
  if (on_row) on_row(row);
}
double row_sum(const std::vector<double>& row, const Scene& s, int patch) {
  double f = 0;
  const ScenePatch& p = s.patches[patch];
  for (int e = p.first_element; e < p.first_element + p.element_count; ++e) f += row[e];
  return f;
}
}  // namespace

std::vector<FormFactorAccuracy> form_factor_accuracy(const std::vector<int>& resolutions,
                                                     const machine::MachineConfig& m,
                                                     const std::function<void(const FormFactorAccuracy&)>& on_row) {
  std::vector<FormFactorAccuracy> out;
  for (FormFactorCase c : {FormFactorCase::parallel_squares, FormFactorCase::perpendicular_squares,
                           FormFactorCase::patch_to_disc})
    for (int res : resolutions) {
      FormFactorAccuracy a{c, res, 0, 0, 0, 0, 0, 0};
      double t0 = now_seconds();
      OpCounts ops;
      HemicubeOptions ho;
      ho.resolution = res;
      ho.cells_per_side = 8;
      FormFactorSetup one = form_factor_setup(c, 1.0, 1);
      {
        HemicubeRenderer r(one.scene, ho);
        a.hemicube_point = row_sum(r.form_factor_row(0, ops), one.scene, one.receiver_patch);
        a.exact_point = one.exact_point;
      }
      if (c == FormFactorCase::patch_to_disc) {
        a.hemicube_area = a.hemicube_point;  // the patch is small: its centre stands for it
        a.exact_area = one.exact_area;
      } else {
        // F(A1 -> A2) = 1/A1 * integral over A1 of F(dA1 -> A2): the mean over an 8 x 8 grid of hemicubes.
        const int n = 8;
        FormFactorSetup grid = form_factor_setup(c, 1.0, n);
        HemicubeRenderer r(grid.scene, ho);
        double sum = 0;
        for (int p = 0; p < n * n; ++p) {
          stop_if_interrupted(ops, m);
          sum += row_sum(r.form_factor_row(p, ops), grid.scene, grid.receiver_patch);
        }
        a.hemicube_area = sum / (n * n);
        a.exact_area = grid.exact_area;
      }
      a.wall_seconds = now_seconds() - t0;
      a.simulated_seconds = simulated_seconds(ops, m);
      hand_over(out, a, on_row);
      stop_if_interrupted(ops, m);
    }
  return out;
}

std::vector<EnergyAccuracy> energy_accuracy(const Scene& scene, const SolverOptions& options,
                                            const std::vector<double>& thresholds, const machine::MachineConfig& m,
                                            const std::function<void(const EnergyAccuracy&)>& on_row) {
  GaussSeidelResult ref = solve_gauss_seidel(scene, options.hemicube);
  double mean_ref = 0, total_area = 0;
  for (std::size_t e = 0; e < scene.elements.size(); ++e) {
    mean_ref += channel_sum(ref.element_radiosity[e]) / 3 * scene.elements[e].area;
    total_area += scene.elements[e].area;
  }
  mean_ref /= total_area;
  std::vector<EnergyAccuracy> out;
  std::size_t next = 0;
  OpCounts ops;
  double t0 = now_seconds();
  auto measure = [&](const ProgressiveState& st, double threshold) {
    double sq = 0, worst = 0;
    const auto& b = st.element_radiosity();
    for (std::size_t e = 0; e < b.size(); ++e) {
      Rgb d = glm::abs(b[e] - ref.element_radiosity[e]) / mean_ref;
      double err = std::max({d.r, d.g, d.b});
      sq += err * err * scene.elements[e].area;
      worst = std::max(worst, err);
    }
    hand_over(out, {threshold, st.steps(), std::sqrt(sq / total_area), worst, simulated_seconds(ops, m), now_seconds() - t0},
              on_row);
  };
  SolverOptions o = options;
  o.energy = thresholds.empty() ? 0.999 : thresholds.back();
  solve_progressive(scene, o, &ops, [&](const StepRecord& rec, const ProgressiveState& st) {
    while (next < thresholds.size() && rec.shot_fraction >= thresholds[next]) measure(st, thresholds[next++]);
    stop_if_interrupted(ops, m);
  });
  return out;
}

std::vector<HierarchicalAccuracy> hierarchical_accuracy(const Scene& scene, const SolverOptions& options,
                                                        const std::vector<int>& levels,
                                                        const machine::MachineConfig& m,
                                                        const std::function<void(const HierarchicalAccuracy&)>& on_row) {
  std::vector<HierarchicalAccuracy> out;
  std::vector<Rgb> reference;
  double mean_ref = 0, total_area = 0;
  std::vector<int> all = {0};
  all.insert(all.end(), levels.begin(), levels.end());
  for (int l : all) {
    SolverOptions o = options;
    o.hemicube.hierarchical_levels = l;
    OpCounts ops;
    double t0 = now_seconds();
    SolveResult r = solve_progressive(scene, o, &ops, [&](const StepRecord&, const ProgressiveState&) { stop_if_interrupted(ops, m); });
    double wall = now_seconds() - t0;
    const auto& b = r.state.element_radiosity();
    if (l == 0) {
      reference = b;
      for (std::size_t e = 0; e < b.size(); ++e) {
        mean_ref += channel_sum(b[e]) / 3 * scene.elements[e].area;
        total_area += scene.elements[e].area;
      }
      mean_ref /= total_area;
    }
    double sq = 0, worst = 0;
    for (std::size_t e = 0; e < b.size(); ++e) {
      Rgb d = glm::abs(b[e] - reference[e]) / mean_ref;
      double err = std::max({d.r, d.g, d.b});
      sq += err * err * scene.elements[e].area;
      worst = std::max(worst, err);
    }
    hand_over(out, {l, r.state.steps(), std::sqrt(sq / total_area), worst, simulated_seconds(ops, m), wall}, on_row);
  }
  return out;
}

}  // namespace gcsim::radiosity
