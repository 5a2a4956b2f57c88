// SPDX-License-Identifier: LGPL-2.1-or-later
// Mesh: topology analysis, exact welding, validation, bounds and extents.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "model/mesh.hpp"
#include "model/model.hpp"
#include "slicing/mesh_slicer.hpp"
#include "support/error.hpp"
#include "test_support.hpp"

namespace sliceform {
namespace {

using test::boxMesh;
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
  // Two holes meeting at a vertex (a pinch), where the triangles left make two fans: split
  // there, each filled. An octahedron without two faces that share only its top vertex.
  Mesh octahedron;
  octahedron.vertices = {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}, {0, 0, -1}};
  octahedron.triangles = {{0, 2, 3}, {0, 4, 1}, {5, 2, 1}, {5, 3, 2}, {5, 4, 3}, {5, 1, 4}};
  ASSERT_EQ(analyseTopology(octahedron).boundaryEdges, 6u);
  EXPECT_EQ(fillSmallHoles(octahedron, 10.0), 2u);
  EXPECT_TRUE(analyseTopology(octahedron).closed());
  EXPECT_EQ(octahedron.triangles.size(), 6u + 2 * 3u);
  // Three holes at a vertex, between three fans: their order around it is not topology's to
  // say, so none is filled. A hexagonal bipyramid without every other face at its top.
  Mesh bipyramid;
  bipyramid.vertices = {{0, 0, 1}, {0, 0, -1}};
  for (int k = 0; k < 6; ++k)
    bipyramid.vertices.push_back({std::cos(k * M_PI / 3), std::sin(k * M_PI / 3), 0});
  for (uint32_t k = 0; k < 6; ++k) {
    const uint32_t a = 2 + k, b = 2 + (k + 1) % 6;
    if (k % 2 == 0) bipyramid.triangles.push_back({0, a, b});
    bipyramid.triangles.push_back({1, b, a});
  }
  ASSERT_EQ(analyseTopology(bipyramid).boundaryEdges, 9u);
  EXPECT_EQ(fillSmallHoles(bipyramid, 10.0), 0u);
  EXPECT_EQ(bipyramid.triangles.size(), 9u);
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

// The meshes side by side in one mesh, not welded.
Mesh together(const std::vector<Mesh>& parts) {
  Mesh all;
  for (const Mesh& part : parts) {
    const auto base = static_cast<uint32_t>(all.vertices.size());
    all.vertices.insert(all.vertices.end(), part.vertices.begin(), part.vertices.end());
    for (const auto& t : part.triangles) all.triangles.push_back({base + t[0], base + t[1], base + t[2]});
  }
  return all;
}

// Points of the triangles [first, last) of `mesh`, by id.
std::set<uint32_t> pointsOf(const Mesh& mesh, size_t first, size_t last) {
  std::set<uint32_t> ids;
  for (size_t t = first; t < last; ++t) ids.insert(mesh.triangles[t].begin(), mesh.triangles[t].end());
  return ids;
}

TEST(Mesh, PartsTouchingAlongAnEdgeAreSplitApart) {
  // Two unit cubes that share only the edge x = y = 1. Welded, that edge has four
  // triangles and its ends belong to both cubes: the mesh was refused as non-manifold.
  const Mesh cubes = together({boxMesh({0, 0, 0}, {1, 1, 1}), boxMesh({1, 1, 0}, {1, 1, 1})});
  const MeshTopology welded = analyseTopology(weldExact(cubes));
  EXPECT_EQ(welded.nonManifoldEdges, 1u);
  EXPECT_NE(welded.describe().find("for example the edge (1, 1, 0)-(1, 1, 1)"), std::string::npos)
      << welded.describe();
  const Model m = modelFromMesh(cubes, "two cubes");
  EXPECT_EQ(m.edgesSplit, 1u);
  EXPECT_NO_THROW(requireClosed(m));
  EXPECT_EQ(m.mesh.vertices.size(), 16u);  // the edge's two ends, once for each cube
  // Each cube is closed on its own: no point is shared between them.
  ASSERT_EQ(m.mesh.triangles.size(), 24u);
  const std::set<uint32_t> first = pointsOf(m.mesh, 0, 12), second = pointsOf(m.mesh, 12, 24);
  for (uint32_t v : first) EXPECT_EQ(second.count(v), 0u) << v;
  // A plane across the edge: two squares, each a loop of its own cube, both turning the same way.
  MeshSliceStats stats;
  const SliceSet set = sliceMesh(m.mesh, makeSliceFrame({0, 0, 1}), {0.25, 0.5}, &stats);
  EXPECT_EQ(stats.loops, 4u);
  EXPECT_EQ(stats.inconsistentLoops, 0u);
  for (const Slice& s : set.slices) EXPECT_NEAR(s.region.area(), 2, 1e-9);
  // A part turned inside out is a closed part too: its sections wind the other way, and
  // are filled all the same.
  Mesh inside = boxMesh({1, 1, 0}, {1, 1, 1});
  for (auto& t : inside.triangles) std::swap(t[1], t[2]);
  const Model flipped = modelFromMesh(together({boxMesh({0, 0, 0}, {1, 1, 1}), inside}), "flipped");
  EXPECT_EQ(flipped.edgesSplit, 1u);
  EXPECT_NO_THROW(requireClosed(flipped));
  EXPECT_NEAR(sliceMesh(flipped.mesh, makeSliceFrame({0, 0, 1}), {0.5}).slices[0].region.area(), 2, 1e-9);
}

TEST(Mesh, OverlappingPartsOnAnEdgeAreSplitByTheirFans) {
  // A unit cube, and a unit cube turned 135 degrees about its edge x = y = 1 so that it
  // reaches into the first (as two parts of cgal/diplodocus.off do where welding joined them).
  // Going round the edge the triangles do not alternate in direction; about each end, each
  // cube's fan leads from one of its triangles on the edge to the other.
  Mesh turned = boxMesh({0, 0, 0}, {1, 1, 1});
  const double h = std::sqrt(0.5);
  for (Vec3& p : turned.vertices) p = {1 - h * p.x + h * p.y, 1 - h * p.x - h * p.y, p.z};
  const Model m = modelFromMesh(together({boxMesh({0, 0, 0}, {1, 1, 1}), turned}), "overlapping cubes");
  EXPECT_EQ(m.edgesSplit, 1u);
  EXPECT_NO_THROW(requireClosed(m));
  EXPECT_EQ(m.mesh.vertices.size(), 16u);
  // The sections are the union of the two squares, which overlap by sqrt(2) - 1.
  MeshSliceStats stats;
  const SliceSet set = sliceMesh(m.mesh, makeSliceFrame({0, 0, 1}), {0.5}, &stats);
  EXPECT_EQ(stats.inconsistentLoops, 0u);
  EXPECT_NEAR(set.slices[0].region.area(), 3 - std::sqrt(2.0), 1e-6);
}

TEST(Mesh, PartsFaceToFaceAboutOneEdgeAreSplitApart) {
  // Three unit cubes about the edge x = y = 1, two of them face to face with the third:
  // the coincident faces, turned opposite ways, lie at the same angle about the edge.
  const Mesh cubes =
      together({boxMesh({0, 0, 0}, {1, 1, 1}), boxMesh({1, 1, 0}, {1, 1, 1}), boxMesh({0, 1, 0}, {1, 1, 1})});
  const Model m = modelFromMesh(cubes, "three cubes");
  EXPECT_NO_THROW(requireClosed(m)) << analyseTopology(m.mesh).describe();
  for (size_t a = 0; a < 3; ++a) {
    const std::set<uint32_t> mine = pointsOf(m.mesh, 12 * a, 12 * a + 12);
    EXPECT_EQ(mine.size(), 8u);
    for (size_t b = a + 1; b < 3; ++b)
      for (uint32_t v : pointsOf(m.mesh, 12 * b, 12 * b + 12)) EXPECT_EQ(mine.count(v), 0u) << a << b;
  }
  MeshSliceStats stats;
  const SliceSet set = sliceMesh(m.mesh, makeSliceFrame({0, 0, 1}), {0.5}, &stats);
  EXPECT_EQ(stats.inconsistentLoops, 0u);
  EXPECT_NEAR(set.slices[0].region.area(), 3, 1e-9);
}

TEST(Mesh, EdgesThatCannotBeSplitAreNamed) {
  // A fin on a cube's edge (three triangles there), and two cubes touching along an edge
  // with one triangle there flipped (three of the four run one way along it).
  Mesh fin = boxMesh({0, 0, 0}, {1, 1, 1});
  fin.vertices.push_back({2, 2, 0.5});
  fin.triangles.push_back({3, 7, 8});  // on the edge (1, 1, 0)-(1, 1, 1)
  Mesh oneFlipped = boxMesh({1, 1, 0}, {1, 1, 1});
  std::swap(oneFlipped.triangles[5][1], oneFlipped.triangles[5][2]);  // (0, 5, 4): on the edge
  const Mesh flipped = together({boxMesh({0, 0, 0}, {1, 1, 1}), oneFlipped});
  for (const Mesh& mesh : {fin, flipped}) {
    const Model m = modelFromMesh(mesh, "touching");
    EXPECT_EQ(m.edgesSplit, 0u);
    try {
      requireClosed(m);
      ADD_FAILURE() << "no error";
    } catch (const Error& e) {
      const std::string text = e.what();
      EXPECT_NE(text.find("1 non-manifold edge"), std::string::npos) << text;
      EXPECT_NE(text.find("for example the edge (1, 1, 0)-(1, 1, 1)"), std::string::npos) << text;
      EXPECT_NE(text.find("could not be"), std::string::npos) << text;
    }
  }
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
