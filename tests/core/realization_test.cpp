// SPDX-License-Identifier: LGPL-2.1-or-later
// Paper realization (§5): slot geometry, the interlock test of Prop. 3, and Alg. 3's
// repairs, on hand-made patches and on arranged solids.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <random>

#include "arrangement/arrange.hpp"
#include "frames/hinge_table.hpp"
#include "model/model.hpp"
#include "realization/interlock.hpp"
#include "realization/patch_states.hpp"
#include "realization/realize.hpp"
#include "support/bounded_cache.hpp"
#include "test_support.hpp"

namespace sliceform {
namespace {

using test::makeHollowSphere;
using test::makeTorus;

Region2d::Loop circle(double cx, double cy, double r, bool clockwise = false) {
  Region2d::Loop out;
  const int n = 180;
  for (int k = 0; k < n; ++k) {
    const double t = 2 * M_PI * (clockwise ? n - k : k) / n;
    out.push_back({cx + r * std::cos(t), cy + r * std::sin(t)});
  }
  return out;
}

Region2d annulus(double cx, double cy, double inner, double outer) {
  return Region2d::fromLoops({circle(cx, cy, outer), circle(cx, cy, inner)}, FillRule::EvenOdd);
}

Region2d rect(double x0, double y0, double x1, double y1) {
  return Region2d::fromLoops({{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}});
}

// A hand-made realization input: U-patches and V-patches given by shape and position,
// with every hinge segment found on the common lines (all of them holding).
RealizationInput handMade(const std::vector<PatchShape>& patches) {
  RealizationInput in;
  in.frames = {makeSliceFrame({1, 0, 0}, {0, 0, 1}), makeSliceFrame({0, 1, 0}, {0, 0, 1})};
  in.patches = patches;
  for (int a = 0; a < static_cast<int>(patches.size()); ++a) {
    if (patches[a].family != Family::U) continue;
    for (int b = 0; b < static_cast<int>(patches.size()); ++b) {
      if (patches[b].family != Family::V) continue;
      const double xa = lineX(in.frames.u, in.frames.v, patches[b].position);
      const double xb = lineX(in.frames.v, in.frames.u, patches[a].position);
      for (const Interval& w : intersectIntervals(patches[a].shape.intervalsOnLine({xa, 0}, {0, 1}),
                                                  patches[b].shape.intervalsOnLine({xb, 0}, {0, 1})))
        in.hinges.push_back({a, b, w, true, w});
    }
  }
  return in;
}

// SlotCutter erodes the shape once and takes the grown slots from it, instead of eroding
// each slotted shape: its piece count must be the one eroding the slotted shape gives, also
// for bridges of paper around the neck width, under a slot and between a slot and a hole.
// A bridge of exactly two necks under a square-ended slot leaves the eroded paper touching
// the grown slot along a line, where either count is right (SlotCutter::openedPieces: a
// bridge within microns of the neck may count either way): there it is one piece or two.
TEST(Slots, CutterCountsPiecesAsErodingTheSlottedShape) {
  SlotParams params;  // neck 0.15 mm with no tolerance: bridges under 0.3 mm are cut
  const double neck = 0.15, crumb = 0.5;
  const Region2d plain = rect(0, 0, 20, 10);
  const Region2d holed = plain.subtract(Region2d::fromLoops({circle(10, 3, 2)}));
  for (const SlotEnd end : {SlotEnd::Square, SlotEnd::Round})
    for (const Region2d* shape : {&plain, &holed})
      for (int k = 0; k <= 20; ++k) {
        const double bridge = 0.2 + 0.01 * k;  // paper left under the slot
        const double root = (shape == &plain ? 0 : 5) + bridge;
        params.end = end;
        const std::vector<SlotCut> cuts = {{10, {root, 11}, false, true}, {4, {-1, 6}, true, false}};
        const SlotCutter cutter(*shape, params, 0);
        int pieces = 0;
        const Region2d out = cutter.cut(slotRegion(cuts, params), &pieces);
        const int expected =
            std::max(static_cast<int>(out.components().size()),
                     openedPieceCountFull(out, neck, crumb) - openedPieceCountFull(*shape, neck, crumb) + 1);
        if (std::fabs(bridge - 2 * neck) < 1e-6 && shape == &plain && end == SlotEnd::Square) {
          EXPECT_TRUE(pieces == 1 || pieces == 2) << pieces;
          EXPECT_EQ(expected, 1);
        } else {
          EXPECT_EQ(pieces, expected) << "bridge " << bridge << (shape == &plain ? "" : " over a hole");
        }
        if (shape == &plain && end == SlotEnd::Square && std::fabs(bridge - 2 * neck) > 0.005)
          EXPECT_EQ(pieces, bridge < 2 * neck ? 2 : 1) << "bridge " << bridge;
      }
}

// One cutter serves every slot choice the search tries of a patch, and grows each slot
// once: whatever choices came before, and where grown slots overlap (two slots on one
// line, slots on lines closer than twice the neck), its count is the one eroding the
// slotted shape gives.
TEST(Slots, CutterGrowsEachSlotOnceForEveryChoice) {
  SlotParams params;  // neck 0.15 mm with no tolerance
  const double neck = 0.15, crumb = 0.5;
  const Region2d shape = rect(0, 0, 30, 12);
  const SlotCutter shared(shape, params, 0);
  int checked = 0, split = 0;
  for (int round = 0; round < 2; ++round)
    for (int k = 0; k <= 12; ++k) {
      const double gap = 0.05 * k;  // paper between two slots' roots on one line
      for (const double beside : {0.0, 0.2, 0.6}) {
        std::vector<SlotCut> cuts = {{8, {-1, 6 - gap / 2}, true, false},
                                     {8, {6 + gap / 2, 13}, false, true},
                                     {20, {-1, 5}, true, false}};
        if (beside > 0) cuts.push_back({20 + params.width() + beside, {4, 13}, false, true});
        int pieces = 0;
        const Region2d out = shared.cut(slotRegion(cuts, params), &pieces);
        const int expected =
            std::max(static_cast<int>(out.components().size()),
                     openedPieceCountFull(out, neck, crumb) - openedPieceCountFull(shape, neck, crumb) + 1);
        EXPECT_EQ(pieces, expected) << "gap " << gap << ", beside " << beside << ", round " << round;
        ++checked;
        split += pieces > 1;
      }
    }
  EXPECT_EQ(checked, 78);
  EXPECT_GT(split, 0);        // some choices cut the patch through...
  EXPECT_LT(split, checked);  // ...and some do not
}

// The neck test made column by column (ErodedColumns) counts the pieces that one Boolean of
// the whole patch less its grown slots gives, and finds the same small pieces: on a plate
// with a hole, a comb whose teeth the slots cut off, and a ring, for choices of slots up,
// down, through or none on each line (two on some lines, round ends on some), one cutter
// per shape serving every choice, so that its columns are made again as slots come on new
// lines (or knowing the lines from the start) and each column's paper less its slots is
// reused.
TEST(Slots, ColumnsCountAsTheWholePatch) {
  SlotParams params;
  const double neck = slotNeck(params, 0), crumb = slotCrumb(params),
               small = SlotCutter::kSliverCrumbs * crumb;
  const auto grow = [&](const Region2d& slots) {
    std::vector<Region2d> out;
    for (const Region2d& slot : slots.loopsApart()) out.push_back(slot.offset(neck));
    return out;
  };
  Region2d comb = rect(0, 0, 30, 3);
  for (int k = 0; k < 10; ++k) comb = comb.unite(rect(3 * k + 0.5, 3, 3 * k + 1.7, 12));
  const std::vector<Region2d> shapes = {rect(0, 0, 30, 12).subtract(Region2d::fromLoops({circle(15, 6, 3)})),
                                        comb, annulus(15, 6, 3, 6)};
  std::mt19937 random(17);
  const auto uniform = [&](double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(random);
  };
  int counted = 0, split = 0, withSmall = 0;
  for (const Region2d& shape : shapes) {
    const Region2d eroded = shape.offset(-neck);
    // One cutter makes its columns as slots come; the other knows the lines up front.
    const double widest = 2 * (params.width() + 2 * neck);
    std::vector<double> lines;
    for (int line = 0; line < 12; ++line) lines.push_back(1.1 + 2.4 * line);
    const double reach = neck + SlotCutter::kNeckArcTolerance;
    const ErodedColumns asTheyCome(eroded, neck, crumb, widest, reach);
    const ErodedColumns known(eroded, neck, crumb, widest, reach, lines, params.width() / 2);
    for (int trial = 0; trial < 60; ++trial) {
      params.end = trial % 3 == 0 ? SlotEnd::Round : SlotEnd::Square;
      std::vector<SlotCut> cuts;
      for (int line = 0; line < 12; ++line) {
        const double x = lines[line], root = uniform(0.5, 11.5);
        switch (std::uniform_int_distribution<int>(0, 4)(random)) {
          case 0:
            cuts.push_back({x, {root, 13}, false, true});
            break;  // up
          case 1:
            cuts.push_back({x, {-1, root}, true, false});
            break;  // down
          case 2:
            cuts.push_back({x, {-1, 13}, true, true});
            break;  // through
          case 3:
            cuts.push_back({x, {root, std::min(13.0, root + 3)}, false, root + 3 > 12});
            break;
          default:
            break;  // none
        }
        if (line % 5 == 2) cuts.push_back({x, {-1, uniform(0, 2)}, true, false});
      }
      const Region2d slots = slotStrips(cuts, params);
      std::vector<Region2d> whole;
      const int expected =
          openedPiecesLess(eroded, Region2d::overlaid(grow(slots)), neck, crumb, small, &whole);
      double b = 0;
      for (const Region2d& r : whole) b += r.area();
      for (const ErodedColumns* columns : {&asTheyCome, &known}) {
        std::vector<Region2d> inColumns;
        const std::optional<int> n = columns->less(slots, grow, small, &inColumns);
        ASSERT_TRUE(n.has_value());
        EXPECT_EQ(*n, expected) << "shape " << &shape - shapes.data() << ", trial " << trial;
        double a = 0;
        for (const Region2d& r : inColumns) a += r.area();
        EXPECT_EQ(inColumns.size(), whole.size());
        EXPECT_NEAR(a, b, 1e-6);
      }
      ++counted;
      split += expected > 1;
      withSmall += !whole.empty();
    }
  }
  EXPECT_EQ(counted, 180);
  EXPECT_GT(split, 20);
  EXPECT_LT(split, counted);
  EXPECT_GT(withSmall, 5);
}

// The search bounds a move by the cutter's neck test alone (SlotCutter::opened) and finishes
// the state from it later: the neck test never counts more pieces than cut() where it found
// no slivers, and cut() given it makes the same bits as cut() alone. The search's own cut
// (tryCut, its pieces not united again) counts as cut() does, trims where it trims, keeps
// the same paper, and paperOf() gives cut()'s very bits; inPieces() says what its count says.
// The searches give them the slots' strips overlaid (slotStrips), not united.
TEST(Slots, NeckTestBoundsTheCutsCount) {
  SlotParams params;  // neck 0.15 mm with no tolerance
  int checked = 0, bounded = 0, slivered = 0, trimmed = 0;
  const auto check = [&](const SlotCutter& cutter, const std::vector<SlotCut>& cuts,
                         const std::string& what) {
    const Region2d slots = slotRegion(cuts, params);
    const SlotCutter::Opened opened = cutter.opened(slots);
    int alone = 0, finished = 0;
    const Region2d a = cutter.cut(slots, &alone);
    const Region2d b = cutter.cut(slots, &finished, &opened);
    EXPECT_EQ(a.paths(), b.paths()) << what;
    EXPECT_EQ(alone, finished) << what;
    // The searches cut the strips overlaid, not united (slotStrips).
    const Region2d strips = slotStrips(cuts, params);
    const SlotCutter::Opened openedStrips = cutter.opened(strips);
    EXPECT_EQ(openedStrips.pieces, opened.pieces) << what;
    EXPECT_EQ(openedStrips.slivers.size(), opened.slivers.size()) << what;
    EXPECT_EQ(cutter.inPieces(strips), alone > 1) << what;
    for (const SlotCutter::Opened* known : {static_cast<const SlotCutter::Opened*>(nullptr), &openedStrips}) {
      const SlotCutter::Trial trial = cutter.tryCut(strips, known);
      EXPECT_EQ(trial.pieces, alone) << what;
      EXPECT_NEAR(trial.paper.area(), a.area(), 1e-6) << what;
      EXPECT_NEAR(trial.paper.subtract(a).area() + a.subtract(trial.paper).area(), 0, 1e-6) << what;
      EXPECT_EQ(cutter.paperOf(slots, trial.trimmed).paths(), a.paths()) << what;
      trimmed += trial.trimmed;
    }
    if (opened.slivers.empty()) {
      EXPECT_LE(opened.pieces, alone) << what;
      ++bounded;
    } else {
      ++slivered;
    }
    ++checked;
  };
  // Two slots on one line with a bridge of paper between their roots, and a slot beside.
  // Square ends, then round ones (a disc over each closed end: loops that overlap).
  const SlotCutter plain(rect(0, 0, 30, 12), params, 0);
  for (const SlotEnd end : {SlotEnd::Square, SlotEnd::Round})
    for (int k = 0; k <= 12; ++k)
      for (const double beside : {0.0, 0.2, 0.6}) {
        params.end = end;
        const double gap = 0.05 * k;
        std::vector<SlotCut> cuts = {{8, {-1, 6 - gap / 2}, true, false},
                                     {8, {6 + gap / 2, 13}, false, true},
                                     {20, {-1, 5}, true, false}};
        if (beside > 0) cuts.push_back({20 + params.width() + beside, {4, 13}, false, true});
        check(plain, cuts, "gap " + std::to_string(gap) + ", beside " + std::to_string(beside));
      }
  params.end = SlotEnd::Square;
  // A 1.2 mm tab on the right edge; a slot 0.1 mm inside that edge, up to near the tab's
  // top, leaves the tab held by a bridge of paper thinner than the neck: a sliver, which
  // cut() trims off when that leaves fewer pieces.
  const SlotCutter tabbed(rect(0, 0, 30, 12).unite(rect(30, 5, 31.2, 6.2)), params, 0);
  for (const double root : {5.0, 5.9, 6.0, 6.05, 6.1, 6.3, 7.0})
    for (const bool second : {false, true}) {
      std::vector<SlotCut> cuts = {{30 - params.width() / 2 - 0.1, {-1, root}, true, false}};
      if (second) cuts.push_back({15, {-1, 11.9}, true, false});
      check(tabbed, cuts, "root " + std::to_string(root) + (second ? ", second slot" : ""));
    }
  EXPECT_EQ(checked, 92);
  EXPECT_GT(bounded, 0);
  EXPECT_GT(slivered, 0);  // both kinds were checked
  EXPECT_GT(trimmed, 0);   // and a trial that trimmed slivers off
}

// The search keeps patch states computed for earlier moves and computes them on both
// cores; the ones it ends with must be exactly what the final slots give afresh.
void expectStatesMatchSlots(const RealizationInput& in, const Realization& r) {
  for (int p = 0; p < static_cast<int>(in.patches.size()); ++p) {
    const std::vector<SlotCut> cuts = planSlots(in.patches[p].shape, patchHinges(in, r.slots, p), r.params);
    ASSERT_EQ(cuts.size(), r.cuts[p].size()) << "patch " << p;
    for (size_t k = 0; k < cuts.size(); ++k) {
      EXPECT_EQ(cuts[k].x, r.cuts[p][k].x);
      EXPECT_EQ(cuts[k].y.lo, r.cuts[p][k].y.lo);
      EXPECT_EQ(cuts[k].y.hi, r.cuts[p][k].y.hi);
    }
    const SlotCutter cutter(in.patches[p].shape, r.params, in.tolerance);
    EXPECT_EQ(cutter.cut(slotRegion(cuts, r.params), nullptr).paths(), r.slotted[p].paths()) << "patch " << p;
  }
  // Whether the slotted patches still meet along each hinge, as docs/decisions.md defines it.
  for (size_t h = 0; h < in.hinges.size(); ++h) {
    const ScaffoldHinge& hinge = in.hinges[h];
    double covered = 0;
    for (const int p : {hinge.u, hinge.v}) {
      const bool isU = p == hinge.u;
      const double x = lineX(isU ? in.frames.u : in.frames.v, isU ? in.frames.v : in.frames.u,
                             in.patches[isU ? hinge.v : hinge.u].position);
      for (const Interval& i : intersectIntervals(r.slotted[p].intervalsOnLine({x, 0}, {0, 1}), {hinge.w}))
        covered += i.hi - i.lo;
    }
    EXPECT_EQ(r.meets[h], covered >= 0.9 * (hinge.w.hi - hinge.w.lo)) << "hinge " << h;
  }
}

// Paper Fig. 3: two rings at right angles through each other, joined where they cross.
// Slotting both joints the same way (U up, V down) leaves them linked.
TEST(Interlock, CrossedRingsAreDetectedAndRepaired) {
  const RealizationInput in =
      handMade({{Family::U, 0, annulus(0, 0, 15, 25)}, {Family::V, 0, annulus(0, 0, 15, 25)}});
  ASSERT_EQ(in.hinges.size(), 2u);
  const Realization r = realize(in, SlotParams{});
  EXPECT_GT(r.interlocks.found, 0);
  EXPECT_EQ(r.interlocks.remaining, 0);
  EXPECT_EQ(r.interlocks.repaired, r.interlocks.found);
  EXPECT_EQ(r.interlocks.cutThroughs, 0);
  EXPECT_EQ(r.splitPatches, 0);
  EXPECT_NE(r.slots[0], r.slots[1]) << "one joint slotted each way unlinks the rings";
  EXPECT_TRUE(r.assemblyChecked);
  expectStatesMatchSlots(in, r);
}

// Two rings linked without touching (Prop. 3 counts pairs that share no hinge too). No slot
// between them can help; a cut-through where a third patch crosses ring A breaks it.
TEST(Interlock, LinkedRingsNeedACutThrough) {
  const RealizationInput in = handMade({{Family::U, 0, annulus(0, 0, 20, 30)},
                                        {Family::V, 0, annulus(0, 25, 20, 30)},
                                        {Family::V, 10, rect(-5, -40, 5, 40)}});
  ASSERT_EQ(in.hinges.size(), 2u) << "A meets C twice on the line x = 10, B not at all";
  const HoleLoops a = holeLoops(in.patches[0].shape, 0), b = holeLoops(in.patches[1].shape, 0);
  EXPECT_EQ(interlockCount(a, in.frames.u, b, in.frames.v), 1);
  const Realization r = realize(in, SlotParams{});
  EXPECT_EQ(r.interlocks.found, 1);
  EXPECT_EQ(r.interlocks.remaining, 0);
  EXPECT_EQ(r.interlocks.cutThroughs, 1);
  EXPECT_EQ(r.splitPatches, 0);
  EXPECT_EQ(r.slotted[0].holeCount(), 0) << "ring A is open now";
  EXPECT_EQ(r.slotted[0].components().size(), 1u);
  expectStatesMatchSlots(in, r);
}

// The slots of one hinge: the U-patch cleared above the root, the V-patch below, each
// exactly thickness + clearance wide, and paper left where the other has its slot.
TEST(Slots, WidthIsThicknessPlusClearance) {
  const RealizationInput in =
      handMade({{Family::U, 0, rect(-20, 0, 20, 40)}, {Family::V, 5, rect(-20, 0, 20, 40)}});
  ASSERT_EQ(in.hinges.size(), 1u);
  SlotParams params;
  params.thickness = 3;  // plywood
  params.clearance = 0.15;
  const Realization r = realize(in, params);
  ASSERT_EQ(r.slots[0], SlotPair::UpDown);
  const double xu = lineX(in.frames.u, in.frames.v, 5), xv = lineX(in.frames.v, in.frames.u, 0);
  const auto gaps = [](const Region2d& region, double y) {
    const std::vector<Interval> row = region.intervalsOnLine({0, y}, {1, 0});
    std::vector<Interval> out;
    for (size_t k = 0; k + 1 < row.size(); ++k) out.push_back({row[k].hi, row[k + 1].lo});
    return out;
  };
  const auto up = gaps(r.slotted[0], 30), below = gaps(r.slotted[0], 10);
  ASSERT_EQ(up.size(), 1u);
  EXPECT_NEAR(up[0].hi - up[0].lo, 3.15, 1e-4);
  EXPECT_NEAR((up[0].lo + up[0].hi) / 2, xu, 1e-4);
  EXPECT_TRUE(below.empty());
  const auto down = gaps(r.slotted[1], 10);
  ASSERT_EQ(down.size(), 1u);
  EXPECT_NEAR(down[0].hi - down[0].lo, 3.15, 1e-4);
  EXPECT_NEAR((down[0].lo + down[0].hi) / 2, xv, 1e-4);
  EXPECT_TRUE(gaps(r.slotted[1], 30).empty());
  // The slots meet at the root, in the middle of the hinge, each kRootGap past it.
  EXPECT_NEAR(r.slotted[0].bounds().max.y, 40, 1e-6);
  const std::vector<Interval> uOnLine = r.slotted[0].intervalsOnLine({xu, 0}, {0, 1});
  ASSERT_EQ(uOnLine.size(), 1u);
  EXPECT_NEAR(uOnLine[0].hi, 20 + kRootGap, 1e-5);
  const std::vector<Interval> vOnLine = r.slotted[1].intervalsOnLine({xv, 0}, {0, 1});
  ASSERT_EQ(vOnLine.size(), 1u);
  EXPECT_NEAR(vOnLine[0].lo, 20 - kRootGap, 1e-5);
  EXPECT_EQ(r.splitPatches, 0);
}

TEST(Slots, RoundEndsStayWithinTheSlot) {
  const RealizationInput in =
      handMade({{Family::U, 0, rect(-20, 0, 20, 40)}, {Family::V, 5, rect(-20, 0, 20, 40)}});
  SlotParams square, round;
  round.end = SlotEnd::Round;
  const Realization a = realize(in, square), b = realize(in, round);
  const double xu = lineX(in.frames.u, in.frames.v, 5);
  // The rounded slot reaches the root on its centre line, and leaves the corners.
  EXPECT_NEAR(b.slotted[0].intervalsOnLine({xu, 0}, {0, 1})[0].hi, 20 + kRootGap, 1e-3);
  EXPECT_GT(b.slotted[0].area(), a.slotted[0].area());
  EXPECT_LT(b.slotted[0].area() - a.slotted[0].area(), round.width() * round.width());
}

// The opened piece count skips growing the eroded region back when the eroded pieces
// decide it alone; it must agree with growing back on the cases where they nearly do not.
TEST(Slots, OpenedPieceCountAgreesWithGrowingBack) {
  const double neck = 0.25, crumb = 0.5;
  const auto disc = [](double cx, double r) { return circle(cx, 0, r); };
  struct Case {
    const char* name;
    Region2d region;
    int pieces;
  };
  const Region2d squares = rect(0, 0, 10, 10).unite(rect(11, 0, 21, 10));
  const std::vector<Case> cases = {
      {"one square", rect(0, 0, 10, 10), 1},
      {"bridge thinner than 2 neck", squares.unite(rect(9, 4.85, 12, 5.15)), 2},
      {"bridge wider than 2 neck", squares.unite(rect(9, 4.7, 12, 5.3)), 1},
      // Two discs overlapping in a waist 0.32 mm wide: eroded, they are two discs 0.495 mm
      // apart, which meet again when grown back by 0.25 mm.
      {"hourglass", Region2d::fromLoops({disc(0, 5), disc(9.995, 5)}, FillRule::NonZero), 1},
      {"hourglass parted", Region2d::fromLoops({disc(0, 5), disc(10.05, 5)}, FillRule::NonZero), 2},
      // A crumb left by erosion counts when it grows back to 0.5 mm² or more.
      {"small square too small", rect(0, 0, 10, 10).unite(rect(20, 0, 20.6, 0.6)), 1},
      {"small square big enough", rect(0, 0, 10, 10).unite(rect(20, 0, 20.8, 0.8)), 2},
      {"small square close by", rect(0, 0, 10, 10).unite(rect(10.3, 0, 11.1, 0.8)), 2},
      // An island in a hole: the boxes overlap, the pieces are far apart.
      {"island in a hole", annulus(0, 0, 10, 20).unite(rect(-3, -3, 3, 3)), 2},
      {"island near the wall", annulus(0, 0, 10, 20).unite(rect(-1, -3, 1, 9.7)), 2},
      // Two interleaved combs, 0.6 mm apart: boxes overlap, pieces stay apart.
      {"combs",
       rect(0, 0, 1, 20).unite(rect(0, 0, 20, 1)).unite(rect(1.6, 1.6, 20, 2.6)).unite(rect(19, 1.6, 20, 20)),
       2},
  };
  for (const Case& c : cases) {
    EXPECT_EQ(openedPieceCountFull(c.region, neck, crumb), c.pieces) << c.name;
    EXPECT_EQ(openedPieceCount(c.region, neck, crumb), c.pieces) << c.name;
  }
}

// Slotted patches of arranged solids: no interlock left, no patch in pieces, and the paper
// promised beside each holding slot is there.
void expectRealizable(const TopoDS_Shape& shape, int slices = 48) {
  ArrangementParams params;
  params.slices = slices;
  SlotParams slots;
  params.hinges.slotWidth = slots.width();
  const Model model = modelFromShape(shape, "test solid");
  const Arrangement a = arrange(model, params);
  ASSERT_TRUE(a.certificate.stable);
  const RealizationInput in = realizationInput(a, model.meshDeflection);
  const Realization r = realize(in, slots);
  expectStatesMatchSlots(in, r);
  EXPECT_EQ(r.interlocks.remaining, 0);
  EXPECT_EQ(r.splitPatches, 0);
  for (const Region2d& p : r.slotted) EXPECT_EQ(p.components().size(), 1u);
  EXPECT_GE(r.minSlotEdgeDistance, params.hinges.minSlotEdgeDistance - 0.01);
  EXPECT_GE(r.shortestHinge, params.hinges.minHingeLength);
  EXPECT_TRUE(r.assemblyChecked);
  EXPECT_EQ(r.assemblyOrder.size(), a.scaffold.patches.size());
  // A holding hinge keeps an up/down pair, so the certificate's pins are all still there.
  for (size_t h = 0; h < a.scaffold.hinges.size(); ++h) {
    const ScaffoldHinge& hinge = a.scaffold.hinges[h];
    if (!hinge.holds) continue;
    bool pinned = false;
    for (size_t o = 0; o < a.scaffold.hinges.size(); ++o) {
      const ScaffoldHinge& other = a.scaffold.hinges[o];
      pinned |= other.u == hinge.u && other.v == hinge.v && other.holds &&
                (r.slots[o] == SlotPair::UpDown || r.slots[o] == SlotPair::DownUp);
    }
    EXPECT_TRUE(pinned);
  }
}

// The slot search's cache of patch states: kept across steps, what was not asked for since
// the generation before is dropped once the budget is spent, and nothing before.
TEST(SearchCache, KeepsWhatWasAskedForLatelyWithinTwiceItsBudget) {
  BoundedCache<int, int> cache(10);
  const auto put = [&](int key) { cache.put(key, std::make_shared<const int>(key * key), 2); };
  for (int k = 0; k < 6; ++k) put(k);  // 12 of 10
  cache.age();
  ASSERT_NE(cache.find(1), nullptr);  // from the older generation into the current one
  EXPECT_EQ(*cache.find(1), 1);
  for (int k = 6; k < 11; ++k) put(k);  // 2 + 10 of 10
  EXPECT_TRUE(cache.contains(0));       // not aged yet
  cache.age();
  for (const int gone : {0, 2, 3, 4, 5}) EXPECT_FALSE(cache.contains(gone)) << gone;
  for (const int kept : {1, 6, 10}) EXPECT_NE(cache.find(kept), nullptr) << kept;
  EXPECT_EQ(*cache.find(10), 100);

  BoundedCache<int, int> small(10);
  small.put(7, std::make_shared<const int>(7), 1);
  small.put(7, std::make_shared<const int>(8), 1);  // a key is put once
  small.age();
  small.age();
  ASSERT_NE(small.find(7), nullptr);  // within the budget nothing is dropped
  EXPECT_EQ(*small.find(7), 7);
}

// The split repair's searches share a RealizeMemo: the patch states one search cut, and
// the neck tests it made of states it never cut, the next one takes. Taken or made, a
// search finds the same slots, pieces and slotted patches.
TEST(RealizeMemo, ASearchFindsTheSameWithTheMemoFilled) {
  ArrangementParams params;
  params.slices = 48;
  SlotParams slots;
  params.hinges.slotWidth = slots.width();
  const Model model = modelFromShape(makeHollowSphere(60, 45), "test solid");
  const RealizationInput in = realizationInput(arrange(model, params), model.meshDeflection);
  const Realization plain = realize(in, slots);
  const std::shared_ptr<RealizeMemo> memo = makeRealizeMemo();
  const Realization first = realize(in, slots, {}, {}, memo.get());
  // The search tested states it never cut (the shell's thin sections split at many slots).
  ASSERT_GT(memo->opened.size(), 100u);
  ASSERT_GT(memo->states.size(), 100u);
  const Realization again = realize(in, slots, {}, {}, memo.get());
  // With the states forgotten, the search has only the memo's neck tests to bound its moves
  // by, and cuts the states it keeps again.
  memo->states = BoundedCache<MemoKey, PatchState>(kPatchStateCacheBytes);
  const Realization bounded = realize(in, slots, {}, {}, memo.get());
  for (const Realization* r : {&first, &again, &bounded}) {
    EXPECT_EQ(r->slots, plain.slots);
    EXPECT_EQ(r->splitPatches, plain.splitPatches);
    EXPECT_EQ(r->interlocks.remaining, plain.interlocks.remaining);
    ASSERT_EQ(r->slotted.size(), plain.slotted.size());
    for (size_t k = 0; k < plain.slotted.size(); ++k)
      EXPECT_NEAR(r->slotted[k].area(), plain.slotted[k].area(), 1e-9) << k;
  }
}

TEST(RealizeSolids, HollowSphere) {
  expectRealizable(makeHollowSphere(60, 45));
}
TEST(RealizeSolids, Torus) {
  expectRealizable(makeTorus(60, 20));
}
TEST(RealizeSolids, BoxWithWindows) {
  expectRealizable(test::makeBoxWithWindows(120, 80, 60, 6));
}

}  // namespace
}  // namespace sliceform
