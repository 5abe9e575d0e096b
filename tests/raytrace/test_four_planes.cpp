// FourPlanes (the uniformity test's four region planes at once) must answer exactly as four
// scalar classify() calls, on hard cases: boxes touching or straddling a plane, flat boxes,
// axis-aligned normals with zero (and negative zero) components, huge and tiny coordinates.
#include <array>

#include <gtest/gtest.h>

#include "apps/common/rng.hpp"
#include "apps/raytrace/plane_classification4.hpp"

namespace gcsim::raytrace {
namespace {

bool any_outside_scalar(const std::array<Plane, 4>& planes, const Bounds3& box) {
  for (const Plane& p : planes)
    if (classify(box, p) == Side::outside) return true;
  return false;
}

TEST(FourPlanes, AgreesWithScalarClassify) {
  apps::Rng rng(5);
  int outside = 0, total = 0;
  for (float scale : {1e-6f, 1.0f, 1e4f}) {
    for (int i = 0; i < 4000; ++i) {
      auto v = [&] { return scale * glm::vec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)); };
      std::array<Plane, 4> planes;
      const glm::vec3 eye = v();
      for (Plane& p : planes) {
        glm::vec3 n = glm::normalize(glm::vec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)));
        if (rng.uniform() < 0.3f) n = glm::vec3(-0.0f, rng.uniform() < 0.5f ? 1.0f : -1.0f, 0.0f);  // axis-aligned
        p = {n, glm::dot(n, eye)};
      }
      Bounds3 box = Bounds3::of_point(v());
      if (rng.uniform() < 0.8f) box.extend(v());  // else a point
      if (rng.uniform() < 0.2f) box.hi.z = box.lo.z;  // flat
      // A box with a corner exactly on a plane (its offset through the corner).
      if (rng.uniform() < 0.2f) planes[i % 4].offset = glm::dot(planes[i % 4].normal, box.lo);
      const bool expected = any_outside_scalar(planes, box);
      ASSERT_EQ(FourPlanes(planes).any_outside(BoxCentre(box)), expected) << "case " << i << " scale " << scale;
      // Built from planes prepared beforehand: the same lanes, so the same answers.
      const PreparedPlane prepared[4] = {PreparedPlane(planes[0]), PreparedPlane(planes[1]), PreparedPlane(planes[2]),
                                         PreparedPlane(planes[3])};
      unsigned in_a, out_a, in_b, out_b;
      FourPlanes(planes).sides(BoxCentre(box), in_a, out_a);
      FourPlanes({&prepared[0], &prepared[1], &prepared[2], &prepared[3]}).sides(BoxCentre(box), in_b, out_b);
      ASSERT_EQ(in_a, in_b) << "case " << i;
      ASSERT_EQ(out_a, out_b) << "case " << i;
      // Two boxes in lanes (a subtree's two children against planes 0 and 1): box lane by lane,
      // its |centre| made from the centre's bits, answers as the scalar test of each lane.
      Bounds3 other = Bounds3::of_point(-v());
      other.extend(v());
      const std::array<Plane, 4> twice{planes[0], planes[1], planes[0], planes[1]};
      unsigned in_l, out_l;
      FourPlanes(twice).sides(BoxLanes(BoxCentre(box), BoxCentre(other)), in_l, out_l);
      for (int lane = 0; lane < 4; ++lane) {
        const Side side = classify(lane < 2 ? box : other, twice[lane]);
        ASSERT_EQ(in_l >> lane & 1u, unsigned(side == Side::inside)) << "case " << i << " lane " << lane;
        ASSERT_EQ(out_l >> lane & 1u, unsigned(side == Side::outside)) << "case " << i << " lane " << lane;
      }
      outside += expected;
      ++total;
    }
  }
  EXPECT_GT(outside, total / 10);
  EXPECT_LT(outside, total - total / 10);
}

}  // namespace
}  // namespace gcsim::raytrace
