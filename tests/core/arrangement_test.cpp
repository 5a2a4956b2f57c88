// SPDX-License-Identifier: LGPL-2.1-or-later
// Arrangement building blocks: the rigidity certificate, Reeb graphs of slice sets and
// their simplification, and the cylinder approximation's dynamic programme.
#include <gtest/gtest.h>

#include <cmath>

#include "cylinders/gca.hpp"
#include "reeb/reeb_graph.hpp"
#include "verify/certificate.hpp"

namespace sliceform {
namespace {

Region2d rect(double x0, double y0, double x1, double y1) {
  return Region2d::fromLoops({{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}});
}

// A grid of nu U-patches and nv V-patches with every U hinged to every V.
std::pair<std::vector<BarPatch>, std::vector<PinHinge>> grid(int nu, int nv) {
  std::vector<BarPatch> patches;
  for (int i = 0; i < nu; ++i) patches.push_back({Family::U, 10.0 * i});
  for (int j = 0; j < nv; ++j) patches.push_back({Family::V, 7.0 * j + 3});
  std::vector<PinHinge> hinges;
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) hinges.push_back({i, nu + j});
  return {patches, hinges};
}

TEST(Certificate, TwoByTwoGridFoldsAndNothingElse) {
  const auto [patches, hinges] = grid(2, 2);
  const Certificate c = certify(patches, hinges);
  EXPECT_TRUE(c.stable) << c.reason;
  EXPECT_EQ(c.nullity, 1);
  EXPECT_EQ(c.pins, 4);
}

TEST(Certificate, LargerGridsStayStable) {
  const auto [patches, hinges] = grid(5, 3);
  EXPECT_EQ(certify(patches, hinges).nullity, 1);
}

TEST(Certificate, PatchHingedOnceWobbles) {
  auto [patches, hinges] = grid(2, 2);
  patches.push_back({Family::U, 25});
  hinges.push_back({4, 2});  // the new U-patch hangs on one V-patch: it can swing
  const Certificate c = certify(patches, hinges);
  EXPECT_FALSE(c.stable);
  EXPECT_EQ(c.nullity, 2);
  EXPECT_NE(c.reason.find("wobbles"), std::string::npos);
}

TEST(Certificate, UPatchHingedToOneVPatchOnlySwings) {
  auto [patches, hinges] = grid(2, 2);
  patches.push_back({Family::U, 25});
  hinges.push_back({4, 2});
  hinges.push_back({4, 2});  // two hinge segments on the same line: still one pin
  EXPECT_EQ(certify(patches, hinges).nullity, 2);
}

TEST(Certificate, SharedPatchDoesNotChainStability) {
  // Two 2x2 grids sharing one U-patch (the paper's Def. 12 chain) swing against each other.
  std::vector<BarPatch> p{{Family::U, 0},   {Family::U, 10}, {Family::V, 0}, {Family::V, 5},
                          {Family::U, -10}, {Family::V, 20}, {Family::V, 25}};
  std::vector<PinHinge> h{{0, 2}, {0, 3}, {1, 2}, {1, 3}, {0, 5}, {0, 6}, {4, 5}, {4, 6}};
  EXPECT_EQ(certify(p, h).nullity, 2);
  h.push_back({1, 5});
  h.push_back({1, 6});  // a second U-patch shared by both: rigid again
  EXPECT_EQ(certify(p, h).nullity, 1);
}

TEST(Certificate, TwoSeparateGridsAreNotOneScaffold) {
  auto [patches, hinges] = grid(2, 2);
  for (int k = 0; k < 4; ++k) patches.push_back({patches[k].family, patches[k].position + 100});
  for (int k = 0; k < 4; ++k) hinges.push_back({hinges[k].a + 4, hinges[k].b + 4});
  EXPECT_EQ(certify(patches, hinges).nullity, 1 + 3 + 1);  // the second grid moves freely and folds
}

TEST(Certificate, ClosePatchesFarFromTheOriginStayApart) {
  // The answer must not depend on where the model sits: a grid of patches 1 mm apart,
  // 20 m from the origin (scaled by the largest coordinate, it once came out nullity 3).
  for (double offset : {0.0, 677.0, 20000.0}) {
    std::vector<BarPatch> patches{
        {Family::U, offset}, {Family::U, offset + 1}, {Family::V, offset}, {Family::V, offset + 1}};
    std::vector<PinHinge> hinges{{0, 2}, {0, 3}, {1, 2}, {1, 3}};
    EXPECT_EQ(certify(patches, hinges).nullity, 1) << "offset " << offset;
    patches.push_back({Family::U, offset + 0.5});
    hinges.push_back({4, 3});  // a patch hung on one of them still swings
    EXPECT_EQ(certify(patches, hinges).nullity, 2) << "offset " << offset;
  }
}

TEST(Certificate, SeveralHingesOfOnePairAreOnePin) {
  auto [patches, hinges] = grid(2, 2);
  hinges.push_back(hinges[0]);
  const Certificate c = certify(patches, hinges);
  EXPECT_EQ(c.pins, 4);
  EXPECT_EQ(c.nullity, 1);
}

TEST(Certificate, RefusesHingeWithinOneFamily) {
  const Certificate c = certify({{Family::U, 0}, {Family::U, 5}}, {{0, 1}});
  EXPECT_FALSE(c.stable);
  EXPECT_NE(c.reason.find("same family"), std::string::npos);
}

// A slice set of a "Y": one trunk piece that splits into two branches; the right one is
// `width` wide and reaches `above` higher than the trunk.
SliceSet ySlices(int trunk, int branch, double width, double above = 0) {
  SliceSet set;
  set.interval = 1;
  for (int i = 0; i < trunk; ++i) set.slices.push_back({double(i), rect(0, 0, 10, 10)});
  for (int i = 0; i < branch; ++i)
    set.slices.push_back({double(trunk + i), rect(0, 0, 4, 10).unite(rect(10 - width, 0, 10, 10 + above))});
  return set;
}

TEST(ReebGraph, SplitGivesThreeEdgesAtOneVertex) {
  const ReebGraph g = buildReebGraph(ySlices(5, 4, 4));
  ASSERT_EQ(g.edges.size(), 3u);
  EXPECT_EQ(g.vertexCount, 4);  // trunk start, split, two branch ends
  const ReebEdge& trunk = g.edges[0];
  EXPECT_EQ(trunk.patches.size(), 5u);
  EXPECT_EQ(g.outgoing(trunk.head).size(), 2u);
  EXPECT_DOUBLE_EQ(trunk.weight(), 5 * 100.0);
}

TEST(ReebGraph, SmallBranchIsAbsorbedAndChainJoins) {
  // Branches of 40 and 2.4 mm² a slice; the thin one weighs 9.6 / 500 of the trunk.
  ReebGraph g = buildReebGraph(ySlices(5, 4, 0.2, 2));
  simplifyReebGraph(g, 0.03);
  ASSERT_EQ(g.edges.size(), 1u);  // thin branch absorbed, then trunk and big branch joined
  const ReebEdge& e = g.edges[0];
  EXPECT_EQ(e.patches.size(), 9u);
  // The thin branch's silhouette survives on the trunk's last patch (a right merge): the
  // part of it above the trunk, 0.2 x 2, is added.
  EXPECT_NEAR(e.patches[4].area(), 100 + 0.4, 1e-6);
  EXPECT_NEAR(e.patches.back().area(), 40, 1e-6);
}

TEST(ReebGraph, LargeBranchesStay) {
  ReebGraph g = buildReebGraph(ySlices(5, 4, 4));
  simplifyReebGraph(g, 0.03);
  EXPECT_EQ(g.edges.size(), 3u);
}

TEST(ReebGraph, RingGivesACycle) {
  // A ring seen edge-on: one piece, then two, then one again.
  SliceSet set;
  for (int i = 0; i < 3; ++i) set.slices.push_back({double(i), rect(0, 0, 10, 10)});
  for (int i = 3; i < 6; ++i) set.slices.push_back({double(i), rect(0, 0, 3, 10).unite(rect(7, 0, 10, 10))});
  for (int i = 6; i < 9; ++i) set.slices.push_back({double(i), rect(0, 0, 10, 10)});
  const ReebGraph g = buildReebGraph(set);
  EXPECT_EQ(g.edges.size(), 4u);
  EXPECT_EQ(g.vertexCount, 4);  // start, split, merge, end: 4 edges on 4 vertices has one cycle
}

TEST(Gca, IdenticalPatchesMakeOneCylinder) {
  const std::vector<Region2d> patches(6, rect(0, 0, 5, 5));
  const auto groups = partitionPatches(patches, 1.0, 0.0);
  ASSERT_EQ(groups.size(), 1u);
  EXPECT_EQ(groups[0], std::make_pair(0, 5));
}

TEST(Gca, ErrorIsEquationOne) {
  // Squares of side 2, 4: union area 16, error ds * ((16 - 4) + (16 - 16)).
  const std::vector<Region2d> patches{rect(0, 0, 2, 2), rect(0, 0, 4, 4)};
  EXPECT_DOUBLE_EQ(cylinderError(patches, 0, 1, 0.5), 0.5 * 12);
}

TEST(Gca, TwoSizesSplitWhereTheyChange) {
  std::vector<Region2d> patches(4, rect(0, 0, 2, 2));
  for (int k = 0; k < 4; ++k) patches.push_back(rect(0, 0, 4, 4));
  const auto groups = partitionPatches(patches, 1.0, 0.01);
  ASSERT_EQ(groups.size(), 2u);
  EXPECT_EQ(groups[0], std::make_pair(0, 3));
  EXPECT_EQ(groups[1], std::make_pair(4, 7));
}

TEST(Gca, LooserTauMeansFewerCylinders) {
  // A cone: areas grow steadily, so the count falls as tauA grows.
  std::vector<Region2d> patches;
  for (int k = 1; k <= 40; ++k) patches.push_back(rect(0, 0, k, k));
  size_t previous = 1000;
  for (double tau : {0.01, 0.1, 0.5}) {
    const auto groups = partitionPatches(patches, 1.0, tau);
    EXPECT_LE(groups.size(), previous);
    previous = groups.size();
    double volume = 0, error = 0;
    for (const Region2d& p : patches) volume += p.area();
    for (const auto& [i, j] : groups) error += cylinderError(patches, i, j, 1.0);
    EXPECT_LE(error, tau * volume + 1e-6);
  }
  EXPECT_LT(previous, 10u);
}

TEST(Gca, NoPartitionFitsTheLeastErrorOneOfRunsUpToTwiceTheShortest) {
  // A cone with no budget: no run of 3 or more fits, so runs of 3 to 5 slices are measured
  // (each row's unions going on from where the first measure stopped) and the partition
  // with the least error stands. Checked against every partition into such runs.
  std::vector<Region2d> patches;
  for (int k = 1; k <= 13; ++k) patches.push_back(rect(0, 0, k, 2 * k));
  const int n = static_cast<int>(patches.size()), minRun = 3;
  const auto groups = partitionPatches(patches, 1.0, 0.0, minRun);
  double error = 0;
  int next = 0;
  for (const auto& [i, j] : groups) {
    EXPECT_EQ(i, next);
    EXPECT_GE(j - i + 1, minRun);
    EXPECT_LE(j - i + 1, 2 * minRun - 1);
    error += cylinderError(patches, i, j, 1.0);
    next = j + 1;
  }
  EXPECT_EQ(next, n);
  // least[i]: the least error of patches i.. in runs of 3 to 5.
  std::vector<double> least(n + 1, HUGE_VAL);
  least[n] = 0;
  for (int i = n - 1; i >= 0; --i)
    for (int len = minRun; len <= 2 * minRun - 1 && i + len <= n; ++len)
      least[i] = std::min(least[i], cylinderError(patches, i, i + len - 1, 1.0) + least[i + len]);
  EXPECT_NEAR(error, least[0], 1e-9);
  EXPECT_GT(error, 0);
}

TEST(Gca, LongEdgesGiveTheAnswerOfEveryRunMeasured) {
  // 30 equal sections and 10 growing slowly, whose answers take runs longer than the 12
  // slices measured first, then 56 wavering ones. Each answer must be the one of the DP
  // over every run: the first group count that fits the budget, with its least error;
  // where none fits (3 slices a run at least, tauA 0.03), the first with the least error of
  // all (there, the equal sections in one run).
  std::vector<Region2d> patches;
  for (int k = 0; k < 40; ++k) patches.push_back(rect(0, 0, 20 + 0.05 * std::max(0, k - 30), 15));
  for (int k = 40; k < 96; ++k)
    patches.push_back(rect(0, 0, std::round(2000 + 800 * std::sin(k / 7.0) + 60 * std::sin(k * 1.3)) / 100,
                           std::round(1500 + 600 * std::cos(k / 9.0) + 40 * std::sin(k * 2.1)) / 100));
  const int n = static_cast<int>(patches.size());
  double volume = 0;
  for (const Region2d& p : patches) volume += p.area();
  for (const auto& [minRun, tau] :
       std::vector<std::pair<int, double>>{{1, 0.03}, {1, 0.1}, {1, 0.2}, {3, 0.03}, {3, 0.1}, {3, 0.2}}) {
    SCOPED_TRACE(testing::Message() << "minRun " << minRun << ", tauA " << tau);
    const double budget = tau * volume;
    // Every run until its error is over the budget and it is 2 minRun - 1 slices long, its
    // union grown one patch at a time.
    std::vector<std::vector<double>> err(n, std::vector<double>(n, HUGE_VAL));
    for (int i = 0; i < n; ++i) {
      Region2d united = patches[i];
      double areas = 0;
      for (int j = i; j < n; ++j) {
        united = j == i ? united : united.unite(patches[j]);
        areas += patches[j].area();
        err[i][j] = (j - i + 1) * united.area() - areas;
        if (err[i][j] > budget && j - i + 1 >= 2 * minRun - 1) break;
      }
    }
    // The least error of each group count; the first count that fits, else the least.
    std::vector<double> least(n + 1, HUGE_VAL), next(n + 1);
    least[n] = 0;
    int groups = 0;
    double error = HUGE_VAL;
    for (int g = 1; g * minRun <= n && !(error <= budget); ++g) {
      std::fill(next.begin(), next.end(), HUGE_VAL);
      for (int i = 0; i < n; ++i)
        for (int k = i + minRun - 1; k < n; ++k) next[i] = std::min(next[i], err[i][k] + least[k + 1]);
      least.swap(next);
      if (least[0] < error) groups = g, error = least[0];
    }
    EXPECT_EQ(error <= budget, tau > 0.05 || minRun == 1);
    const auto answer = partitionPatches(patches, 1.0, tau, minRun);
    EXPECT_EQ(static_cast<int>(answer.size()), groups);
    double total = 0;
    int from = 0;
    for (const auto& [i, j] : answer) {
      EXPECT_EQ(i, from);
      EXPECT_GE(j - i + 1, minRun);
      ASSERT_LT(err[i][j], HUGE_VAL);
      total += err[i][j];
      from = j + 1;
    }
    EXPECT_EQ(from, n);
    EXPECT_NEAR(total, error, 1e-9 * budget);
  }
}

}  // namespace
}  // namespace sliceform
