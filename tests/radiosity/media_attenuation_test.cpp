// Media between the surfaces (PathTransmittance): a shot delivers F * T, the rest is booked as taken
// by the media, a transmittance of exactly 1 changes no bit, and the parallel solver still equals
// the sequential one bit for bit.
#include <gtest/gtest.h>

#include <cmath>

#include "apps/radiosity/parallel_radiosity.hpp"
#include "apps/radiosity/progressive_solver.hpp"
#include "parix/backend.hpp"
#include "tests/support/published_machine.hpp"
#include "test_scenes.hpp"

namespace gcsim::radiosity {
namespace {

class Constant final : public PathTransmittance {
 public:
  explicit Constant(Rgb t) : t_(t) {}
  Rgb between(const Vec3&, const Vec3&) const override { return t_; }

 private:
  Rgb t_;
};

// A homogeneous medium filling space: exp(-sigma distance) per channel.
class Everywhere final : public PathTransmittance {
 public:
  explicit Everywhere(Rgb sigma) : sigma_(sigma) {}
  Rgb between(const Vec3& a, const Vec3& b) const override {
    const double d = glm::length(b - a);
    return {std::exp(-sigma_.r * d), std::exp(-sigma_.g * d), std::exp(-sigma_.b * d)};
  }

 private:
  Rgb sigma_;
};

SolverOptions options(double energy, const PathTransmittance* media) {
  SolverOptions o;
  o.hemicube.resolution = 32;
  o.energy = energy;
  o.media = media;
  return o;
}

TEST(MediaAttenuation, ATransmittanceOfOneChangesNoBit) {
  const Scene room = testing::lit_room();
  const Constant clear(Rgb(1.0));
  const SolveResult plain = solve_progressive(room, options(0.99, nullptr));
  const SolveResult through = solve_progressive(room, options(0.99, &clear));
  EXPECT_EQ(through.state.element_radiosity(), plain.state.element_radiosity());
  EXPECT_EQ(through.state.energy().in_media, Rgb(0.0));
  EXPECT_EQ(through.steps.size(), plain.steps.size());
}

TEST(MediaAttenuation, TheFirstShotArrivesScaledByTheTransmittance) {
  const Scene room = testing::lit_room();
  const Rgb t(0.5, 0.25, 0.125);  // powers of two: the scaled values are exact
  const Constant fog(t);
  SolverOptions one = options(1.0, nullptr);
  one.max_steps = 1;
  one.shooters = 1;
  const SolveResult plain = solve_progressive(room, one);
  one.media = &fog;
  const SolveResult through = solve_progressive(room, one);
  int lit = 0;
  for (std::size_t e = 0; e < room.elements.size(); ++e) {
    const Rgb emitted = room.surface_of_element(int(e)).exitance;
    const Rgb gained_plain = plain.state.element_radiosity()[e] - emitted;
    const Rgb gained = through.state.element_radiosity()[e] - emitted;
    for (int k = 0; k < 3; ++k) EXPECT_EQ(gained[k], t[k] * gained_plain[k]) << "element " << e << " channel " << k;
    lit += gained_plain.r > 0;
  }
  EXPECT_GT(lit, 10);
  // What the media took is (1 - T) of what reached the elements: received = gained * A / rho.
  Rgb reached(0.0);
  for (std::size_t e = 0; e < room.elements.size(); ++e) {
    const Rgb rho = room.surfaces[room.patches[room.elements[e].patch].surface].reflectance;
    const Rgb gained_plain = plain.state.element_radiosity()[e] - room.surface_of_element(int(e)).exitance;
    for (int k = 0; k < 3; ++k)
      if (gained_plain[k] > 0) reached[k] += gained_plain[k] * room.elements[e].area / rho[k];
  }
  for (int k = 0; k < 3; ++k) {
    EXPECT_GT(reached[k], 0);
    EXPECT_NEAR(through.state.energy().in_media[k], (1 - t[k]) * reached[k], 1e-12 * reached[k]);
  }
  EXPECT_EQ(through.state.energy().escaped, plain.state.energy().escaped);
}

TEST(MediaAttenuation, EnergyIsConservedWithTheMediasShareAtEveryStep) {
  const Scene room = testing::lit_room();
  const Everywhere fog(Rgb(0.3, 0.6, 1.2));
  int steps = 0;
  solve_progressive(room, options(0.999, &fog), nullptr, [&](const StepRecord& rec, const ProgressiveState& st) {
    const EnergyBalance& e = st.energy();
    for (int k = 0; k < 3; ++k)
      ASSERT_NEAR(e.unshot[k] + e.absorbed[k] + e.escaped[k] + e.in_media[k], e.emitted[k], 1e-12 * e.emitted[k])
          << "step " << rec.step;
    ++steps;
  });
  EXPECT_GT(steps, 5);
}

TEST(MediaAttenuation, ThickerMediaLeaveLessLightOnTheWalls) {
  const Scene room = testing::lit_room();
  double previous = 1e300;
  for (double sigma : {0.0, 0.2, 0.8}) {
    const Everywhere fog{Rgb(sigma)};
    const SolveResult r = solve_progressive(room, options(0.999, &fog));
    double reflected = 0;
    for (std::size_t e = 0; e < room.elements.size(); ++e)
      reflected += (r.state.element_radiosity()[e] - room.surface_of_element(int(e)).exitance).g * room.elements[e].area;
    EXPECT_LT(reflected, previous) << "sigma " << sigma;
    previous = reflected;
  }
}

TEST(MediaAttenuation, ParallelEqualsSequentialThroughMedia) {
  const Scene room = testing::lit_room();
  const Everywhere fog(Rgb(0.3, 0.6, 1.2));
  ParallelOptions o;
  o.solver = options(0.95, &fog);
  o.solver.hemicube.cells_per_side = 4;
  const SolveResult reference = solve_progressive(room, o.solver);
  for (int nodes : {2, 3}) {
    ParallelOutcome out;
    parix::run({"simulated", test_support::published_machine(nodes)},
               [&](parix::Processor& p) { radiosity_program(p, room, o, &out); });
    ASSERT_EQ(out.element_radiosity, reference.state.element_radiosity()) << "nodes " << nodes;
    EXPECT_EQ(out.energy.in_media, reference.state.energy().in_media);
  }
}

// Received power (SolverOptions::received): before any shot each element holds E + rho Phi / A, its
// patch rho Phi more unshot energy; the books balance with it; none at all changes no bit.
TEST(ReceivedPower, StartsAsRhoPhiOverAAndIsBooked) {
  const Scene room = testing::lit_room();
  std::vector<Rgb> received(room.elements.size(), Rgb(0.0));
  received[3] = Rgb(2.0, 4.0, 8.0);
  SolverOptions none = options(1.0, nullptr);
  none.max_steps = 0;
  SolverOptions given = none;
  given.received = &received;
  const SolveResult before = solve_progressive(room, none), after = solve_progressive(room, given);
  const SceneElement& el = room.elements[3];
  const Rgb rho = room.surfaces[room.patches[el.patch].surface].reflectance;
  for (std::size_t e = 0; e < room.elements.size(); ++e) {
    const Rgb expected = before.state.element_radiosity()[e] + (e == 3 ? rho * received[3] / el.area : Rgb(0.0));
    EXPECT_EQ(after.state.element_radiosity()[e], expected) << "element " << e;
  }
  const EnergyBalance& b = after.state.energy();
  EXPECT_EQ(b.injected, received[3]);
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(b.absorbed[k], (1 - rho[k]) * received[3][k], 1e-12);
    EXPECT_NEAR(b.unshot[k] - before.state.energy().unshot[k], rho[k] * received[3][k], 1e-9 * b.unshot[k]);
  }
}

TEST(ReceivedPower, BalancesAtEveryStepAndNoneChangesNoBit) {
  const Scene room = testing::lit_room();
  const Everywhere fog(Rgb(0.3, 0.6, 1.2));
  std::vector<Rgb> received(room.elements.size(), Rgb(0.0));
  SolverOptions o = options(0.99, &fog);
  o.received = &received;
  const SolveResult plain = solve_progressive(room, options(0.99, &fog)), zero = solve_progressive(room, o);
  EXPECT_EQ(zero.state.element_radiosity(), plain.state.element_radiosity());
  EXPECT_EQ(zero.steps.size(), plain.steps.size());
  for (std::size_t e = 0; e < received.size(); e += 5) received[e] = Rgb(0.5, 0.25, 1.0);
  int steps = 0;
  solve_progressive(room, o, nullptr, [&](const StepRecord& rec, const ProgressiveState& st) {
    const EnergyBalance& e = st.energy();
    for (int k = 0; k < 3; ++k)
      ASSERT_NEAR(e.unshot[k] + e.absorbed[k] + e.escaped[k] + e.in_media[k], e.emitted[k] + e.injected[k],
                  1e-12 * e.emitted[k])
          << "step " << rec.step;
    ++steps;
  });
  EXPECT_GT(steps, 5);
}

}  // namespace
}  // namespace gcsim::radiosity
