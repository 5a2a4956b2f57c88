// SPDX-License-Identifier: LGPL-2.1-or-later
// Arrangement on real solids: Reeb graph topology of OCCT solids, the cylinder DP against
// brute force, and whole scaffolds that the certificate accepts under every scheme.
#include <gtest/gtest.h>
#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>

#include <BRepPrimAPI_MakeBox.hxx>
#include <BRep_Builder.hxx>
#include <TopoDS_Compound.hxx>

#include <algorithm>
#include <cmath>
#include <random>

#include "arrangement/arrange.hpp"
#include "realization/realize.hpp"
#include "slicing/mesh_slicer.hpp"
#include "support/error.hpp"
#include "test_support.hpp"

namespace sliceform {
namespace {

using test::makeBoxWithHoles;
using test::makeSphere;
using test::makeTorus;

SliceSet meshSlices(const TopoDS_Shape& shape, Vec3 normal, int count) {
  const Model model = modelFromShape(shape, "test solid");
  const SliceFrame frame = makeSliceFrame(normal);
  const Interval range = model.mesh.extent(frame.normal);
  return sliceMesh(model.mesh, frame, uniformPositions(range.lo, range.hi, count));
}

// Two spheres on the X axis joined by a bar along X (bar radius 4 * k).
TopoDS_Shape dumbbell(double k = 1) {
  const TopoDS_Shape left = BRepPrimAPI_MakeSphere(gp_Pnt(-30 * k, 0, 0), 15 * k).Shape();
  const TopoDS_Shape right = BRepPrimAPI_MakeSphere(gp_Pnt(30 * k, 0, 0), 15 * k).Shape();
  const TopoDS_Shape bar =
      BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(-30 * k, 0, 0), gp_Dir(1, 0, 0)), 4 * k, 60 * k).Shape();
  return BRepAlgoAPI_Fuse(BRepAlgoAPI_Fuse(left, bar).Shape(), right).Shape();
}

TEST(ReebSolids, TorusAcrossItsHoleHasOneCycle) {
  // Torus around Z, sliced along X: one piece at each end, two across the hole.
  ReebGraph g = buildReebGraph(meshSlices(makeTorus(30, 8), {1, 0, 0}, 64));
  simplifyReebGraph(g, 0.03);
  EXPECT_EQ(g.edges.size(), 4u);
  EXPECT_EQ(g.cycleRank(), 1);
  EXPECT_EQ(g.componentCount(), 1);
}

TEST(ReebSolids, TorusAlongItsAxisIsOneRingEdge) {
  // Sliced along Z every section is one annulus: a single edge, no cycle in the graph.
  ReebGraph g = buildReebGraph(meshSlices(makeTorus(30, 8), {0, 0, 1}, 32));
  EXPECT_EQ(g.edges.size(), 1u);
  EXPECT_EQ(g.cycleRank(), 0);
}

TEST(ReebSolids, DumbbellAlongTheBarIsOneChain) {
  ReebGraph g = buildReebGraph(meshSlices(dumbbell(), {1, 0, 0}, 96));
  simplifyReebGraph(g, 0.03);
  EXPECT_EQ(g.edges.size(), 1u);
  EXPECT_EQ(g.cycleRank(), 0);
}

TEST(ReebSolids, DumbbellAcrossTheBarMergesThenSplits) {
  // Along Y: two discs, joined through the bar's section near y = 0, then two discs again.
  // The solid has genus 0, so the graph is a tree: two edges in, the joined middle, two out.
  ReebGraph g = buildReebGraph(meshSlices(dumbbell(), {0, 1, 0}, 96));
  simplifyReebGraph(g, 0.03);
  ASSERT_EQ(g.edges.size(), 5u);
  EXPECT_EQ(g.cycleRank(), 0);
  EXPECT_EQ(g.componentCount(), 1);
  int middle = -1;
  for (int e = 0; e < 5; ++e)
    if (g.incoming(g.edges[e].tail).size() == 2 && g.outgoing(g.edges[e].head).size() == 2) middle = e;
  ASSERT_GE(middle, 0);
  // The bar (radius 4) joins the discs for |y| < 4: the middle edge spans about 8 mm.
  const double span = (g.edges[middle].lastSlice() - g.edges[middle].firstSlice + 1) * 30.0 / 96;
  EXPECT_NEAR(span, 8, 2 * 30.0 / 96);
}

