// SPDX-License-Identifier: LGPL-2.1-or-later
// Mesh slicer: hand-built meshes, planes through vertices, bad winding, holes, OCCT solids.
#include <gtest/gtest.h>

#include <cmath>

#include "model/model.hpp"
#include "slicing/mesh_slicer.hpp"
#include "support/error.hpp"
#include "test_support.hpp"

namespace sliceform {
namespace {

using test::boxMesh;
using test::cubeMesh;

Region2d sliceOne(const Mesh& mesh, const SliceFrame& frame, double position,
                  MeshSliceStats* stats = nullptr) {
  const SliceSet set = sliceMesh(mesh, frame, {position}, stats);
  EXPECT_EQ(set.slices.size(), 1u);
  EXPECT_EQ(set.slices[0].position, position);
  return set.slices[0].region;
}

// Closed box [0,a]³ whose faces are n x n grids of squares (two triangles each), so that
// planes at multiples of a/n run through rings of vertices and along mesh edges.
Mesh gridCube(double a, int n) {
  Mesh soup;
  for (int k = 0; k < 3; ++k) {
    for (double side : {0.0, a}) {
      auto point = [&](int i, int j) {
        double p[3];
        p[k] = side;
        p[(k + 1) % 3] = a * i / n;
        p[(k + 2) % 3] = a * j / n;
        return Vec3{p[0], p[1], p[2]};
      };
      for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
          // Counter-clockwise in (k+1, k+2) faces +k; the face at 0 faces -k.
          Vec3 q[4] = {point(i, j), point(i + 1, j), point(i + 1, j + 1), point(i, j + 1)};
          if (side == 0) std::swap(q[1], q[3]);
          const auto base = static_cast<uint32_t>(soup.vertices.size());
          soup.vertices.insert(soup.vertices.end(), q, q + 4);
          soup.triangles.push_back({base, base + 1, base + 2});
          soup.triangles.push_back({base, base + 2, base + 3});
        }
      }
    }
  }
  return weldExact(soup);
}

TEST(MeshSlicer, BoxAlongAxesGivesExactRectangles) {
  const Mesh box = boxMesh({0, 0, 0}, {2, 3, 5});
  const struct {
    Vec3 normal;
    double position, area;
  } cases[] = {{{1, 0, 0}, 0.7, 15}, {{0, 1, 0}, 2.2, 10}, {{0, 0, 1}, 4.1, 6}, {{-1, 0, 0}, -1.9, 15}};
  for (const auto& c : cases) {
    MeshSliceStats stats;
    const Region2d r = sliceOne(box, makeSliceFrame(c.normal), c.position, &stats);
    EXPECT_NEAR(r.area(), c.area, 1e-9) << "normal " << c.normal.x << "," << c.normal.y << "," << c.normal.z;
    EXPECT_EQ(stats.loops, 1u);
    EXPECT_EQ(stats.segments, 8u);  // two triangles on each of the four side faces
    EXPECT_EQ(stats.inconsistentLoops, 0u);
    EXPECT_EQ(r.holeCount(), 0);
  }
  // Along x the 2D frame is (y, z): the section is exactly [0,3] x [0,5].
  const Box2 b = sliceOne(box, makeSliceFrame({1, 0, 0}), 1.0).bounds();
  EXPECT_DOUBLE_EQ(b.min.x, 0.0);
  EXPECT_DOUBLE_EQ(b.min.y, 0.0);
  EXPECT_DOUBLE_EQ(b.max.x, 3.0);
  EXPECT_DOUBLE_EQ(b.max.y, 5.0);
  // A plane beside the box gives an empty region.
  EXPECT_TRUE(sliceOne(box, makeSliceFrame({1, 0, 0}), 2.5).empty());
}

TEST(MeshSlicer, TiltedPlanesThroughCube) {
  const double a = 2;
  const Mesh cube = cubeMesh(a);
  // Normal (1,1,0)/√2: the plane x + y = s cuts a rectangle of height a and width s√2
  // (s <= a) or (2a - s)√2 (s >= a).
  const SliceFrame diagonal = makeSliceFrame({1, 1, 0}, {0, 0, 1});
  // Section vertices off the 1e-5 mm grid are rounded to it: allow for that.
  for (double s : {0.3, 1.0, 1.7, 2.6, 3.9}) {
    const double width = (s <= a ? s : 2 * a - s) * std::sqrt(2.0);
    EXPECT_NEAR(sliceOne(cube, diagonal, s / std::sqrt(2.0)).area(), a * width,
                test::gridTolerance(2 * (a + width)))
        << "s = " << s;
  }
  // Normal (1,1,1)/√3: x + y + z = s cuts an equilateral triangle of side s√2 for s <= a,
  // and the regular hexagon of side a/√2 at the centre, s = 3a/2.
  const SliceFrame corner = makeSliceFrame({1, 1, 1});
  for (double s : {0.5, 1.2, 2.0}) {
    EXPECT_NEAR(sliceOne(cube, corner, s / std::sqrt(3.0)).area(), std::sqrt(3.0) / 2 * s * s,
                test::gridTolerance(3 * s * std::sqrt(2.0)));
  }
  EXPECT_NEAR(sliceOne(cube, corner, 1.5 * a / std::sqrt(3.0)).area(), 3 * std::sqrt(3.0) / 4 * a * a,
              test::gridTolerance(6 * a / std::sqrt(2.0)));
}

