// SPDX-License-Identifier: LGPL-2.1-or-later
// The glTF's triangles: they cover exactly what the outline encloses (holes open, loops in
// any direction, any plane), and all face the panel's normal.
#include <gtest/gtest.h>

#include <cmath>

#include "output/triangulate.hpp"

namespace sliceform {
namespace {

// Area of the triangles; every triangle must turn counter-clockwise about `normal`.
double area(const Triangles& t, const Vec3& normal) {
  double sum = 0;
  for (const auto& c : t.corners) {
    const Vec3 n = cross(t.points[c[1]] - t.points[c[0]], t.points[c[2]] - t.points[c[0]]);
    EXPECT_GE(dot(n, normal), 0);
    sum += norm(n) / 2;
  }
  return sum;
}

// A wavy disc of 400 points with a 90-gon hole and a square hole, the holes in the same
// direction as the outline, on a tilted plane.
TEST(Triangulate, CoversTheRegionWithItsHoles) {
  const Vec3 x{0.6, 0.8, 0}, y{0, 0, 1}, normal = cross(x, y), origin{10, -4, 3};
  auto at = [&](double u, double v) { return origin + x * u + y * v; };
  std::vector<std::vector<Vec3>> loops(3);
  double expected = 0;
  for (int k = 0; k < 400; ++k) {
    const double t = 2 * M_PI * k / 400, r = 50 * (1 + 0.2 * std::sin(7 * t));
    const double t1 = 2 * M_PI * (k + 1) / 400, r1 = 50 * (1 + 0.2 * std::sin(7 * t1));
    loops[0].push_back(at(r * std::cos(t), r * std::sin(t)));
    expected += 0.5 * r * r1 * std::sin(t1 - t);
  }
  for (int k = 0; k < 90; ++k) {
    const double t = 2 * M_PI * k / 90;
    loops[1].push_back(at(-15 + 8 * std::cos(t), 8 * std::sin(t)));
  }
  expected -= 0.5 * 90 * 64 * std::sin(2 * M_PI / 90);
  loops[2] = {at(10, -5), at(20, -5), at(20, 5), at(10, 5)};
  expected -= 100;
  const Triangles t = triangulate(loops, normal);
  EXPECT_NEAR(area(t, normal), expected, 1e-9 * expected);
  EXPECT_GE(t.points.size(), 494u);
  // Seen from the other side, the same triangles turn the other way.
  const Triangles back = triangulate(loops, normal * -1);
  EXPECT_NEAR(area(back, normal * -1), expected, 1e-9 * expected);
}

// Two squares that share a corner and one that overlaps another (even-odd: the overlap is
// a hole); GLU adds points where loops cross.
TEST(Triangulate, TouchingAndCrossingLoops) {
  const Vec3 normal{0, 0, 1};
  const std::vector<std::vector<Vec3>> loops{{{0, 0, 0}, {10, 0, 0}, {10, 10, 0}, {0, 10, 0}},
                                             {{10, 10, 0}, {20, 10, 0}, {20, 20, 0}, {10, 20, 0}},
                                             {{15, 15, 0}, {25, 15, 0}, {25, 25, 0}, {15, 25, 0}}};
  const Triangles t = triangulate(loops, normal);
  // 100 + (100 - 25) + (100 - 25).
  EXPECT_NEAR(area(t, normal), 250, 1e-9);
  EXPECT_GT(t.points.size(), 12u);
}

TEST(Triangulate, NothingEnclosedGivesNoTriangles) {
  EXPECT_TRUE(triangulate({}, {0, 0, 1}).corners.empty());
  EXPECT_TRUE(triangulate({{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}}, {0, 0, 1}).corners.empty());
}

}  // namespace
}  // namespace sliceform