// Fewest groups of a partition whose error fits tauA, by trying all 2^(n-1) partitions.
size_t bruteForceGroups(const std::vector<Region2d>& patches, double ds, double tauA) {
  const int n = static_cast<int>(patches.size());
  double volume = 0;
  for (const Region2d& p : patches) volume += ds * p.area();
  size_t best = patches.size();
  for (unsigned cuts = 0; cuts < (1u << (n - 1)); ++cuts) {
    double error = 0;
    size_t groups = 0;
    for (int i = 0; i < n;) {
      int j = i;
      while (j + 1 < n && !(cuts & (1u << j))) ++j;
      error += cylinderError(patches, i, j, ds);
      ++groups;
      i = j + 1;
    }
    if (error <= tauA * volume) best = std::min(best, groups);
  }
  return best;
}

TEST(Gca, DynamicProgrammeMatchesBruteForce) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> size(1, 10), shift(-3, 3);
  for (int trial = 0; trial < 40; ++trial) {
    const int n = 2 + trial % 8;
    std::vector<Region2d> patches;
    for (int k = 0; k < n; ++k) {
      const double w = size(random), h = size(random), x = shift(random);
      patches.push_back(Region2d::fromLoops({{{x, 0}, {x + w, 0}, {x + w, h}, {x, h}}}));
    }
    for (double tau : {0.0, 0.05, 0.3}) {
      const auto groups = partitionPatches(patches, 0.5, tau);
      EXPECT_EQ(groups.size(), bruteForceGroups(patches, 0.5, tau)) << "trial " << trial << " tau " << tau;
      int next = 0;  // the groups tile the patches in order
      for (const auto& [i, j] : groups) {
        EXPECT_EQ(i, next);
        next = j + 1;
      }
      EXPECT_EQ(next, n);
    }
  }
}

struct SchemeCase {
  const char* name;
  Scheme scheme;
};

class ScaffoldOnSolids : public ::testing::TestWithParam<SchemeCase> {};

void expectCertified(const TopoDS_Shape& shape, Scheme scheme) {
  ArrangementParams params;
  params.slices = 48;
  params.stabilize.scheme = scheme;
  const Arrangement a = arrange(modelFromShape(shape, "test solid"), params);
  EXPECT_TRUE(a.certificate.stable) << a.certificate.reason;
  EXPECT_EQ(a.certificate.nullity, 1);
  int u = 0, v = 0;
  for (const ScaffoldPatch& p : a.scaffold.patches) (p.family == Family::U ? u : v)++;
  EXPECT_GE(u, 2);
  EXPECT_GE(v, 2);
  // The required family has every cylinder covered on these simple solids.
  // Only small parts may be left without a patch: tips where no hinge can hold under the
  // hinge rules (the dumbbell's end caps).
  for (Family f : {Family::U, Family::V}) {
    const auto& cylinders = f == Family::U ? a.uCylinders : a.vCylinders;
    double largest = 0;
    for (const Cylinder& c : cylinders) largest = std::max(largest, c.section.area());
    for (int c : f == Family::U ? a.scaffold.uncoveredU : a.scaffold.uncoveredV)
      EXPECT_LT(cylinders[c].section.area(), 0.15 * largest) << "a large cylinder got no patch";
  }
  // Every hinge lies inside both patches' shapes, and holding ones are long enough.
  for (const ScaffoldHinge& h : a.scaffold.hinges) {
    EXPECT_GT(h.w.hi, h.w.lo);
    if (h.holds) EXPECT_GE(h.w.hi - h.w.lo, params.hinges.minHingeLength);
    const auto [p0, p1] = hingeEnds(a, h);
    const Vec3 mid = (p0 + p1) * 0.5;
    for (int k : {h.u, h.v}) {
      const ScaffoldPatch& p = a.scaffold.patches[k];
      const SliceSet& set = p.family == Family::U ? a.u : a.v;
      const Region2d& section = (p.family == Family::U ? a.uCylinders : a.vCylinders)[p.cylinder].section;
      EXPECT_NEAR(set.frame.position(mid), p.position, 1e-9);
      const Vec2 q = set.frame.to2d(mid);
      EXPECT_FALSE(section
                       .intersect(Region2d::fromLoops({{{q.x - 0.01, q.y - 0.01},
                                                        {q.x + 0.01, q.y - 0.01},
                                                        {q.x + 0.01, q.y + 0.01},
                                                        {q.x - 0.01, q.y + 0.01}}}))
                       .empty());
    }
  }
  EXPECT_GT(a.quality.silhouetteIouU, 0.8);
  EXPECT_GT(a.quality.silhouetteIouV, 0.8);
  EXPECT_GT(a.quality.volumeIou, 0.5);
  EXPECT_LE(a.quality.volumeIou, 1.0 + 1e-9);
}

