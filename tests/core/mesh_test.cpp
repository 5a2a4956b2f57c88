// SPDX-License-Identifier: LGPL-2.1-or-later
// Mesh: topology analysis, exact welding, validation, bounds and extents.
#include <gtest/gtest.h>

#include <cmath>

#include "model/mesh.hpp"
#include "model/model.hpp"
#include "support/error.hpp"
#include "test_support.hpp"

namespace sliceform {
namespace {

using test::cubeMesh;

TEST(Mesh, ClosedCubeIsClosed) {
  const Mesh cube = cubeMesh(2);
  ASSERT_EQ(cube.vertices.size(), 8u);
  ASSERT_EQ(cube.triangles.size(), 12u);
  const MeshTopology topo = analyseTopology(cube);
  EXPECT_TRUE(topo.closed());
  EXPECT_EQ(topo.boundaryEdges, 0u);
  EXPECT_EQ(topo.nonManifoldEdges, 0u);
  EXPECT_EQ(topo.holes, 0u);
  EXPECT_EQ(topo.degenerateTriangles, 0u);
  EXPECT_TRUE(topo.sampleBoundaryEdges.empty());
  EXPECT_EQ(topo.describe(), "");
}

TEST(Mesh, MissingTriangleLeavesOneHole) {
  Mesh cube = cubeMesh(2);
  const auto removed = cube.triangles[5];
  cube.triangles.erase(cube.triangles.begin() + 5);
  const MeshTopology topo = analyseTopology(cube);
  EXPECT_FALSE(topo.closed());
  EXPECT_EQ(topo.boundaryEdges, 3u);
  EXPECT_EQ(topo.holes, 1u);
  EXPECT_EQ(topo.nonManifoldEdges, 0u);
  const std::string text = topo.describe();
  EXPECT_NE(text.find("not closed"), std::string::npos) << text;
  EXPECT_NE(text.find("3 boundary edges"), std::string::npos) << text;
  EXPECT_NE(text.find("1 hole"), std::string::npos) << text;
  // The sample edges are edges of the removed triangle.
  ASSERT_FALSE(topo.sampleBoundaryEdges.empty());
  for (const auto& edge : topo.sampleBoundaryEdges) {
    for (const Vec3& end : edge) {
      bool ofRemoved = false;
      for (uint32_t v : removed) ofRemoved = ofRemoved || cube.vertices[v] == end;
      EXPECT_TRUE(ofRemoved);
    }
  }
}

TEST(Mesh, HolesAreCountedSeparately) {
  // A whole face missing: 4 boundary edges in one hole.
  Mesh face = cubeMesh(1);
  face.triangles.erase(face.triangles.begin(), face.triangles.begin() + 2);
  MeshTopology topo = analyseTopology(face);
  EXPECT_EQ(topo.boundaryEdges, 4u);
  EXPECT_EQ(topo.holes, 1u);
  // One triangle missing from the bottom and one from the top: two separate holes.
  Mesh two = cubeMesh(1);
  two.triangles.erase(two.triangles.begin() + 2);  // top face (z = 1)
  two.triangles.erase(two.triangles.begin() + 0);  // bottom face (z = 0)
  topo = analyseTopology(two);
  EXPECT_EQ(topo.boundaryEdges, 6u);
  EXPECT_EQ(topo.holes, 2u);
  EXPECT_NE(topo.describe().find("2 holes"), std::string::npos) << topo.describe();
}

TEST(Mesh, SmallHolesAreFilledLargeOnesLeft) {
  // A missing triangle of a 2 mm cube face: the hole is 2.8 mm across.
  Mesh cube = cubeMesh(2);
  cube.triangles.erase(cube.triangles.begin() + 5);
  Mesh kept = cube;
  EXPECT_EQ(fillSmallHoles(kept, 2.0), 0u);  // larger than allowed: left alone
  EXPECT_EQ(kept.triangles.size(), cube.triangles.size());
  EXPECT_EQ(fillSmallHoles(cube, 3.0), 1u);
  EXPECT_TRUE(analyseTopology(cube).closed());
  EXPECT_EQ(cube.triangles.size(), 11u + 3u);  // a fan of three about the hole's centre
  // Two holes meeting at a vertex (a pinch): no fan is sure to be right, so none is added.
  // An octahedron without two faces that share only its top vertex.
  Mesh octahedron;
  octahedron.vertices = {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}, {0, 0, -1}};
  octahedron.triangles = {{0, 2, 3}, {0, 4, 1}, {5, 2, 1}, {5, 3, 2}, {5, 4, 3}, {5, 1, 4}};
  ASSERT_EQ(analyseTopology(octahedron).boundaryEdges, 6u);
  EXPECT_EQ(fillSmallHoles(octahedron, 10.0), 0u);
  EXPECT_EQ(octahedron.triangles.size(), 6u);
}

TEST(Mesh, NonManifoldAndDegenerateTriangles) {
  Mesh cube = cubeMesh(1);
  cube.triangles.push_back(cube.triangles[0]);  // each of its edges now has 3 triangles
  cube.triangles.push_back({1, 1, 2});          // a repeated vertex
  const MeshTopology topo = analyseTopology(cube);
  EXPECT_FALSE(topo.closed());
  EXPECT_EQ(topo.nonManifoldEdges, 3u);
  EXPECT_EQ(topo.boundaryEdges, 0u);
  EXPECT_EQ(topo.degenerateTriangles, 1u);
  EXPECT_NE(topo.describe().find("non-manifold"), std::string::npos) << topo.describe();
  // One of them is named, to be found in the model.
  ASSERT_EQ(topo.sampleNonManifoldEdges.size(), 3u);
  EXPECT_NE(topo.describe().find("for example the edge (0, 0, 0)-("), std::string::npos) << topo.describe();
}

TEST(Mesh, WeldExactMergesTriangleSoup) {
  const Mesh soup = test::toSoup(cubeMesh(3));
  ASSERT_EQ(soup.vertices.size(), 36u);
  const MeshTopology before = analyseTopology(soup);
  EXPECT_EQ(before.boundaryEdges, 36u);
  EXPECT_EQ(before.holes, 12u);
  const Mesh welded = weldExact(soup);
  EXPECT_EQ(welded.vertices.size(), 8u);
  EXPECT_EQ(welded.triangles.size(), 12u);
  EXPECT_TRUE(analyseTopology(welded).closed());
  // Every welded triangle is the soup triangle at the same place, same corners in order.
  for (size_t i = 0; i < soup.triangles.size(); ++i) {
    for (int k = 0; k < 3; ++k)
      EXPECT_EQ(welded.vertices[welded.triangles[i][k]], soup.vertices[soup.triangles[i][k]]);
  }
}

TEST(Mesh, WeldExactTreatsSignedZerosAlikeAndDropsCollapsedTriangles) {
  Mesh m;
  m.vertices = {{0.0, 0, 0}, {-0.0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 0, 1e-300}};
  m.triangles = {{0, 2, 3}, {1, 2, 3}, {0, 1, 2}};  // the last collapses once 0 and 1 merge
  const Mesh w = weldExact(m);
  // 0 and -0 merge; (1, 0, 1e-300) is a point of its own (kept, although unused).
  EXPECT_EQ(w.vertices.size(), 4u);
  EXPECT_EQ(w.triangles.size(), 2u);
  // Nearly equal is not equal: exact welding keeps them apart.
  Mesh near;
  near.vertices = {{0, 0, 0}, {1, 0, 0}, {1 + 1e-12, 0, 0}, {0, 1, 0}};
  near.triangles = {{0, 1, 3}, {0, 2, 3}};
  EXPECT_EQ(weldExact(near).vertices.size(), 4u);
}

void expectBadInput(const Mesh& mesh, const std::string& fragment) {
  try {
    validateMesh(mesh, "test-source");
    ADD_FAILURE() << "validateMesh accepted a bad mesh (" << fragment << ")";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::BadInput);
    const std::string what = e.what();
    EXPECT_NE(what.find("test-source"), std::string::npos) << what;
    EXPECT_NE(what.find(fragment), std::string::npos) << what;
  }
}

