// The render's progress model (apps/pipeline/pass_progress.hpp) driven by made-up pass reports:
// no clock, no terminal, so nothing here depends on timing.
#include "apps/pipeline/pass_progress.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace gcsim::pipeline {
namespace {

PassProgress three_passes() { return PassProgress({{"media: photons", 1.0}, {"radiosity", 2.0}, {"view", 1.0}}); }

TEST(PassProgress, WeighsEachPassByItsPrediction) {
  PassProgress p = three_passes();
  EXPECT_DOUBLE_EQ(p.report(0, 0.5, 1.0).fraction, 0.5 / 4);
  EXPECT_DOUBLE_EQ(p.report(1, 0.5, 2.0).fraction, (1.0 + 1.0) / 4);
  EXPECT_DOUBLE_EQ(p.report(2, 0.0, 3.0).fraction, 3.0 / 4);
}

TEST(PassProgress, TimeLeftIsThePredictedRestAtThePaceOfTheWorkDone) {
  PassProgress p = three_passes();
  // The photons (predicted 1 of 4) took 2 s: 2 s per predicted unit, 3 units left.
  const PassProgressState s = p.report(1, 0.0, 2.0);
  ASSERT_TRUE(s.seconds_left.has_value());
  EXPECT_DOUBLE_EQ(*s.seconds_left, 6.0);
  // Radiosity goes faster than predicted: half of it (1 unit) in 0.5 s, so its other half takes
  // 0.5 s at its own pace; the view (1 unit) goes at the pace so far, 2.5 s for 2 units.
  EXPECT_DOUBLE_EQ(*p.report(1, 0.5, 2.5).seconds_left, 0.5 + 2.5 / 2.0);
  // Below a tenth of a pass done, its own pace is too noisy: the pace so far for all of it.
  PassProgress q = three_passes();
  q.report(1, 0.0, 2.0);
  EXPECT_DOUBLE_EQ(*q.report(1, 0.05, 2.01).seconds_left, 2.01 / 1.1 * (4.0 - 1.1));
  EXPECT_FALSE(PassProgress({{"a", 1.0}}).report(0, 0.0, 1.0).seconds_left.has_value());  // nothing done yet
}

TEST(PassProgress, NeverGoesBackAndReachesOneOnlyAtTheEnd) {
  PassProgress p = three_passes();
  // Reports as a render gives them: out of order, repeated, too large, a late one from a pass left behind.
  const std::vector<std::pair<int, double>> reports = {{0, 0.2}, {0, 0.1}, {0, 1.0}, {0, 1.5}, {1, 0.3},
                                                       {0, 0.9}, {1, 0.2}, {1, 1.0}, {2, 0.5}, {2, 1.0}, {2, 1.0}};
  double last = 0.0;
  int hundred = 0;
  double elapsed = 0.0;
  for (const auto& [pass, fraction] : reports) {
    const PassProgressState s = p.report(pass, fraction, elapsed += 1.0);
    EXPECT_GE(s.fraction, last) << "pass " << pass << " at " << fraction;
    EXPECT_LT(s.fraction, 1.0) << "100 % before the render is done";
    hundred += s.fraction >= 1.0;
    last = s.fraction;
  }
  const PassProgressState end = p.finish();
  EXPECT_EQ(end.fraction, 1.0);
  hundred += end.fraction >= 1.0;
  EXPECT_EQ(hundred, 1);
  EXPECT_EQ(p.report(2, 0.5, elapsed).fraction, 1.0);  // a straggling report after the end changes nothing
}

TEST(PassProgress, NamesThePassThatRuns) {
  PassProgress p = three_passes();
  EXPECT_EQ(p.state().pass, "media: photons");
  EXPECT_EQ(p.report(1, 0.1, 1.0).pass, "radiosity");
  EXPECT_EQ(p.state().number, 2);
  EXPECT_EQ(p.state().of, 3);
  EXPECT_EQ(p.report(0, 1.0, 1.0).pass, "radiosity");  // a late photon report does not take the name back
  EXPECT_EQ(p.report(2, 0.0, 2.0).pass, "view");
  EXPECT_EQ(p.finish().pass, "done");
}

TEST(PassProgress, PassesWithoutAPredictionWeighAsTheOthers) {
  PassProgress p({{"a", 2.0}, {"b", 0.0}, {"c", 4.0}});  // b weighs 3, the mean of a and c
  EXPECT_DOUBLE_EQ(p.report(2, 0.0, 1.0).fraction, 5.0 / 9.0);
  PassProgress none({{"a", 0.0}, {"b", -1.0}});
  EXPECT_DOUBLE_EQ(none.report(1, 0.0, 1.0).fraction, 0.5);
  EXPECT_THROW(PassProgress({}), std::invalid_argument);
  EXPECT_THROW(none.report(2, 0.0, 1.0), std::out_of_range);
}

}  // namespace
}  // namespace gcsim::pipeline