TEST(MeshSlicer, PlanesThroughVerticesAndEdges) {
  // Octahedron |x| + |y| + |z| <= c: the plane z = 0 holds four vertices and four edges.
  const double c = 3;
  Mesh octa;
  octa.vertices = {{c, 0, 0}, {0, c, 0}, {-c, 0, 0}, {0, -c, 0}, {0, 0, c}, {0, 0, -c}};
  for (uint32_t i = 0; i < 4; ++i) {
    octa.triangles.push_back({i, (i + 1) % 4, 4});
    octa.triangles.push_back({(i + 1) % 4, i, 5});
  }
  ASSERT_TRUE(analyseTopology(octa).closed());
  for (double h : {0.0, -1.0, 1.0, 2.5}) {
    MeshSliceStats stats;
    const Region2d r = sliceOne(octa, makeSliceFrame({0, 0, 1}), h, &stats);
    EXPECT_NEAR(r.area(), 2 * (c - std::fabs(h)) * (c - std::fabs(h)), 1e-9) << "h = " << h;
    EXPECT_EQ(stats.loops, 1u);
    EXPECT_EQ(r.components().size(), 1u);
  }
  // A gridded cube cut exactly at grid planes, along an axis and along a face diagonal.
  const double a = 2;
  const Mesh grid = gridCube(a, 4);
  ASSERT_TRUE(analyseTopology(grid).closed());
  for (double x : {0.5, 1.0, 1.5}) {
    MeshSliceStats stats;
    const Region2d r = sliceOne(grid, makeSliceFrame({1, 0, 0}), x, &stats);
    EXPECT_NEAR(r.area(), a * a, 1e-9) << "x = " << x;
    EXPECT_EQ(stats.loops, 1u);
    EXPECT_EQ(r.holeCount(), 0);
  }
  // A plane on a face: a vertex on the plane counts as above it, so the section is the one
  // just below the plane (nothing at the bottom face, the full square at the top face).
  EXPECT_TRUE(sliceOne(grid, makeSliceFrame({1, 0, 0}), 0.0).empty());
  EXPECT_NEAR(sliceOne(grid, makeSliceFrame({1, 0, 0}), a).area(), a * a, 1e-9);
  EXPECT_NEAR(sliceOne(grid, makeSliceFrame({-1, 0, 0}), 0.0).area(), a * a, 1e-9);
  // x + y = a runs through the grid vertices (a - t, t, z) and along vertical grid edges.
  EXPECT_NEAR(sliceOne(grid, makeSliceFrame({1, 1, 0}, {0, 0, 1}), a / std::sqrt(2.0)).area(),
              a * a * std::sqrt(2.0), test::gridTolerance(2 * a + 2 * a * std::sqrt(2.0)));
}

TEST(MeshSlicer, FlippedTrianglesStillSliceRight) {
  const double a = 2;
  Mesh cube = cubeMesh(a);
  for (size_t t : {0u, 5u, 9u}) std::swap(cube.triangles[t][1], cube.triangles[t][2]);
  size_t inconsistent = 0;
  for (const Vec3& n : {Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}}) {
    for (double p : {0.4, 1.3}) {
      MeshSliceStats stats;
      EXPECT_NEAR(sliceOne(cube, makeSliceFrame(n), p, &stats).area(), a * a, 1e-9);
      inconsistent += stats.inconsistentLoops;
    }
  }
  EXPECT_GT(inconsistent, 0u);  // the flipped triangles were really crossed
  // Inside out (every triangle flipped): consistent, and still the right area.
  Mesh inverted = cubeMesh(a);
  for (auto& t : inverted.triangles) std::swap(t[1], t[2]);
  MeshSliceStats stats;
  EXPECT_NEAR(sliceOne(inverted, makeSliceFrame({0, 1, 0}), 0.9, &stats).area(), a * a, 1e-9);
  EXPECT_EQ(stats.inconsistentLoops, 0u);
}