TEST_P(ScaffoldOnSolids, Sphere) {
  expectCertified(makeSphere(60), GetParam().scheme);
}
TEST_P(ScaffoldOnSolids, Torus) {
  expectCertified(makeTorus(60, 20), GetParam().scheme);
}
TEST_P(ScaffoldOnSolids, BoxWithHoles) {
  expectCertified(makeBoxWithHoles(120, 80, 60, {{40, 40, 12}, {85, 40, 12}}), GetParam().scheme);
}
// A bar of 8 mm radius: thick enough for 4 mm hinges with 2 mm of paper beside each slot.
TEST_P(ScaffoldOnSolids, Dumbbell) {
  expectCertified(dumbbell(2), GetParam().scheme);
}

INSTANTIATE_TEST_SUITE_P(Schemes, ScaffoldOnSolids,
                         ::testing::Values(SchemeCase{"both", Scheme::Both},
                                           SchemeCase{"U", Scheme::DominantU},
                                           SchemeCase{"V", Scheme::DominantV}),
                         [](const auto& info) { return std::string(info.param.name); });

// A plate 147 mm square and 28 mm thick with 7 x 7 square through holes of 7 mm, the outer
// ones 7 mm from the border. A slice across a row of holes has a 7 mm strip at either
// border: a branch of the Reeb graph small enough that simplification absorbs it into the
// neighbouring full-width patch, so the strip's own slices lie in no cylinder. Volume IoU,
// taken as model volume over cylinder volume, came out at 1.036.
TopoDS_Shape plateWithSquareHoles() {
  BRep_Builder builder;
  TopoDS_Compound holes;
  builder.MakeCompound(holes);
  for (int i = 0; i < 7; ++i)
    for (int j = 0; j < 7; ++j)
      builder.Add(holes, BRepPrimAPI_MakeBox(gp_Pnt(7 + 21 * i, 7 + 21 * j, -1), 7, 7, 30).Shape());
  return test::cut(BRepPrimAPI_MakeBox(147, 147, 28).Shape(), holes);
}

TEST(Quality, VolumeIouOfAPlateWithManyHolesIsAtMostOne) {
  const Model plate = modelFromShape(plateWithSquareHoles(), "plate");
  ArrangementParams params;
  const Arrangement a = arrange(plate, params);
  ASSERT_LT(a.reebU.edges.size(), buildReebGraph(a.u).edges.size()) << "no branch was absorbed";
  EXPECT_LE(a.quality.volumeIou, 1.0);
  EXPECT_GT(a.quality.volumeIou, 0.9);
  // Nothing absorbed, and every patch its own cylinder: the cylinders are the slices.
  params.tauM = 0;
  params.tauA = 0;
  EXPECT_NEAR(arrange(plate, params).quality.volumeIou, 1.0, 1e-9);
}