TEST(Mesh, ValidateMeshRejectsBadMeshes) {
  EXPECT_NO_THROW(validateMesh(cubeMesh(1), "cube"));
  Mesh nan = cubeMesh(1);
  nan.vertices[3].y = NAN;
  expectBadInput(nan, "vertex 4 has a NaN");
  Mesh inf = cubeMesh(1);
  inf.vertices[0].z = -INFINITY;
  expectBadInput(inf, "infinite");
  Mesh range = cubeMesh(1);
  range.triangles[2][1] = 8;
  expectBadInput(range, "triangle 3 uses vertex 9 of 8");
  expectBadInput(Mesh{}, "no triangles");
}

TEST(Mesh, BoundsAndExtent) {
  const Mesh box = test::boxMesh({1, -2, 3}, {2, 4, 6});
  const Box3 b = box.bounds();
  EXPECT_EQ(b.min, (Vec3{1, -2, 3}));
  EXPECT_EQ(b.max, (Vec3{3, 2, 9}));
  EXPECT_DOUBLE_EQ(b.diagonal(), std::sqrt(4.0 + 16.0 + 36.0));
  const Interval x = box.extent({1, 0, 0});
  EXPECT_DOUBLE_EQ(x.lo, 1.0);
  EXPECT_DOUBLE_EQ(x.hi, 3.0);
  const Interval minusZ = box.extent({0, 0, -1});
  EXPECT_DOUBLE_EQ(minusZ.lo, -9.0);
  EXPECT_DOUBLE_EQ(minusZ.hi, -3.0);
  // Along the diagonal (1,1,1)/√3 the extremes are the corners (1,-2,3) and (3,2,9).
  const double s = 1 / std::sqrt(3.0);
  const Interval diag = box.extent({s, s, s});
  EXPECT_NEAR(diag.lo, 2 * s, 1e-12);
  EXPECT_NEAR(diag.hi, 14 * s, 1e-12);
  EXPECT_TRUE(Mesh{}.bounds().empty());
  EXPECT_EQ(Mesh{}.bounds().diagonal(), 0.0);
}

}  // namespace
}  // namespace sliceform