TEST(MeshSlicer, OpenMeshThrowsBadInput) {
  Mesh cube = cubeMesh(2);
  cube.triangles.erase(cube.triangles.begin() + 5);  // a triangle of the face y = 0
  try {
    sliceMesh(cube, makeSliceFrame({1, 0, 0}), {0.5, 1.0, 1.5});
    FAIL() << "an open mesh was sliced without error";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::BadInput);
    EXPECT_NE(std::string(e.what()).find("not closed"), std::string::npos) << e.what();
  }
  // Unsorted positions are a parameter error.
  try {
    sliceMesh(cubeMesh(2), makeSliceFrame({1, 0, 0}), {1.5, 0.5});
    FAIL() << "unsorted positions accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::BadParameter);
  }
}

// A triangulation within deflection d of the surface lies between the solid shrunk by d and
// the solid grown by d, so its sections do too. (Perimeter x d is not a bound: where the
// surface meets the plane at a grazing angle the section moves by much more than d.)
void expectBetween(double area, double lo, double hi, double perimeter, double position) {
  const double slack = test::gridTolerance(perimeter);
  EXPECT_GE(area, lo - slack) << "at " << position;
  EXPECT_LE(area, hi + slack) << "at " << position;
}

TEST(MeshSlicer, TriangulatedSphereAgreesWithCircles) {
  const double R = 10, d = 0.02;
  const Model model = modelFromShape(test::makeSphere(R), "sphere", d);
  ASSERT_DOUBLE_EQ(model.meshDeflection, d);
  ASSERT_TRUE(analyseTopology(model.mesh).closed()) << analyseTopology(model.mesh).describe();
  const std::vector<double> hs{-9.9, -9.5, -6, -2.5, 0.1, 3, 7.7};
  for (const Vec3& n : {Vec3{0, 0, 1}, Vec3{1, 0, 0}, Vec3{1, -2, 0.5}}) {
    const SliceSet set = sliceMesh(model.mesh, makeSliceFrame(n), hs);
    for (const Slice& s : set.slices) {
      // Chords of a sphere lie inside it: between radius R - d and R.
      const double h = s.position;
      expectBetween(s.region.area(), test::discArea(R - d, h), test::discArea(R, h),
                    2 * M_PI * std::sqrt(R * R - h * h), h);
      EXPECT_EQ(s.region.components().size(), 1u);
    }
  }
}

TEST(MeshSlicer, TriangulatedTorusAgreesWithAnnuli) {
  const double R = 10, r = 3, d = 0.01;
  const Model model = modelFromShape(test::makeTorus(R, r), "torus", d);
  ASSERT_TRUE(analyseTopology(model.mesh).closed());
  const SliceSet set = sliceMesh(model.mesh, makeSliceFrame({0, 0, 1}), {-2.5, -1, 0.2, 1.5, 2.9});
  for (const Slice& s : set.slices) {
    expectBetween(s.region.area(), test::torusArea(R, r - d, s.position),
                  test::torusArea(R, r + d, s.position), 4 * M_PI * (R + d), s.position);
    EXPECT_EQ(s.region.holeCount(), 1);
  }
  // Through the axis: two discs of radius r.
  const Region2d discs = sliceOne(model.mesh, makeSliceFrame({1, 0, 0}), 0.0);
  EXPECT_EQ(discs.components().size(), 2u);
  expectBetween(discs.area(), 2 * test::discArea(r - d, 0), 2 * test::discArea(r + d, 0), 4 * M_PI * r, 0);
}

TEST(MeshSlicer, TriangulatedHollowSphereHasOneHole) {
  const double R = 10, r = 6, d = 0.02;
  const Model model = modelFromShape(test::makeHollowSphere(R, r), "hollow sphere", d);
  ASSERT_TRUE(analyseTopology(model.mesh).closed());
  for (double h : {-8.0, -3.0, 0.5, 5.5}) {
    MeshSliceStats stats;
    const Region2d region = sliceOne(model.mesh, makeSliceFrame({0, 0, 1}), h, &stats);
    // Both spheres are triangulated with chords inside them.
    const bool throughVoid = std::fabs(h) < r;
    const double perimeter = 2 * M_PI * (R + r);
    expectBetween(region.area(), test::discArea(R - d, h) - test::discArea(r, h),
                  test::discArea(R, h) - test::discArea(r - d, h), perimeter, h);
    EXPECT_EQ(stats.loops, throughVoid ? 2u : 1u);
    EXPECT_EQ(stats.openChains, 0u);
    EXPECT_EQ(stats.inconsistentLoops, 0u);
    ASSERT_EQ(region.holeCount(), throughVoid ? 1 : 0);
    if (!throughVoid) continue;
    // The hole loop runs clockwise and encloses the inner circle.
    int holes = 0;
    for (const Region2d::Loop& loop : region.loops()) {
      const double a = test::signedArea(loop);
      if (a > 0) continue;
      ++holes;
      expectBetween(-a, test::discArea(r - d, h), test::discArea(r, h), 2 * M_PI * r, h);
    }
    EXPECT_EQ(holes, 1);
  }
}

}  // namespace
}  // namespace sliceform