TEST(Arrange, RefusesWhatCannotHold) {
  ArrangementParams params;
  params.slices = 32;
  params.hinges.minHingeLength = 500;  // longer than the sphere
  try {
    arrange(modelFromShape(makeSphere(30), "small ball"), params);
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::Unbuildable);
    EXPECT_NE(std::string(e.what()).find("too thin or too small"), std::string::npos);
  }
}

TEST(Arrange, RefusesDirectionsThatAreNotOrthogonal) {
  ArrangementParams params;
  params.v = {1, 1, 0};
  try {
    arrange(modelFromShape(makeSphere(30), "ball"), params);
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::BadParameter);
  }
}

TEST(Arrange, MaxSpacingAddsHeldPatches) {
  ArrangementParams params;
  params.slices = 64;
  const Model model = modelFromShape(BRepPrimAPI_MakeBox(200, 60, 60).Shape(), "long box");
  const Arrangement sparse = arrange(model, params);
  params.stabilize.maxSpacing = 20;
  const Arrangement dense = arrange(model, params);
  EXPECT_GT(dense.scaffold.patches.size(), sparse.scaffold.patches.size());
  EXPECT_TRUE(dense.certificate.stable) << dense.certificate.reason;
  // Along the 200 mm U extent, no gap between U-patches exceeds the spacing (+ one slice).
  std::vector<double> us;
  for (const ScaffoldPatch& p : dense.scaffold.patches)
    if (p.family == Family::U) us.push_back(p.position);
  std::sort(us.begin(), us.end());
  for (size_t k = 1; k < us.size(); ++k) EXPECT_LE(us[k] - us[k - 1], 2 * (20 + dense.u.interval));
}

// A block with a comb of 1 mm teeth 1 mm apart on top: sliced along X every section
// differs from the last, so every slice would make a cylinder of its own.
TopoDS_Shape comb() {
  TopoDS_Shape shape = BRepPrimAPI_MakeBox(gp_Pnt(0, 0, 0), gp_Pnt(100, 40, 20)).Shape();
  for (int k = 0; k < 50; ++k)
    shape =
        BRepAlgoAPI_Fuse(shape, BRepPrimAPI_MakeBox(gp_Pnt(2 * k, 0, 20), gp_Pnt(2 * k + 1, 40, 60)).Shape())
            .Shape();
  return shape;
}

TEST(Arrange, PatchesOfOneFamilyKeepPaperBetweenTheirSlots) {
  ArrangementParams params;
  params.slices = 100;
  params.u = {1, 0, 0};
  params.v = {0, 1, 0};
  params.hinges.slotWidth = 0.5;
  const Model model = modelFromShape(comb(), "comb");
  const Arrangement a = arrange(model, params);
  EXPECT_DOUBLE_EQ(a.minSpacing, 2.5);  // slot width + the 2 mm kept beside a slot
  EXPECT_TRUE(a.certificate.stable) << a.certificate.reason;
  const RealizationInput in = realizationInput(a, model.meshDeflection);
  int stackedPairs = 0;
  for (size_t i = 0; i < in.patches.size(); ++i) {
    for (size_t j = i + 1; j < in.patches.size(); ++j) {
      const PatchShape &p = in.patches[i], &q = in.patches[j];
      if (p.family != q.family || p.position == q.position) continue;
      if (p.shape.withoutHoles().intersect(q.shape.withoutHoles()).empty()) continue;
      ++stackedPairs;
      EXPECT_GE(std::fabs(p.position - q.position), a.minSpacing - 1e-9)
          << patchId(a.scaffold, static_cast<int>(i)) << " and " << patchId(a.scaffold, static_cast<int>(j));
    }
  }
  EXPECT_GT(stackedPairs, 0);
  // Below the slot width plus that paper, the rule cannot hold: refused, naming the option.
  params.stabilize.minSpacing = 1;
  try {
    arrange(model, params);
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::BadParameter);
    EXPECT_NE(std::string(e.what()).find("--min-slot-edge-distance"), std::string::npos);
  }
}

}  // namespace
}  // namespace sliceform
