// How a loop's form factors travel (form_factor_exchange.hpp): exchanged together, K = 2 shooters'
// form factors take one all-node exchange instead of two, so a loop has 2 exchanges instead of 3;
// the radiosities, the compute and the bytes exchanged are the same.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <stdexcept>

#include "apps/radiosity/form_factor_exchange.hpp"
#include "apps/radiosity/parallel_radiosity.hpp"
#include "test_scenes.hpp"

namespace gcsim::radiosity {
namespace {

TEST(FormFactorExchange, NamesParseBackAndUnknownOnesAreRefused) {
  EXPECT_EQ(parse_form_factor_exchange("together"), FormFactorExchange::together);
  EXPECT_EQ(parse_form_factor_exchange(to_string(FormFactorExchange::per_shooter)), FormFactorExchange::per_shooter);
  EXPECT_THROW(parse_form_factor_exchange("joint"), std::invalid_argument);
}

testing::SimulatedRun run_with(const Scene& scene, FormFactorExchange exchange, parix::BcastAlgo bcast, int nodes) {
  ParallelOptions o = testing::quick_parallel_options(bcast);
  o.ff_exchange = exchange;
  return testing::run_published(scene, o, nodes);
}

TEST(FormFactorExchange, TogetherSavesOneExchangeInThreeAndChangesNoRadiosity) {
  const Scene scene = testing::lit_room();
  for (parix::BcastAlgo bcast : {parix::BcastAlgo::sequential, parix::BcastAlgo::tree}) {
    const int nodes = 4;
    const testing::SimulatedRun apart = run_with(scene, FormFactorExchange::per_shooter, bcast, nodes);
    const testing::SimulatedRun together = run_with(scene, FormFactorExchange::together, bcast, nodes);
    ASSERT_EQ(together.out.element_radiosity, apart.out.element_radiosity);
    ASSERT_EQ(together.out.exchanged_bytes, apart.out.exchanged_bytes);
    // A loop of s shooters: 1 + s exchanges apart, 2 together. An all-node exchange (sequential or
    // tree) sends 2 (N - 1) messages whatever it carries.
    std::int64_t saved = 0;
    for (const StepRecord& s : apart.out.steps) saved += std::int64_t(s.shooters.size()) - 1;
    ASSERT_GT(saved, 10);
    EXPECT_EQ(apart.result.total_messages() - together.result.total_messages(), saved * 2 * (nodes - 1));
    for (int i = 0; i < nodes; ++i) {
      const parix::ProcessorStats &a = apart.result.processors[std::size_t(i)],
                                  &b = together.result.processors[std::size_t(i)];
      // The same operations; charged in fewer batches, each rounded to the picosecond.
      EXPECT_LE(std::abs(std::int64_t(b.compute - a.compute)), saved) << i;
      EXPECT_LT(b.comm, a.comm) << i;
    }
  }
}

}  // namespace
}  // namespace gcsim::radiosity
