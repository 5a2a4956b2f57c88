// SPDX-License-Identifier: LGPL-2.1-or-later
// Region2d: areas, loop orientation, components, booleans, offsets and line intervals.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "frames/hinge_table.hpp"
#include "geometry/line_erosion.hpp"
#include "geometry/region2d.hpp"
#include "support/error.hpp"
#include "test_support.hpp"

namespace sliceform {
namespace {

using Loop = Region2d::Loop;
using test::signedArea;

// Axis-aligned rectangle [x0, x1] x [y0, y1], counter-clockwise unless `clockwise`.
Loop rect(double x0, double y0, double x1, double y1, bool clockwise = false) {
  Loop l{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
  if (clockwise) std::reverse(l.begin(), l.end());
  return l;
}

// Clipper works in units of 1e-5 mm, so exact inputs come back exact up to rounding.
constexpr double kTiny = 1e-9;

TEST(Region2d, SquareWithHoleArea) {
  // Even-odd: the hole is a hole whatever its orientation.
  for (bool cw : {false, true}) {
    const Region2d r = Region2d::fromLoops({rect(0, 0, 10, 10), rect(3, 3, 7, 7, cw)});
    EXPECT_NEAR(r.area(), 100.0 - 16.0, kTiny);
    EXPECT_EQ(r.holeCount(), 1);
  }
  // Non-zero: a clockwise inner loop is a hole, a counter-clockwise one is not.
  EXPECT_NEAR(Region2d::fromLoops({rect(0, 0, 10, 10), rect(3, 3, 7, 7, true)}, FillRule::NonZero).area(),
              84.0, kTiny);
  EXPECT_NEAR(Region2d::fromLoops({rect(0, 0, 10, 10), rect(3, 3, 7, 7)}, FillRule::NonZero).area(), 100.0,
              kTiny);
  EXPECT_TRUE(Region2d().empty());
  EXPECT_EQ(Region2d().area(), 0.0);
}

TEST(Region2d, LoopsAreOrientedOuterPositiveHoleNegative) {
  // Give the outer loop clockwise and the hole counter-clockwise: loops() must fix both.
  const Region2d r = Region2d::fromLoops({rect(0, 0, 10, 10, true), rect(3, 3, 7, 7)});
  const std::vector<Loop> loops = r.loops();
  ASSERT_EQ(loops.size(), 2u);
  int outers = 0, holes = 0;
  for (const Loop& l : loops) {
    const double a = signedArea(l);
    if (a > 0) {
      ++outers;
      EXPECT_NEAR(a, 100.0, kTiny);
    } else {
      ++holes;
      EXPECT_NEAR(a, -16.0, kTiny);
    }
  }
  EXPECT_EQ(outers, 1);
  EXPECT_EQ(holes, 1);
  const Box2 b = r.bounds();
  EXPECT_FALSE(b.empty);
  EXPECT_DOUBLE_EQ(b.min.x, 0.0);
  EXPECT_DOUBLE_EQ(b.min.y, 0.0);
  EXPECT_DOUBLE_EQ(b.max.x, 10.0);
  EXPECT_DOUBLE_EQ(b.max.y, 10.0);
  EXPECT_TRUE(Region2d().bounds().empty);
}

TEST(Region2d, ComponentsOfDisjointSquares) {
  const Region2d r = Region2d::fromLoops({rect(0, 0, 2, 2), rect(5, 0, 8, 3)});
  const std::vector<Region2d> parts = r.components();
  ASSERT_EQ(parts.size(), 2u);
  double areas[2] = {parts[0].area(), parts[1].area()};
  if (areas[0] > areas[1]) std::swap(areas[0], areas[1]);
  EXPECT_NEAR(areas[0], 4.0, kTiny);
  EXPECT_NEAR(areas[1], 9.0, kTiny);
}

TEST(Region2d, ComponentsOfSquareWithHoleAndIsland) {
  // Outer 10x10 with a 6x6 hole, and a 2x2 island inside the hole.
  const Region2d r = Region2d::fromLoops({rect(0, 0, 10, 10), rect(2, 2, 8, 8), rect(4, 4, 6, 6)});
  EXPECT_NEAR(r.area(), 100.0 - 36.0 + 4.0, kTiny);
  const std::vector<Region2d> parts = r.components();
  ASSERT_EQ(parts.size(), 2u);
  const Region2d& ring = parts[0].area() > parts[1].area() ? parts[0] : parts[1];
  const Region2d& island = parts[0].area() > parts[1].area() ? parts[1] : parts[0];
  EXPECT_NEAR(ring.area(), 64.0, kTiny);
  EXPECT_EQ(ring.holeCount(), 1);
  EXPECT_EQ(ring.loops().size(), 2u);
  EXPECT_NEAR(island.area(), 4.0, kTiny);
  EXPECT_EQ(island.holeCount(), 0);
  EXPECT_EQ(island.components().size(), 1u);
}

// What a patch covers seen from the side (the spacing rule's "stacked"): holes filled,
// islands in them included, two separate squares still two.
TEST(Region2d, WithoutHolesFillsHolesAndKeepsPieces) {
  const Region2d ring = Region2d::fromLoops({rect(0, 0, 10, 10), rect(2, 2, 8, 8), rect(4, 4, 6, 6)});
  const Region2d filled = ring.withoutHoles();
  EXPECT_NEAR(filled.area(), 100.0, kTiny);
  EXPECT_EQ(filled.holeCount(), 0);
  const Region2d two = Region2d::fromLoops({rect(0, 0, 1, 1), rect(3, 0, 4, 1)}).withoutHoles();
  EXPECT_EQ(two.components().size(), 2u);
  EXPECT_NEAR(two.area(), 2.0, kTiny);
}

// subtractComponents reads the pieces off the difference's own tree; they must be the
// pieces (same paths) that subtract(...).components() gives, also where pieces touch at a
// corner, islands sit in holes, and a cut leaves a piece inside another's hole.
TEST(Region2d, SubtractComponentsMatchesSubtractThenComponents) {
  const Region2d frame = Region2d::fromLoops({rect(0, 0, 30, 30), rect(5, 5, 25, 25, true)});
  const Region2d island = Region2d::fromLoops({rect(10, 10, 20, 20)});
  const std::vector<std::pair<Region2d, Region2d>> cases = {
      {Region2d::fromLoops({rect(0, 0, 10, 10)}), Region2d::fromLoops({rect(4, -1, 6, 11)})},
      {frame.unite(island), Region2d::fromLoops({rect(14, -1, 16, 12)})},
      {frame.unite(island), Region2d::fromLoops({rect(14, 12, 16, 31)})},
      // The cut leaves two squares touching at one corner.
      {Region2d::fromLoops({rect(0, 0, 10, 10)}),
       Region2d::fromLoops({rect(5, 0, 10, 5), rect(0, 5, 5, 10)})},
      {Region2d::fromLoops({rect(0, 0, 10, 10)}), Region2d()},
      {Region2d(), Region2d::fromLoops({rect(0, 0, 10, 10)})},
  };
  for (size_t k = 0; k < cases.size(); ++k) {
    const std::vector<Region2d> fast = cases[k].first.subtractComponents(cases[k].second);
    const std::vector<Region2d> slow = cases[k].first.subtract(cases[k].second).components();
    ASSERT_EQ(fast.size(), slow.size()) << "case " << k;
    for (size_t i = 0; i < fast.size(); ++i) EXPECT_EQ(fast[i].paths(), slow[i].paths()) << "case " << k;
  }
}

TEST(Region2d, BooleanAreas) {
  const Region2d a = Region2d::fromLoops({rect(0, 0, 10, 10)});
  const Region2d b = Region2d::fromLoops({rect(5, 5, 15, 15)});
  EXPECT_NEAR(a.unite(b).area(), 175.0, kTiny);
  EXPECT_NEAR(a.intersect(b).area(), 25.0, kTiny);
  EXPECT_NEAR(a.subtract(b).area(), 75.0, kTiny);
  EXPECT_NEAR(b.subtract(a).area(), 75.0, kTiny);
  // Subtracting a region strictly inside makes a hole; intersecting with a disjoint one
  // leaves nothing.
  const Region2d holed = a.subtract(Region2d::fromLoops({rect(1, 1, 2, 3)}));
  EXPECT_NEAR(holed.area(), 98.0, kTiny);
  EXPECT_EQ(holed.holeCount(), 1);
  EXPECT_TRUE(a.intersect(Region2d::fromLoops({rect(20, 20, 21, 21)})).empty());
  EXPECT_NEAR(Region2d::uniteAll({a, b, Region2d::fromLoops({rect(20, 0, 21, 1)})}).area(), 176.0, kTiny);
}

TEST(Region2d, UniteAllOfManyOnEveryCoreIsTheUnion) {
  // 37 squares in a staircase (18 pairs at the first level: united on every core), and
  // every fourth apart from the rest: the union's area is known, its pieces are counted,
  // and two runs give the same loops to the unit.
  std::vector<Region2d> squares;
  double area = 0;
  for (int k = 0; k < 37; ++k) {
    const double x = k + (k / 4) * 20.0;  // a gap of 20 after every four
    squares.push_back(Region2d::fromLoops({rect(x, k, x + 2, k + 2)}));
  }
  // Each run of four overlapping 2 x 2 squares, one unit apart: 4 x 4 less the overlaps.
  for (int run = 0; run < 37; run += 4) {
    const int n = std::min(4, 37 - run);
    area += 4.0 * n - (n - 1) * 1.0;
  }
  const Region2d all = Region2d::uniteAll(squares);
  EXPECT_NEAR(all.area(), area, kTiny);
  EXPECT_EQ(all.components().size(), 10u);
  const std::vector<Loop> first = all.loops(), again = Region2d::uniteAll(squares).loops();
  ASSERT_EQ(first.size(), again.size());
  for (size_t k = 0; k < again.size(); ++k) {
    ASSERT_EQ(first[k].size(), again[k].size());
    for (size_t i = 0; i < again[k].size(); ++i) {
      EXPECT_EQ(first[k][i].x, again[k][i].x);
      EXPECT_EQ(first[k][i].y, again[k][i].y);
    }
  }
}

TEST(Region2d, ErodedSquareKeepsSharpCorners) {
  const double a = 10, d = 1.5;
  const Region2d r = Region2d::fromLoops({rect(0, 0, a, a)}).offset(-d);
  // Rounding each vertex to 1e-5 mm moves an edge by at most that much.
  EXPECT_NEAR(r.area(), (a - 2 * d) * (a - 2 * d), 4 * a * 1e-5);
  const Box2 b = r.bounds();
  EXPECT_NEAR(b.min.x, d, 1e-5);
  EXPECT_NEAR(b.max.y, a - d, 1e-5);
  // Eroding by more than half the side leaves nothing.
  EXPECT_TRUE(Region2d::fromLoops({rect(0, 0, a, a)}).offset(-a / 2 - 0.1).empty());
}

TEST(Region2d, GrownSquareHasRoundCorners) {
  const double a = 10, d = 2;
  const Region2d r = Region2d::fromLoops({rect(0, 0, a, a)}).offset(d);
  const double expected = a * a + 4 * a * d + M_PI * d * d;
  EXPECT_NEAR(r.area(), expected, 1e-3 * expected);
  // The corner arcs are polygons inscribed in the true arcs: never more than the exact area.
  EXPECT_LE(r.area(), expected + 1e-6);
  // With square corners the area would be (a + 2d)²: the rounding must show.
  EXPECT_LT(r.area(), (a + 2 * d) * (a + 2 * d) - 0.5 * (4 - M_PI) * d * d);
  const Box2 b = r.bounds();
  EXPECT_NEAR(b.min.x, -d, 1e-5);
  EXPECT_NEAR(b.max.x, a + d, 1e-5);
}

// A slot grown with square corners where they miss the paper: the paper less it is the
// paper less the slot grown with every corner round, to the unit, and a corner beyond the
// paper is one vertex.
TEST(Region2d, SlotsGrownSquareOffThePaperCutItAsGrownRound) {
  const double neck = 0.17;
  const Region2d paper = Region2d::fromLoops({rect(0, 0, 30, 20), rect(8, 6, 14, 12)})
                             .subtract(Region2d::fromLoops({{{18, 21}, {20, 10}, {22, 21}}}))
                             .offset(-neck);
  const Region2d everywhere = Region2d::fromLoops({rect(-100, -100, 100, 100)});  // no corner squared
  // Alone, far from the paper, all four corners square: the rectangle grown by the neck.
  const Region2d far = Region2d::fromLoops({rect(40, 0, 40.5, 5)});
  const Region2d farGrown = far.grownSquareOff(neck, paper);
  ASSERT_EQ(farGrown.paths().size(), 1u);
  EXPECT_EQ(farGrown.paths().front().size(), 4u);
  EXPECT_NEAR(farGrown.area(), (0.5 + 2 * neck) * (5 + 2 * neck), 1e-6);
  std::mt19937 random(23);
  std::uniform_real_distribution<double> at(-2, 32), length(0.5, 15);
  int squared = 0, round = 0;
  for (int i = 0; i < 300; ++i) {
    const double x = at(random), y = at(random) * 0.7, w = 0.5;
    const Region2d slot = Region2d::fromLoops({rect(x - w / 2, y, x + w / 2, y + length(random))});
    const Region2d grown = slot.grownSquareOff(neck, paper), roundly = slot.grownSquareOff(neck, everywhere);
    const Region2d a = paper.subtract(grown), b = paper.subtract(roundly);
    EXPECT_EQ(a.paths(), b.paths()) << "slot at " << x << ", " << y;
    EXPECT_TRUE(a.subtract(b).empty() && b.subtract(a).empty());
    // The grown slot covers the round one, and the corners it squared are each a vertex.
    EXPECT_TRUE(roundly.subtract(grown).empty());
    const size_t cut = roundly.paths().front().size() - grown.paths().front().size();
    cut > 0 ? ++squared : ++round;
  }
  EXPECT_GT(squared, 100);  // slots reaching out of the paper, or lying beside it
  EXPECT_GT(round, 20);     // slots wholly inside it
  // Not one rectangle (a slot with a round end): grown as offset grows it.
  const Region2d roundEnd = Region2d::fromLoops({{{40, 0}, {41, 0}, {41, 3}, {40.5, 3.5}, {40, 3}}});
  EXPECT_EQ(roundEnd.grownSquareOff(neck, paper).paths(), roundEnd.offset(neck).paths());
}

// A slot's round corners (SlotCutter::kNeckArcTolerance: 10 µm) are chords tangent to the
// true arcs: the grown slot covers every point within the neck of the slot, and reaches no
// further than the tolerance beyond it; a corner takes fewer vertices than at 1 µm.
TEST(Region2d, SlotsGrownRoundCoverTheNeckWithinTheirTolerance) {
  const Region2d everywhere = Region2d::fromLoops({rect(-100, -100, 100, 100)});
  const double x0 = 5, y0 = 8, x1 = 5.5, y1 = 12;
  const Region2d slot = Region2d::fromLoops({rect(x0, y0, x1, y1)});
  for (const double neck : {0.11, 0.17, 0.4}) {
    for (const double tolerance : {0.001, 0.01}) {
      const Region2d grown = slot.grownSquareOff(neck, everywhere, tolerance);
      for (int d = 0; d < 360; ++d) {
        const double t = d * M_PI / 180, cx = std::cos(t) > 0 ? x1 : x0, cy = std::sin(t) > 0 ? y1 : y0;
        EXPECT_TRUE(grown.contains({cx + neck * std::cos(t), cy + neck * std::sin(t)})) << neck << " " << d;
      }
      // offset's chords (1 µm) cut up to 2.25 µm inside its arcs (its last step may be half
      // a step longer): 2.5 µm more.
      EXPECT_TRUE(grown.subtract(slot.offset(neck + tolerance + 0.0025)).empty()) << neck << " " << tolerance;
    }
    EXPECT_LT(slot.grownSquareOff(neck, everywhere, 0.01).paths().front().size(),
              slot.grownSquareOff(neck, everywhere, 0.001).paths().front().size());
  }
}

TEST(Region2d, IntervalsOnVerticalLineThroughHole) {
  // Square [0,10]² with a hole [3,7] x [4,6.5].
  const Region2d r = Region2d::fromLoops({rect(0, 0, 10, 10), rect(3, 4, 7, 6.5)});
  const std::vector<Interval> iv = r.intervalsOnLine({5, 0}, {0, 1});
  ASSERT_EQ(iv.size(), 2u);
  EXPECT_DOUBLE_EQ(iv[0].lo, 0.0);
  EXPECT_DOUBLE_EQ(iv[0].hi, 4.0);
  EXPECT_DOUBLE_EQ(iv[1].lo, 6.5);
  EXPECT_DOUBLE_EQ(iv[1].hi, 10.0);
  // t is measured from `point`: moving it down by 3 shifts every interval by 3.
  const std::vector<Interval> shifted = r.intervalsOnLine({5, -3}, {0, 1});
  ASSERT_EQ(shifted.size(), 2u);
  EXPECT_DOUBLE_EQ(shifted[0].lo, 3.0);
  EXPECT_DOUBLE_EQ(shifted[1].hi, 13.0);
  // A line beside the hole crosses the square once; a line outside not at all.
  const std::vector<Interval> beside = r.intervalsOnLine({1.25, 0}, {0, 1});
  ASSERT_EQ(beside.size(), 1u);
  EXPECT_DOUBLE_EQ(beside[0].lo, 0.0);
  EXPECT_DOUBLE_EQ(beside[0].hi, 10.0);
  EXPECT_TRUE(r.intervalsOnLine({11, 0}, {0, 1}).empty());
  // A horizontal line through the hole.
  const std::vector<Interval> across = r.intervalsOnLine({0, 5}, {1, 0});
  ASSERT_EQ(across.size(), 2u);
  EXPECT_DOUBLE_EQ(across[0].hi, 3.0);
  EXPECT_DOUBLE_EQ(across[1].lo, 7.0);
}

TEST(Region2d, IntervalsOnLineThroughVertices) {
  // A diamond with vertices on the axes: the vertical line x = 0 runs through two vertices,
  // which must be counted once each.
  const Region2d r = Region2d::fromLoops({{{0, -2}, {3, 0}, {0, 2}, {-3, 0}}});
  const std::vector<Interval> iv = r.intervalsOnLine({0, 0}, {0, 1});
  ASSERT_EQ(iv.size(), 1u);
  EXPECT_DOUBLE_EQ(iv[0].lo, -2.0);
  EXPECT_DOUBLE_EQ(iv[0].hi, 2.0);
}

// All lines in one pass give what each line alone gives, to the bit: through vertices, along
// edges, outside, unsorted and twice the same line, on a region with a hole, an island and
// irregular edges.
TEST(Region2d, IntervalsOnVerticalLinesAreEachLinesToTheBit) {
  const Region2d r = Region2d::fromLoops({{{0, -2}, {3, 0}, {7.3, 0.4}, {9.1, 6.7}, {4, 5}, {0, 2}, {-3, 0}},
                                          rect(4, 1, 6, 3, true),
                                          rect(4.5, 1.5, 5.5, 2.5)},
                                         FillRule::NonZero);
  std::vector<double> xs{5, 0, -3, 3, 9.1, 9.2, -4, 4, 4.5, 5, 7.3};
  for (int k = 0; k < 200; ++k) xs.push_back(-3.5 + 0.0637 * k);
  const std::vector<std::vector<Interval>> all = r.intervalsOnVerticalLines(xs);
  ASSERT_EQ(all.size(), xs.size());
  int crossed = 0;
  for (size_t k = 0; k < xs.size(); ++k) {
    const std::vector<Interval> one = r.intervalsOnLine({xs[k], 0}, {0, 1});
    ASSERT_EQ(all[k].size(), one.size()) << "x = " << xs[k];
    for (size_t i = 0; i < one.size(); ++i) {
      EXPECT_EQ(all[k][i].lo, one[i].lo) << "x = " << xs[k];
      EXPECT_EQ(all[k][i].hi, one[i].hi) << "x = " << xs[k];
    }
    crossed += one.size() > 1;  // through the hole: two intervals, or three past the island
  }
  EXPECT_GT(crossed, 10);
  EXPECT_TRUE(all[6].empty());  // x = -4 misses the region
}

// Distance from p to the region's boundary.
double toBoundary(const Region2d& r, Vec2 p) {
  double best = HUGE_VAL;
  for (const Loop& loop : r.loops())
    for (size_t i = 0; i < loop.size(); ++i) {
      const Vec2 a = loop[i], b = loop[(i + 1) % loop.size()];
      const double dx = b.x - a.x, dy = b.y - a.y, len2 = dx * dx + dy * dy;
      const double t = len2 > 0 ? std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / len2, 0.0, 1.0) : 0.0;
      best = std::min(best, std::hypot(a.x + t * dx - p.x, a.y + t * dy - p.y));
    }
  return best;
}

double lengthOf(const std::vector<Interval>& iv) {
  double sum = 0;
  for (const Interval& i : iv) sum += i.hi - i.lo;
  return sum;
}

// The erosion met on the lines is the erosion's: every point of the region more than d from
// its boundary is in it and no other (sampled along every line), and its ends lie d from the
// boundary. Clipper's offset(-d) on the same lines agrees but for its chords (1 µm inside
// the true arcs), which tell most where a line grazes an arc.
TEST(Region2d, ErodedOnVerticalLinesIsTheErosion) {
  // The region of IntervalsOnVerticalLinesAreEachLinesToTheBit three times as large.
  std::vector<Loop> loops{{{0, -2}, {3, 0}, {7.3, 0.4}, {9.1, 6.7}, {4, 5}, {0, 2}, {-3, 0}},
                          rect(4, 1, 6, 3, true),
                          rect(4.5, 1.5, 5.5, 2.5)};
  for (Loop& loop : loops)
    for (Vec2& p : loop) p = {3 * p.x, 3 * p.y};
  const Region2d r = Region2d::fromLoops(loops, FillRule::NonZero);
  std::vector<double> xs{12, 15, 27.3, -12, 9};
  for (int k = 0; k < 200; ++k) xs.push_back(-10.5 + 0.191 * k);
  const std::vector<std::vector<Interval>> full = r.intervalsOnVerticalLines(xs);
  for (const double d : {0.3, 0.8, 2.25}) {
    const std::vector<std::vector<Interval>> eroded = erodedOnVerticalLines(r, xs, full, d);
    const std::vector<std::vector<Interval>> clipper = r.offset(-d).intervalsOnVerticalLines(xs);
    ASSERT_EQ(eroded.size(), xs.size());
    int lost = 0, split = 0;
    double apart = 0, total = 0;
    for (size_t k = 0; k < xs.size(); ++k) {
      for (const Interval& i : eroded[k]) {
        EXPECT_LT(i.lo, i.hi);
        EXPECT_NEAR(toBoundary(r, {xs[k], i.lo}), d, 1e-6) << "x = " << xs[k] << ", d = " << d;
        EXPECT_NEAR(toBoundary(r, {xs[k], i.hi}), d, 1e-6) << "x = " << xs[k] << ", d = " << d;
      }
      for (const Interval& w : full[k])
        for (int s = 0; s <= 100; ++s) {
          const Vec2 p{xs[k], w.lo + (w.hi - w.lo) * s / 100};
          const double dist = toBoundary(r, p);
          if (std::abs(dist - d) < 1e-6) continue;
          const bool in = std::any_of(eroded[k].begin(), eroded[k].end(),
                                      [&](const Interval& i) { return i.lo <= p.y && p.y <= i.hi; });
          EXPECT_EQ(in, dist > d) << "x = " << p.x << ", y = " << p.y << ", d = " << d;
        }
      lost += lengthOf(eroded[k]) < lengthOf(full[k]) - 2 * d + 1e-9;
      split += eroded[k].size() > full[k].size();
      // What one holds and the other does not.
      const double both = lengthOf(intersectIntervals(eroded[k], clipper[k]));
      apart += lengthOf(eroded[k]) + lengthOf(clipper[k]) - 2 * both;
      total += lengthOf(eroded[k]);
    }
    EXPECT_GT(lost, 10) << "d = " << d;  // corners and edges aslant take more than d at each end
    EXPECT_GT(total, 0) << "d = " << d;
    EXPECT_LT(apart, 1e-3 * total) << "d = " << d;
    if (d < 1) EXPECT_GT(split, 1) << "d = " << d;  // beside the hole's walls
  }
}

TEST(Region2d, HoleCount) {
  const Region2d two = Region2d::fromLoops({rect(0, 0, 10, 4), rect(1, 1, 3, 3), rect(6, 1, 8, 3)});
  EXPECT_EQ(two.holeCount(), 2);
  EXPECT_NEAR(two.area(), 40.0 - 8.0, kTiny);
  const Region2d filled = two.unite(Region2d::fromLoops({rect(0.5, 0.5, 3.5, 3.5)}));
  EXPECT_EQ(filled.holeCount(), 1);
  EXPECT_EQ(Region2d::fromLoops({rect(0, 0, 1, 1)}).holeCount(), 0);
}

TEST(Region2d, FillRulesOnOverlappingSquares) {
  // Two counter-clockwise squares overlapping in [5,10]²: non-zero fills the overlap
  // (winding 2), even-odd leaves it out.
  const std::vector<Loop> loops{rect(0, 0, 10, 10), rect(5, 5, 15, 15)};
  EXPECT_NEAR(Region2d::fromLoops(loops, FillRule::NonZero).area(), 175.0, kTiny);
  EXPECT_NEAR(Region2d::fromLoops(loops, FillRule::EvenOdd).area(), 150.0, kTiny);
  // Opposite orientations: winding 0 in the overlap for both rules.
  const std::vector<Loop> opposite{rect(0, 0, 10, 10), rect(5, 5, 15, 15, true)};
  EXPECT_NEAR(Region2d::fromLoops(opposite, FillRule::NonZero).area(), 150.0, kTiny);
}

TEST(Region2d, CoordinatesOutOfRangeAreRejected) {
  for (double bad : {double(NAN), double(INFINITY), 1e20}) {
    try {
      Region2d::fromLoops({{{0, 0}, {bad, 0}, {0, 1}}});
      ADD_FAILURE() << "no error for coordinate " << bad;
    } catch (const Error& e) {
      EXPECT_EQ(e.kind(), ErrorKind::BadInput);
    }
  }
  // Loops of fewer than three points enclose nothing.
  EXPECT_TRUE(Region2d::fromLoops({{{0, 0}, {1, 1}}}).empty());
}

// What the label placers and the slot cutter ask of the region (they use no Clipper).
TEST(Region2d, PointSegmentAndBoxQueries) {
  const Region2d r = Region2d::fromLoops({rect(0, 0, 10, 10), rect(3, 3, 7, 7)});
  EXPECT_TRUE(r.contains({1, 1}));
  EXPECT_TRUE(r.contains({0, 5}));  // on the boundary
  EXPECT_FALSE(r.contains({5, 5}));
  EXPECT_FALSE(r.contains({11, 1}));
  EXPECT_TRUE(r.containsSegment({1, 1}, {1, 9}, 1e-3));
  EXPECT_FALSE(r.containsSegment({1, 5}, {9, 5}, 1e-3));
  // A 2 x 2 box fits with its centre in [1, 9]² outside (2, 8)²; one box rules out [1, 2]².
  const Box2 window{{-5, -5}, {15, 15}, false};
  EXPECT_NEAR(r.boxCentres({1, 1}, window, {}).area(), 28.0, 1e-6);
  EXPECT_NEAR(r.boxCentres({1, 1}, window, {{{0, 0}, {2, 2}, false}}).area(), 27.0, 1e-6);
  // Coarse round corners are chords inside the true arcs: the hole grows a little less.
  const double coarse = r.coarseOffset(-1, 0.02).area(), fine = r.offset(-1).area();
  EXPECT_NEAR(fine, 64.0 - (16.0 + 16.0 + M_PI), 0.01);
  EXPECT_GT(coarse, fine);
  EXPECT_LT(coarse, fine + 0.1);
  EXPECT_EQ(r.simplified(0.02).area(), r.area());
}

TEST(Region2d, RawComponentsAndUnionAtOnce) {
  const Region2d two = Region2d::uniteAtOnce(
      {Region2d::fromLoops({rect(0, 0, 4, 2)}), Region2d::fromLoops({rect(3, 0, 8, 2)})});
  EXPECT_NEAR(two.area(), 16.0, kTiny);
  const Region2d strip = Region2d::fromLoops({rect(4, -1, 5, 3)});
  const std::vector<Region2d> raw = two.subtractComponentsRaw(strip), clean = two.subtractComponents(strip);
  ASSERT_EQ(raw.size(), 2u);
  ASSERT_EQ(clean.size(), 2u);
  // In whatever order each sweep found them (the raw one's is turned a quarter).
  std::vector<double> rawAreas, cleanAreas;
  for (size_t i = 0; i < 2; ++i) rawAreas.push_back(raw[i].area()), cleanAreas.push_back(clean[i].area());
  std::sort(rawAreas.begin(), rawAreas.end());
  std::sort(cleanAreas.begin(), cleanAreas.end());
  for (size_t i = 0; i < 2; ++i) EXPECT_NEAR(rawAreas[i], cleanAreas[i], kTiny);
}

// The raw pieces are swept turned a quarter (slots along y leave Clipper's active list
// short) and turned back: the same pieces, where they were, outer loop first and
// counterclockwise, each hole clockwise.
TEST(Region2d, RawComponentsLieWhereTheShapeIs) {
  const Region2d shape = Region2d::fromLoops({rect(1, 2, 21, 9), rect(15, 4, 17, 6)});
  std::vector<Region2d::Loop> slots;
  for (int k = 0; k < 4; ++k) slots.push_back(rect(4 + 3 * k, k % 2 ? 5 : 1, 4.5 + 3 * k, k % 2 ? 10 : 6));
  const Region2d cut = Region2d::fromLoops(slots);
  const std::vector<Region2d> raw = shape.subtractComponentsRaw(cut), clean = shape.subtractComponents(cut);
  ASSERT_EQ(raw.size(), clean.size());
  double total = 0;
  for (const Region2d& piece : raw) {
    const Box2 box = piece.bounds();
    const auto same = std::find_if(clean.begin(), clean.end(), [&](const Region2d& c) {
      const Box2 b = c.bounds();
      return std::abs(b.min.x - box.min.x) < kTiny && std::abs(b.min.y - box.min.y) < kTiny &&
             std::abs(b.max.x - box.max.x) < kTiny && std::abs(b.max.y - box.max.y) < kTiny &&
             std::abs(c.area() - piece.area()) < kTiny;
    });
    EXPECT_NE(same, clean.end());
    const std::vector<Region2d::Loop> loops = piece.loops();
    EXPECT_GT(Region2d::signedArea(loops.front()), 0);
    for (size_t k = 1; k < loops.size(); ++k) EXPECT_LT(Region2d::signedArea(loops[k]), 0);
    total += piece.area();
  }
  EXPECT_NEAR(total, shape.subtract(cut).area(), kTiny);
}

// A segment away from every edge is decided without a Boolean: it must answer as one would
// (inside all along, or a piece outside longer than the slack).
TEST(Region2d, SegmentsInsideAgreeWithSamples) {
  // A square with a hole and a notch cut into its top.
  const Region2d r = Region2d::fromLoops({rect(0, 0, 10, 10), rect(3, 3, 7, 7)})
                         .subtract(Region2d::fromLoops({{{4, 10.5}, {5, 8}, {6, 10.5}}}));
  EXPECT_TRUE(r.containsSegment({1, 1}, {1, 0}, 1e-3));           // ends on the boundary
  EXPECT_FALSE(r.containsSegment({4, 4}, {6, 6}, 1e-3));          // in the hole
  EXPECT_FALSE(r.containsSegment({3.5, 9.5}, {6.5, 9.5}, 1e-3));  // across the notch
  EXPECT_TRUE(r.containsSegment({11, 1}, {11, 1.0005}, 1e-3));    // outside, shorter than the slack
  EXPECT_FALSE(r.containsSegment({11, 1}, {11, 2}, 1e-3));
  std::mt19937 random(41);
  std::uniform_real_distribution<double> at(-1, 11);
  int inside = 0, outside = 0;
  for (int i = 0; i < 400; ++i) {
    const Vec2 a{at(random), at(random)}, b{at(random), at(random)};
    // Points every 5 µm along it. A segment with one or two of them outside is left out:
    // what it has outside may be shorter than the slack.
    const int n = static_cast<int>(std::hypot(b.x - a.x, b.y - a.y) / 0.005) + 1;
    int in = 0;
    for (int k = 0; k <= n; ++k) in += r.contains({a.x + (b.x - a.x) * k / n, a.y + (b.y - a.y) * k / n});
    if (in == n + 1) {
      ++inside;
      EXPECT_TRUE(r.containsSegment(a, b, 1e-3)) << a.x << "," << a.y << " " << b.x << "," << b.y;
    } else if (n + 1 - in > 2) {
      ++outside;
      EXPECT_FALSE(r.containsSegment(a, b, 1e-3)) << a.x << "," << a.y << " " << b.x << "," << b.y;
    }
  }
  EXPECT_GT(inside, 20);
  EXPECT_GT(outside, 200);
}

// BoxRoom answers as boxCentres does, to the unit, whether it works the answer out or
// remembers it.
// A plate with a hole, cut along x = 4 and x = 6.5 by a Boolean with a strip between them:
// the pieces' stretches on those lines are where the cut left them, and only there (not on
// the plate's own sides at x = 0 and 10, which are not asked for, nor on lines off the cut).
TEST(Region2d, StretchesOnTheLinesACutLeaves) {
  const Region2d plate = Region2d::fromLoops({rect(0, 0, 10, 8), rect(5, 2, 8, 5, true)});
  const Region2d strip = Region2d::fromLoops({rect(4, -1, 6.5, 9)});
  std::vector<Region2d::Stretch> found;
  for (const Region2d& piece : plate.subtractComponentsRaw(strip))
    for (const Region2d::Stretch& s : piece.stretchesOn({4, 6.5})) found.push_back(s);
  ASSERT_EQ(found.size(), 3u);
  std::sort(found.begin(), found.end(),
            [](const auto& a, const auto& b) { return a.x != b.x ? a.x < b.x : a.y.lo < b.y.lo; });
  EXPECT_EQ(found[0].x, 4);  // the left piece's side, the plate's full height
  EXPECT_NEAR(found[0].y.lo, 0, 1e-9);
  EXPECT_NEAR(found[0].y.hi, 8, 1e-9);
  EXPECT_EQ(found[1].x, 6.5);  // the right piece's side, below the hole and above it
  EXPECT_NEAR(found[1].y.hi, 2, 1e-9);
  EXPECT_NEAR(found[2].y.lo, 5, 1e-9);
  EXPECT_TRUE(plate.stretchesOn({4.00001, 6.5}).empty());
  EXPECT_EQ(plate.stretchesOn({0, 10}).size(), 2u);
}

TEST(Region2d, BoxRoomAnswersAsBoxCentres) {
  const Region2d r = Region2d::fromLoops({rect(0, 0, 30, 20), rect(8, 6, 14, 12)})
                         .subtract(Region2d::fromLoops({{{18, 21}, {20, 10}, {22, 21}}}));
  const BoxRoom room(r);
  std::mt19937 random(17);
  std::uniform_real_distribution<double> at(-2, 32), size(0.2, 4);
  int empty = 0, some = 0;
  for (int i = 0; i < 300; ++i) {
    const Vec2 half{size(random), size(random)}, c{at(random), at(random)};
    const Box2 window{{c.x - 3 * half.x, c.y - 3 * half.y}, {c.x + 3 * half.x, c.y + 3 * half.y}, false};
    std::vector<Box2> avoid;
    for (int k = i % 4; k > 0; --k) {
      const Vec2 o{at(random), at(random)};
      avoid.push_back({{o.x - 2, o.y - 2}, {o.x + 2, o.y + 2}, false});
    }
    const Region2d expected = r.boxCentres(half, window, avoid);
    for (int ask = 0; ask < 2; ++ask)
      EXPECT_EQ(room.boxCentres(half, window, avoid).paths(), expected.paths());
    expected.empty() ? ++empty : ++some;
  }
  EXPECT_GT(empty, 50);
  EXPECT_GT(some, 50);
}

// RoomGrid never calls a question empty that has room, on shapes with narrow teeth, thin
// rings and holes, small and large (its cells grow with the shape); and it does rule out
// most questions without room, or it saves nothing.
TEST(Region2d, RoomGridRulesOutOnlyQuestionsWithoutRoom) {
  std::vector<Loop> comb{rect(0, 0, 40, 4)};
  for (int k = 0; k < 16; ++k) comb.push_back(rect(1 + 2.3 * k, 3, 2.5 + 2.3 * k, 14 + k % 5));
  Loop outer, inner;
  for (int k = 0; k < 90; ++k) {
    const double a = 2 * M_PI * k / 90;
    outer.push_back({150 + 140 * std::cos(a), 150 + 140 * std::sin(a)});
    inner.push_back({150 + 137.5 * std::cos(a), 150 + 137.5 * std::sin(a)});
  }
  std::reverse(inner.begin(), inner.end());
  const Region2d shapes[] = {
      Region2d::fromLoops(comb, FillRule::NonZero),
      Region2d::fromLoops({outer, inner, rect(60, 60, 240, 70), rect(100, 100, 200, 200)}),
      Region2d::fromLoops({rect(0, 0, 30, 20), rect(8, 6, 14, 12)})
          .subtract(Region2d::fromLoops({{{18, 21}, {20, 10}, {22, 21}}}))};
  std::mt19937 random(29);
  int empty = 0, ruledOut = 0;
  for (const Region2d& r : shapes) {
    const RoomGrid grid(r.paths());
    const Box2 b = r.bounds();
    std::uniform_real_distribution<double> x(b.min.x - 2, b.max.x + 2), y(b.min.y - 2, b.max.y + 2),
        size(0.3, 3), reach(0.5, 20), tight(0.6, 0.8);
    for (int i = 0; i < 800; ++i) {
      // Half the questions a box that barely fits a tooth or the ring, or barely does not
      // (teeth 1.5 mm wide, the ring 2.5 mm): where a careless grid goes wrong.
      const double t = tight(random);
      const Vec2 half = i % 2 ? Vec2{size(random), size(random)} : Vec2{t, 1.66 * t};
      const Vec2 c{x(random), y(random)};
      const double wx = reach(random), wy = reach(random);
      const Box2 window{{c.x - wx, c.y - wy}, {c.x + wx, c.y + wy}, false};
      std::vector<Box2> avoid;
      std::vector<ClipperLib::cInt> units;
      for (int k = i % 3; k > 0; --k) {
        const Vec2 o{c.x + reach(random) - 10, c.y + reach(random) - 10};
        avoid.push_back({{o.x - 3, o.y - 3}, {o.x + 3, o.y + 3}, false});
        for (const double v : {o.x - 3, o.y - 3, o.x + 3, o.y + 3}) units.push_back(Region2d::toUnits(v));
      }
      const bool may =
          grid.mayHold(Region2d::toUnits(half.x), Region2d::toUnits(half.y), Region2d::toUnits(window.min.x),
                       Region2d::toUnits(window.min.y), Region2d::toUnits(window.max.x),
                       Region2d::toUnits(window.max.y), units.data(), avoid.size());
      const bool room = !r.boxCentres(half, window, avoid).empty();
      EXPECT_TRUE(may || !room) << "half " << half.x << " x " << half.y << " about " << c.x << ", " << c.y;
      if (!room) ++empty, ruledOut += !may;
    }
  }
  EXPECT_GT(empty, 600);
  EXPECT_GT(ruledOut, empty * 6 / 10);
}

}  // namespace
}  // namespace sliceform
