// The fitter recovers parameters from figures that a known machine produced; the one-node
// shortcut predicts exactly what a full run does.
#include "apps/calibration/calibration.hpp"

#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include <fmt/format.h>

namespace gcsim::calibration {
namespace {

TEST(LeastSquares, FitsAnExponentialExactly) {
  // y = a exp(-b t) sampled without noise: the fit finds a and b, with zero standard errors.
  const double a = 3.5, b = 0.7;
  const Residuals f = [&](const std::vector<double>& x) {
    std::vector<double> r;
    for (int i = 0; i < 10; ++i) r.push_back(x[0] * std::exp(-x[1] * i * 0.5) - a * std::exp(-b * i * 0.5));
    return r;
  };
  const LeastSquaresResult res = least_squares(f, {1.0, 0.1}, 10);
  EXPECT_TRUE(res.converged) << res.reason;
  EXPECT_NEAR(res.x[0], a, 1e-6);
  EXPECT_NEAR(res.x[1], b, 1e-6);
  EXPECT_LT(res.sigma[0], 1e-6);
}

TEST(LeastSquares, RefusesMoreUnknownsThanFigures) {
  const Residuals f = [](const std::vector<double>& x) { return std::vector<double>{x[0]}; };
  EXPECT_THROW(least_squares(f, {1.0, 2.0}, 1), std::invalid_argument);
}

// Table 4.6 as a machine with known connection and link figures would measure it; the fit from
// the published values must find that machine again.
TEST(Calibrate, RecoversTheMachineThatProducedTheFigures) {
  const MachineFile file("");
  const std::map<std::string, double> truth = {{"network.connect_base_us", 700},
                                               {"network.connect_per_hop_us", 180},
                                               {"network.link_bandwidth_mbps", 3.0}};
  Predictor predictor(PredictionSettings{});
  MeasuredTable table = thesis_table("4.6");
  const Grid produced = predictor.predict({table}, file.with(truth))[0];
  const auto csv = std::filesystem::temp_directory_path() / fmt::format("gcsim_calibration_truth_{}.csv", ::getpid());
  {
    std::ofstream out(csv);
    out << "nodes,connect_only,1KB,4KB,16KB\n";
    for (std::size_t r = 0; r < table.nodes.size(); ++r)
      out << fmt::format("{},{:.17g},{:.17g},{:.17g},{:.17g}\n", table.nodes[r], produced[r][0], produced[r][1], produced[r][2],
                         produced[r][3]);
  }
  const CalibrationResult res = calibrate(file, {table_from_spec(csv.string() + ":4.6")},
                                          {"network.connect_base_us", "network.connect_per_hop_us", "network.link_bandwidth_mbps"},
                                          predictor);
  std::filesystem::remove(csv);
  ASSERT_TRUE(res.fit.converged) << res.fit.reason;
  for (const auto& p : res.parameters) EXPECT_NEAR(p.value / truth.at(p.key), 1.0, 1e-3) << p.key;
  for (const auto& c : res.cells) EXPECT_LT(std::abs(c.error()), 1e-4) << c.nodes << " " << c.column;
}

TEST(Predictor, OneNodeTimeFromCountsEqualsAFullRun) {
  PredictionSettings s;
  s.hemicube = 32;
  s.energy = 0.9;
  const MachineFile file("");
  MeasuredTable t = table_from_spec("4.3@1");
  Predictor warm(s);
  warm.predict({t}, file.config());  // keeps the counts
  const machine::MachineConfig other = file.with({{"ops.polygon_project", 3000}, {"ops.hemicube_pixel", 77}});
  const Grid from_counts = warm.predict({t}, other)[0];
  Predictor cold(s);
  const Grid full = cold.predict({t}, other)[0];
  for (std::size_t k = 0; k < t.columns.size(); ++k)
    EXPECT_NEAR(from_counts[0][k], full[0][k], 1e-9 * full[0][k]) << t.columns[k];
  EXPECT_EQ(warm.runs(), 3);  // the second prediction ran nothing
}

}  // namespace
}  // namespace gcsim::calibration
