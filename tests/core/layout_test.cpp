// SPDX-License-Identifier: LGPL-2.1-or-later
// The layout stage: flat cut loops that close and keep arcs, labels on paper and clear of
// each other, nesting that never overlaps patches or leaves a sheet, and the same layout
// from run to run.
#include <gtest/gtest.h>

#include <BRepAdaptor_Curve.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <random>
#include <regex>
#include <sstream>

#include "layout/labels.hpp"
#include "layout/layout.hpp"
#include "layout/nesting.hpp"
#include "model/model.hpp"
#include "output/sheets_cairo.hpp"
#include "pipeline/design.hpp"
#include "support/error.hpp"
#include "test_support.hpp"

namespace sliceform {
namespace {

Design designOf(const TopoDS_Shape& shape, const SheetSpec& sheet = {}) {
  DesignParams params;
  params.arrangement.slices = 32;
  params.sheet = sheet;
  return runDesign(modelFromShape(shape, "test solid"), params);
}

const Design& sphere() {
  static const Design d = designOf(test::makeSphere(60));
  return d;
}

Region2d box(const Label& l) {
  const double w = labelWidth(l.text, l.height) / 2, h = l.height / 2;
  const double hx = l.vertical ? h : w, hy = l.vertical ? w : h;
  return Region2d::fromLoops({{{l.at.x - hx, l.at.y - hy},
                               {l.at.x + hx, l.at.y - hy},
                               {l.at.x + hx, l.at.y + hy},
                               {l.at.x - hx, l.at.y + hy}}});
}

double distance(Vec2 a, Vec2 b) {
  return std::hypot(a.x - b.x, a.y - b.y);
}

Region2d placed(const Region2d& r, const Placement& p) {
  std::vector<Region2d::Loop> loops;
  for (const Region2d::Loop& loop : r.loops()) {
    Region2d::Loop moved;
    for (const Vec2& q : loop) moved.push_back(p.apply(q));
    loops.push_back(moved);
  }
  return Region2d::fromLoops(loops);
}

TEST(Labels, StrokesStayInTheirBox) {
  for (const bool vertical : {false, true}) {
    const Label l = setLabel("V12", {10, 20}, 4, vertical);
    ASSERT_EQ(l.strokes.size(), 1u + 2u + 1u);  // V, 1 (two strokes), 2
    const Box2 b = box(l).bounds();
    Box2 ink;
    for (const Stroke& s : l.strokes)
      for (const Vec2& p : s) {
        ink.min = {std::min(ink.empty ? p.x : ink.min.x, p.x), std::min(ink.empty ? p.y : ink.min.y, p.y)};
        ink.max = {std::max(ink.empty ? p.x : ink.max.x, p.x), std::max(ink.empty ? p.y : ink.max.y, p.y)};
        ink.empty = false;
      }
    // The ink fills the box exactly: the box is what placement keeps on paper.
    EXPECT_NEAR(ink.min.x, b.min.x, 1e-4);
    EXPECT_NEAR(ink.min.y, b.min.y, 1e-4);
    EXPECT_NEAR(ink.max.x, b.max.x, 1e-4);
    EXPECT_NEAR(ink.max.y, b.max.y, 1e-4);
  }
  EXPECT_NEAR(labelWidth("U3", 6), 9.5, 1e-9);  // two glyphs of 4 and a gap of 1.5 units
}

// A small island of paper lies wholly inside a big label's box, so no edge of the box
// crosses its boundary: the label must still not be set there (the bunny's U19 once was).
TEST(Labels, NameNeverOnAnIslandSmallerThanItsBox) {
  auto square = [](double x, double y, double side) {
    return Region2d::Loop{{x, y}, {x + side, y}, {x + side, y + side}, {x, y + side}};
  };
  const Region2d paper = Region2d::fromLoops({square(0, 0, 9.5), square(30, 0, 3)});
  const Label l = placeName(paper, "U19");
  ASSERT_GT(l.height, 0);
  EXPECT_TRUE(box(l).subtract(paper).empty()) << "at " << l.at.x << ", " << l.at.y << " height " << l.height;
}

// The name goes to the deepest part of the paper: on a dumbbell, the middle of the larger
// disc, not the smaller one or the bar between them, nor drawn towards the lobe beside it.
TEST(Labels, NameAtTheDeepestSpot) {
  auto disc = [](Vec2 c, double r) {
    Region2d::Loop l;
    for (int i = 0; i < 180; ++i)
      l.push_back({c.x + r * std::cos(i * M_PI / 90), c.y + r * std::sin(i * M_PI / 90)});
    return l;
  };
  const Region2d::Loop bar{{0, -2}, {60, -2}, {60, 2}, {0, 2}};
  const Region2d paper =
      Region2d::fromLoops({disc({0, 0}, 12), bar, disc({60, 0}, 20), disc({78, 0}, 14)}, FillRule::NonZero);
  const Label l = placeName(paper, "V3");
  EXPECT_EQ(l.height, 8);
  EXPECT_LT(distance(l.at, {60, 0}), 0.25) << l.at.x << ", " << l.at.y;  // 0.15 mm: the box is no disc
}

// Partner labels search only a window beside their slot and keep the pieces of it that are
// paper. A window wholly inside a hole has none; an island in that hole is paper and may
// carry a label, but only with the whole box on it.
TEST(Labels, PartnerWindowKeepsOnlyPaper) {
  auto square = [](double x, double y, double side, bool hole = false) {
    Region2d::Loop l{{x, y}, {x + side, y}, {x + side, y + side}, {x, y + side}};
    if (hole) std::reverse(l.begin(), l.end());
    return l;
  };
  const LabelSpot spot{"V7", 50, {40, 60}, 50, 0.5, {40, 60}};
  const Region2d frame =
      Region2d::fromLoops({square(0, 0, 100), square(20, 20, 60, true)}, FillRule::NonZero);
  int missing = 0;
  EXPECT_TRUE(placePartners(frame, {spot}, {}, 3.5, missing).empty());
  EXPECT_EQ(missing, 1);

  const Region2d islands = Region2d::fromLoops(
      {square(0, 0, 100), square(20, 20, 60, true), square(50.5, 45, 4.5)}, FillRule::NonZero);
  missing = 0;
  const std::vector<Label> labels = placePartners(islands, {spot}, {}, 3.5, missing);
  ASSERT_EQ(labels.size(), 1u);
  EXPECT_EQ(missing, 0);
  EXPECT_TRUE(box(labels[0]).subtract(islands).empty()) << "at " << labels[0].at.x << ", " << labels[0].at.y;
  EXPECT_GT(labels[0].at.x, 50.5);

  // A label already there keeps the next one off its box.
  missing = 0;
  const std::vector<Label> next = placePartners(islands, {spot}, labels, 3.5, missing);
  for (const Label& l : next) EXPECT_TRUE(box(l).intersect(box(labels[0])).empty());
}

// Labels on a wavy ring, whose edges head every way: each label's box stays on the paper,
// clear of its cuts by the margin, and of the other labels.
TEST(Labels, OnCurvedPaperBoxesStayClearOfTheCuts) {
  Region2d::Loop outer, hole;
  for (int i = 0; i < 360; ++i) {
    const double t = i * M_PI / 180, r = 30 + 3 * std::sin(7 * t), q = 9 + 1.5 * std::sin(5 * t);
    outer.push_back({r * std::cos(t), r * std::sin(t)});
    hole.push_back({q * std::cos(-t), q * std::sin(-t)});
  }
  const Region2d paper = Region2d::fromLoops({outer, hole}, FillRule::NonZero);
  const Region2d clear = paper.offset(-0.59);  // the 0.6 mm margin, less rounding
  const Label name = placeName(paper, "U12");
  ASSERT_GT(name.height, 0);
  EXPECT_TRUE(box(name).subtract(clear).empty()) << name.at.x << ", " << name.at.y;
  std::vector<LabelSpot> spots;
  for (double x = -27.5; x <= 27.5; x += 2.5)
    for (const Interval& w : paper.intervalsOnLine({x, 0}, {0, 1}))
      spots.push_back({"V" + std::to_string(spots.size()), x, w, (w.lo + w.hi) / 2, 0.5, w});
  int missing = 0;
  const std::vector<Label> labels = placePartners(paper, spots, {name}, 3.5, missing);
  EXPECT_EQ(labels.size() + missing, spots.size());
  EXPECT_GT(labels.size(), spots.size() / 2);
  for (size_t i = 0; i < labels.size(); ++i) {
    EXPECT_TRUE(box(labels[i]).subtract(clear).empty()) << labels[i].text;
    EXPECT_TRUE(box(labels[i]).intersect(box(name)).empty()) << labels[i].text;
    for (size_t j = 0; j < i; ++j)
      EXPECT_TRUE(box(labels[i]).intersect(box(labels[j])).empty())
          << labels[i].text << " " << labels[j].text;
  }
}

// Text on a sheet reads left to right (or bottom to top) whichever way nesting turned its
// patch: the "U" of "U1" comes before the "1".
TEST(Labels, ReadUprightOnTheSheetWhateverThePatchRotation) {
  for (const double rotation : {0.0, 90.0, 180.0, 270.0}) {
    SheetLayout layout;
    FlatPatch patch;
    patch.name = setLabel("U1", {5, 2}, 4, false);
    layout.patches.push_back(patch);
    layout.packing.sheets = 1;
    layout.packing.placements.push_back(Placement{0, {100, 100}, rotation});
    const std::vector<SheetDrawing> sheets = sheetDrawings(layout);
    ASSERT_EQ(sheets.size(), 1u);
    ASSERT_EQ(sheets[0].engrave.size(), 3u);  // U, then 1 in two strokes
    auto centre = [](const Stroke& s) {
      Vec2 c{0, 0};
      for (const Vec2& p : s) c = {c.x + p.x / s.size(), c.y + p.y / s.size()};
      return c;
    };
    const Vec2 u = centre(sheets[0].engrave[0]), one = centre(sheets[0].engrave[2]);
    const bool quarter = rotation == 90 || rotation == 270;
    if (quarter) {
      EXPECT_LT(u.y, one.y - 1) << rotation;   // vertical, read bottom to top
      EXPECT_NEAR(u.x, one.x, 2) << rotation;  // both within the 4 mm line
    } else {
      EXPECT_LT(u.x, one.x - 1) << rotation;
      EXPECT_NEAR(u.y, one.y, 2) << rotation;
    }
  }
}

TEST(Layout, CutLoopsCloseKeepArcsAndBoundThePaper) {
  const Design& d = sphere();
  int arcs = 0;
  for (const FlatPatch& p : d.layout.patches) {
    double area = 0;
    for (const CutLoop& loop : p.cut) {
      for (size_t i = 0; i < loop.size(); ++i) {
        const CutElement& e = loop[i];
        arcs += e.kind == CutElement::Kind::Arc ? 1 : 0;
        if (e.kind == CutElement::Kind::Arc) {
          EXPECT_NEAR(distance(pointAt(e, 0), e.a), 0, 1e-6) << p.id;
          EXPECT_NEAR(distance(pointAt(e, 1), e.b), 0, 1e-6) << p.id;
        }
        if (e.kind != CutElement::Kind::Circle)
          EXPECT_NEAR(distance(e.b, loop[(i + 1) % loop.size()].a), 0, 1e-6)
              << p.id << " loop does not close";
      }
      Region2d::Loop points;
      for (const CutElement& e : loop)
        for (const Vec2& q : sample(e, 0.005)) points.push_back(q);
      area += Region2d::signedArea(points);
    }
    // Loops run either way round; the outer one dominates, the holes and slots subtract.
    EXPECT_NEAR(std::fabs(area), p.outline.area(), 0.01 * p.outline.area()) << p.id;
  }
  EXPECT_GT(arcs, static_cast<int>(d.layout.patches.size()));  // a sphere's patches are arcs and slots
}

TEST(Layout, LabelsSitOnPaperAndClearOfEachOther) {
  const Design& d = sphere();
  int partners = 0;
  for (const FlatPatch& p : d.layout.patches) {
    ASSERT_GT(p.name.height, 0) << p.id;
    EXPECT_EQ(p.name.text, p.id);
    std::vector<Label> all = {p.name};
    all.insert(all.end(), p.partners.begin(), p.partners.end());
    for (size_t i = 0; i < all.size(); ++i) {
      EXPECT_LT(box(all[i]).subtract(p.outline).area(), 1e-9)
          << p.id << ": label " << all[i].text << " off the paper";
      for (size_t j = 0; j < i; ++j)
        EXPECT_LT(box(all[i]).intersect(box(all[j])).area(), 1e-9)
            << p.id << ": " << all[i].text << " on " << all[j].text;
    }
    partners += static_cast<int>(p.partners.size() + p.unlabelled.size());
  }
  // One partner label per hinge end that is still a hinge: every hinge labels both patches.
  int meeting = 0;
  for (const bool m : d.realization.meets) meeting += m ? 1 : 0;
  EXPECT_EQ(partners, 2 * meeting);
}

// Each patch carries its assembly step ("#5" for the fifth in assembly_order) beside its id,
// so whoever assembles finds the next patch on the sheets: on paper, clear of every other
// label, and every step from 1 to the patch count once.
TEST(Layout, StepNumbersBesideTheIds) {
  const Design& d = sphere();
  const std::vector<int>& order = d.realization.assemblyOrder;
  ASSERT_EQ(order.size(), d.layout.patches.size());
  std::vector<int> steps;
  for (const FlatPatch& p : d.layout.patches) {
    const int step = static_cast<int>(std::find(order.begin(), order.end(), p.patch) - order.begin()) + 1;
    EXPECT_EQ(p.step, step) << p.id;
    EXPECT_EQ(p.stepLabel.text, "#" + std::to_string(step)) << p.id;
    ASSERT_GE(p.stepLabel.height, kMinLabelHeight - 1e-9) << p.id;
    EXPECT_FALSE(p.stepLabel.strokes.empty()) << p.id;
    EXPECT_LT(box(p.stepLabel).subtract(p.outline).area(), 1e-9) << p.id << ": step off the paper";
    std::vector<Label> others = {p.name};
    others.insert(others.end(), p.partners.begin(), p.partners.end());
    for (const Label& o : others)
      EXPECT_LT(box(p.stepLabel).intersect(box(o)).area(), 1e-9) << p.id << ": step on " << o.text;
    // Near its id: within a few id heights.
    EXPECT_LT(distance(p.stepLabel.at, p.name.at), 4 * p.name.height + 10) << p.id;
    steps.push_back(p.step);
  }
  std::sort(steps.begin(), steps.end());
  for (size_t i = 0; i < steps.size(); ++i) EXPECT_EQ(steps[i], static_cast<int>(i) + 1);
}

void expectNoOverlaps(const SheetLayout& l) {
  ASSERT_EQ(l.packing.placements.size(), l.patches.size());
  std::vector<Region2d> onSheet;
  for (size_t k = 0; k < l.patches.size(); ++k) {
    const Placement& at = l.packing.placements[k];
    ASSERT_GE(at.sheet, 0);
    ASSERT_LT(at.sheet, l.packing.sheets);
    onSheet.push_back(placed(l.patches[k].outline, at));
    const Box2 b = onSheet.back().bounds();
    EXPECT_GE(b.min.x, l.sheet.margin - 1e-3) << l.patches[k].id;
    EXPECT_GE(b.min.y, l.sheet.margin - 1e-3) << l.patches[k].id;
    EXPECT_LE(b.max.x, l.sheet.width - l.sheet.margin + 1e-3) << l.patches[k].id;
    EXPECT_LE(b.max.y, l.sheet.height - l.sheet.margin + 1e-3) << l.patches[k].id;
  }
  for (size_t a = 0; a < onSheet.size(); ++a)
    for (size_t b = 0; b < a; ++b)
      if (l.packing.placements[a].sheet == l.packing.placements[b].sheet)
        // Apart by the spacing, less what the micrometre placement grid may take.
        EXPECT_TRUE(onSheet[a].offset(l.sheet.spacing - 0.01).intersect(onSheet[b]).empty())
            << l.patches[a].id << " and " << l.patches[b].id << " closer than the spacing";
}

TEST(Layout, NestedPatchesNeverOverlapAndStayOnTheSheet) {
  expectNoOverlaps(sphere().layout);
}

TEST(Layout, SmallSheetsTakeMoreOfThemAndStillNoOverlap) {
  // The sphere on 130 x 130 mm cards: several sheets, rotations in use.
  const SheetLayout l = layOut(layoutInput(sphere()), sheetSpec("130x130", 4, 2));
  EXPECT_GT(l.packing.sheets, sphere().layout.packing.sheets);
  expectNoOverlaps(l);
  EXPECT_LE(l.packing.sheets, l.shelf.sheets);
}

TEST(Layout, SameInputSameLayout) {
  const SheetLayout again = layOut(layoutInput(sphere()), sphere().layout.sheet);
  const SheetLayout &a = sphere().layout, &b = again;
  ASSERT_EQ(a.packing.placements.size(), b.packing.placements.size());
  for (size_t k = 0; k < a.packing.placements.size(); ++k) {
    EXPECT_EQ(a.packing.placements[k].sheet, b.packing.placements[k].sheet);
    EXPECT_EQ(a.packing.placements[k].offset.x, b.packing.placements[k].offset.x);
    EXPECT_EQ(a.packing.placements[k].offset.y, b.packing.placements[k].offset.y);
    EXPECT_EQ(a.packing.placements[k].rotation, b.packing.placements[k].rotation);
    EXPECT_EQ(a.patches[k].name.at.x, b.patches[k].name.at.x);
  }
}

// Laid out again, as layOut lays the design out anew: a sheet edit nests the patches again
// and keeps their flattening and labels; the same error where a patch does not fit.
TEST(Layout, LaidOutAgainOnAnotherSheetIsTheLayoutThere) {
  const SheetSpec card = sheetSpec("130x130", 4, 2);
  const SheetLayout fresh = layOut(layoutInput(sphere()), card);
  const SheetLayout again = laidOutAgain(layoutInput(sphere()), sphere().layout, card);
  EXPECT_EQ(again.sheet.name, "130x130");
  EXPECT_EQ(again.packing.sheets, fresh.packing.sheets);
  EXPECT_GT(again.packing.sheets, sphere().layout.packing.sheets);
  EXPECT_EQ(again.shelf.sheets, fresh.shelf.sheets);
  ASSERT_EQ(again.packing.placements.size(), fresh.packing.placements.size());
  ASSERT_EQ(again.patches.size(), fresh.patches.size());
  for (size_t k = 0; k < fresh.patches.size(); ++k) {
    const Placement &a = again.packing.placements[k], &b = fresh.packing.placements[k];
    EXPECT_EQ(a.sheet, b.sheet);
    EXPECT_EQ(a.offset.x, b.offset.x);
    EXPECT_EQ(a.offset.y, b.offset.y);
    EXPECT_EQ(a.rotation, b.rotation);
    EXPECT_EQ(again.patches[k].id, fresh.patches[k].id);
    EXPECT_EQ(again.patches[k].name.at.x, fresh.patches[k].name.at.x);
    ASSERT_EQ(again.patches[k].partners.size(), fresh.patches[k].partners.size());
    for (size_t i = 0; i < fresh.patches[k].partners.size(); ++i)
      EXPECT_EQ(again.patches[k].partners[i].at.y, fresh.patches[k].partners[i].at.y);
  }
  expectNoOverlaps(again);
  EXPECT_THROW(laidOutAgain(layoutInput(sphere()), sphere().layout, sheetSpec("100x100", 10, 3)), Error);
}

// A kerf edit moves the cut paths and nothing else: the layout of the design with another
// kerf, its cut paths drawn again, is the one layOut makes of it.
TEST(Layout, LaidOutAgainWithAnotherKerfDrawsTheCutPathsAgain) {
  Design kerfed = sphere();
  kerfed.realization.params.kerf = 0.2;
  const SheetLayout fresh = layOut(layoutInput(kerfed), sphere().layout.sheet);
  const SheetLayout again = laidOutAgain(layoutInput(kerfed), sphere().layout, sphere().layout.sheet);
  EXPECT_EQ(again.kerf, 0.2);
  EXPECT_EQ(again.packing.sheets, fresh.packing.sheets);
  ASSERT_EQ(again.patches.size(), fresh.patches.size());
  for (size_t k = 0; k < fresh.patches.size(); ++k) {
    EXPECT_EQ(again.packing.placements[k].offset.x, fresh.packing.placements[k].offset.x);
    EXPECT_EQ(again.patches[k].name.at.x, fresh.patches[k].name.at.x);
    const std::vector<CutLoop>&a = again.patches[k].cut, &b = fresh.patches[k].cut,
          &before = sphere().layout.patches[k].cut;
    ASSERT_EQ(a.size(), b.size());
    for (size_t i = 0; i < b.size(); ++i) {
      ASSERT_EQ(a[i].size(), b[i].size());
      for (size_t e = 0; e < b[i].size(); ++e) {
        EXPECT_EQ(a[i][e].a.x, b[i][e].a.x);
        EXPECT_EQ(a[i][e].a.y, b[i][e].a.y);
      }
    }
    // Moved out by half the kerf: the outer loop's box grows by 0.1 mm a side.
    const auto width = [](const std::vector<CutLoop>& loops) {
      double lo = HUGE_VAL, hi = -HUGE_VAL;
      for (const CutLoop& loop : loops)
        for (const CutElement& e : loop)
          for (const Vec2& p : sample(e, 0.001)) lo = std::min(lo, p.x), hi = std::max(hi, p.x);
      return hi - lo;
    };
    EXPECT_NEAR(width(a), width(before) + 0.2, 0.02) << again.patches[k].id;
  }
}

// Where a kerf path of half-kerf `r` may lie about `paper`: no nearer than r, no further
// than 2r (a mitre at 120°), each within `slack`.
struct KerfBand {
  Region2d clear, near;
  KerfBand(const Region2d& paper, double r, double slack)
      : clear(paper.offset(r - slack)), near(paper.offset(2 * r + slack)) {}
  void expectHolds(Vec2 q, const std::string& id) const {
    EXPECT_FALSE(clear.contains(q)) << id << ": the path comes nearer the paper than half the kerf";
    EXPECT_TRUE(near.contains(q)) << id << ": the path strays from the paper";
  }
};

// The kerf's path keeps half the kerf off the paper everywhere and follows it closely (the
// beam, as wide as the kerf, cuts the paper as designed); a corner it turns less than 120°
// goes straight on (a mitre) rather than round an arc of half the kerf, as OCCT's offset
// draws it (the 90° corners of the slots' mouths).
TEST(Layout, KerfPathsKeepHalfTheKerfOffThePaperAndMitreTheirCorners) {
  Design kerfed = sphere();
  const double r = 0.1;
  kerfed.realization.params.kerf = 2 * r;
  const SheetLayout l = layOut(layoutInput(kerfed), sphere().layout.sheet);
  int corners = 0, rounded = 0;
  for (const FlatPatch& p : l.patches) {
    const KerfBand band(p.outline, r, 0.002);
    for (const CutLoop& loop : p.cut)
      for (const CutElement& e : loop) {
        for (const Vec2& q : sample(e, 0.001)) band.expectHolds(q, p.id);
        if (e.kind == CutElement::Kind::Arc && std::abs(e.radius - r) < 1e-9) {
          EXPECT_GE(sweepOf(e), 120 * M_PI / 180 - 1e-9) << p.id << ": a corner arc turning less than 120°";
          ++corners;
        }
      }
    for (TopExp_Explorer it(kerfCompensated(kerfed.patches[p.patch].shape, 2 * r), TopAbs_EDGE); it.More();
         it.Next()) {
      const BRepAdaptor_Curve c(TopoDS::Edge(it.Current()));
      rounded += c.GetType() == GeomAbs_Circle && std::abs(c.Circle().Radius() - r) < 1e-9;
    }
  }
  EXPECT_LT(corners * 3, rounded) << "of OCCT's " << rounded << " corner arcs, " << corners << " are left";
}

// A mesh's patches are polygons: their kerf paths are the polygons moved out, keeping half
// the kerf off the paper, every corner that turns less than 120° mitred, none rounded.
TEST(Layout, KerfPathsOfAMeshAreItsPolygonsMovedOut) {
  DesignParams params;
  params.arrangement.slices = 32;
  const double r = 0.1;
  params.slots.kerf = 2 * r;
  const Model sphereMesh = modelFromMesh(modelFromShape(test::makeSphere(60), "sphere").mesh, "sphere mesh");
  const Design d = runDesign(sphereMesh, params);
  int mitres = 0;
  for (const FlatPatch& p : d.layout.patches) {
    EXPECT_FALSE(d.patches[p.patch].exact);
    const KerfBand band(p.outline, r, 0.002);
    for (const CutLoop& loop : p.cut) {
      for (size_t i = 0; i < loop.size(); ++i) {
        const CutElement &e = loop[i], &next = loop[(i + 1) % loop.size()];
        ASSERT_EQ(e.kind, CutElement::Kind::Line) << p.id;
        EXPECT_NEAR(e.b.x, next.a.x, 1e-9);
        EXPECT_NEAR(e.b.y, next.a.y, 1e-9);
        for (const Vec2& q : {e.a, Vec2{(e.a.x + e.b.x) / 2, (e.a.y + e.b.y) / 2}}) band.expectHolds(q, p.id);
      }
      mitres += static_cast<int>(loop.size());
    }
  }
  // One element a polygon's vertex: no arcs, nor the extra vertex a round corner adds.
  int vertices = 0;
  for (const FlatPatch& p : d.layout.patches)
    for (const Region2d::Loop& loop : p.outline.loops()) vertices += static_cast<int>(loop.size());
  EXPECT_LE(mitres, vertices * 11 / 10);
}

// An exact face with an edge that is neither a line nor a circle (here the hole's ellipses,
// a box minus a cylinder sliced at 45° to its axis) gets its kerf path from the paper's
// polygon, as a mesh's patch does: lines only, half the kerf off the paper. OCCT's offset
// would fit B-splines to the ellipses' offsets, 18 ms a face.
TEST(Layout, KerfPathsOfFacesWithOtherCurvesComeFromThePaperPolygon) {
  const TopoDS_Shape box =
      test::cut(BRepPrimAPI_MakeBox(80, 60, 60).Shape(),
                BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(40, 30, -20), gp_Dir(0, 0, 1)), 15, 100).Shape());
  DesignParams params;
  params.arrangement.slices = 32;
  params.arrangement.u = {1, 0, 0};
  params.arrangement.v = {0, std::sqrt(0.5), std::sqrt(0.5)};
  const double r = 0.1;
  params.slots.kerf = 2 * r;
  const Design d = runDesign(modelFromShape(box, "box minus a cylinder"), params);
  int curved = 0;
  for (const FlatPatch& p : d.layout.patches) {
    const PatchFace& face = d.patches[p.patch];
    bool other = false;
    for (TopExp_Explorer it(face.shape, TopAbs_EDGE); it.More(); it.Next()) {
      const GeomAbs_CurveType type = BRepAdaptor_Curve(TopoDS::Edge(it.Current())).GetType();
      other = other || (type != GeomAbs_Line && type != GeomAbs_Circle);
    }
    if (!face.exact || !other) continue;
    ++curved;
    const KerfBand band(p.outline, r, kOutlineDeflection + 0.002);
    ASSERT_FALSE(p.cut.empty()) << p.id;
    for (const CutLoop& loop : p.cut)
      for (const CutElement& e : loop) {
        ASSERT_EQ(e.kind, CutElement::Kind::Line) << p.id;
        for (const Vec2& q : sample(e, 0.001)) band.expectHolds(q, p.id);
      }
  }
  EXPECT_GT(curved, 0) << "no exact patch with an ellipse: the test no longer tests it";
}

// Where OCCT's offset fails on an exact face (occt-misc Axis_of_bearing.brep: one patch of
// 21 at 0.15 mm), the kerf's path comes from the paper's polygon, and keeps half the kerf
// off the paper as the others do: the design is laid out, not refused.
TEST(Layout, KerfPathsWhereOcctsOffsetFailsComeFromThePaperPolygon) {
  const Model model = scaledToSize(readModel(SLICEFORM_OCCT_DATA_DIR "/occ/Axis_of_bearing.brep"), 150);
  DesignParams params;
  const double r = 0.075;
  params.slots.kerf = 2 * r;
  const Design d = runDesign(model, params);
  int failing = 0;
  for (const FlatPatch& p : d.layout.patches) {
    try {
      kerfCompensated(d.patches[p.patch].shape, 2 * r);
    } catch (const Error&) {
      ++failing;
    }
    // The outline is the exact face's polygon, within kOutlineDeflection of it.
    const KerfBand band(p.outline, r, kOutlineDeflection + 0.002);
    ASSERT_FALSE(p.cut.empty()) << p.id;
    for (const CutLoop& loop : p.cut)
      for (const CutElement& e : loop)
        for (const Vec2& q : sample(e, 0.001)) band.expectHolds(q, p.id);
  }
  EXPECT_GT(failing, 0) << "no patch left to the polygon: the test no longer tests it";
}

TEST(Layout, PatchLargerThanTheSheetIsAClearError) {
  try {
    layOut(layoutInput(sphere()), sheetSpec("100x100", 10, 3));
    FAIL() << "a 120 mm sphere's patches were laid out on 80 mm of sheet";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::BadParameter);
    EXPECT_NE(std::string(e.what()).find("does not fit a 100x100 sheet"), std::string::npos) << e.what();
  }
}

// A patch that fits the sheet only turned a quarter turn goes on it turned, and lies
// inside its margins: libnest2d left a 300 x 200 mm patch off A3 (277 x 400 mm inside).
TEST(Layout, PatchThatFitsOnlyTurnedIsTurned) {
  const SheetSpec a3 = sheetSpec("A3", 10, 3);
  const Region2d wide = Region2d::fromLoops({{{0, 0}, {300, 0}, {300, 200}, {0, 200}}});
  const Region2d small = Region2d::fromLoops({{{0, 0}, {50, 0}, {50, 40}, {0, 40}}});
  const Packing p = nestOnSheets({small, wide, wide}, {"U0", "U1", "U2"}, a3);
  EXPECT_EQ(p.sheets, 2);
  ASSERT_EQ(p.placements.size(), 3u);
  // The shelf layout, the comparison in the report, turns it too.
  const Packing shelf = shelfPack({small, wide, wide}, {"U0", "U1", "U2"}, a3);
  for (const Packing& q : {p, shelf}) {
    for (size_t k = 1; k < 3; ++k) {
      EXPECT_EQ(std::lround(q.placements[k].rotation) % 180, 90) << "U" << k;
      const Box2 b = placed(wide, q.placements[k]).bounds();
      EXPECT_GE(b.min.x, a3.margin - 1e-6);
      EXPECT_GE(b.min.y, a3.margin - 1e-6);
      EXPECT_LE(b.max.x, a3.width - a3.margin + 1e-6);
      EXPECT_LE(b.max.y, a3.height - a3.margin + 1e-6);
    }
  }
}

// Sheets where a patch has no room are not asked for it (layout/first_fit.hpp): every
// patch still goes on the sheet, at the place and turn, that libnest2d's own first fit
// gives it. Shapes of all kinds and sizes, so that sheets fill up unevenly and most patches
// meet full sheets first; with turns and without.
TEST(Layout, NestingSkipsNoSheetThatWouldTakeThePatch) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> size(8, 110), turn(0, 2 * M_PI), count(3, 9);
  std::vector<Region2d> outlines;
  std::vector<std::string> names;
  for (int k = 0; k < 48; ++k) {
    // A convex polygon: points on an ellipse, a few to many, turned any way.
    const double a = size(random), b = size(random) / 2, t = turn(random);
    const int n = k % 4 == 0 ? 4 : static_cast<int>(count(random)) * (k % 3 + 1);
    Region2d::Loop loop;
    for (int i = 0; i < n; ++i) {
      const double u = 2 * M_PI * i / n, x = a * std::cos(u), y = b * std::sin(u);
      loop.push_back({x * std::cos(t) - y * std::sin(t), x * std::sin(t) + y * std::cos(t)});
    }
    outlines.push_back(Region2d::fromLoops({loop}));
    names.push_back("U" + std::to_string(k));
  }
  for (const bool rotate : {true, false}) {
    SheetSpec a4 = sheetSpec("A4", 10, 3);
    a4.rotate = rotate;
    const Packing skipping = nestOnSheets(outlines, names, a4);
    const Packing asking = nestOnSheets(outlines, names, a4, true);
    EXPECT_GE(asking.sheets, 4) << "too few sheets to skip any";
    EXPECT_EQ(skipping.sheets, asking.sheets);
    ASSERT_EQ(skipping.placements.size(), asking.placements.size());
    for (size_t k = 0; k < outlines.size(); ++k) {
      EXPECT_EQ(skipping.placements[k].sheet, asking.placements[k].sheet)
          << names[k] << (rotate ? " turning" : "");
      EXPECT_EQ(skipping.placements[k].offset.x, asking.placements[k].offset.x) << names[k];
      EXPECT_EQ(skipping.placements[k].offset.y, asking.placements[k].offset.y) << names[k];
      EXPECT_EQ(skipping.placements[k].rotation, asking.placements[k].rotation) << names[k];
    }
  }
}

TEST(Layout, SheetNames) {
  EXPECT_EQ(sheetSpec("A3", 10, 3).height, 420);
  EXPECT_NEAR(sheetSpec("Letter", 10, 3).width, 215.9, 1e-9);
  const SheetSpec custom = sheetSpec("600x400", 5, 2);
  EXPECT_EQ(custom.width, 600);
  EXPECT_EQ(custom.height, 400);
  EXPECT_THROW(sheetSpec("B5", 10, 3), Error);
  EXPECT_THROW(sheetSpec("A4", 120, 3), Error);  // no room inside the margins
  EXPECT_THROW(sheetSpec("A4", 10, -1), Error);
}

TEST(SheetSvg, SizeAndViewBoxAreMillimetres) {
  const Design& d = sphere();
  test::TempDir dir;
  const std::string path = dir.file("sheet.svg");
  writeSheetSvg(sheetDrawings(d.layout).front(), d.layout.sheet, path);
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_TRUE(
      std::regex_search(text.str(), std::regex(R"(width="210mm" height="297mm" viewBox="0 0 210 297")")))
      << text.str().substr(0, 300);
}

// A sheet's SVG has the same bytes whatever cairo drew before it in the process: the files
// are written side by side, and cairo numbers surfaces from one counter for the process.
TEST(Layout, SvgSheetBytesDoNotDependOnWhatWasDrawnBefore) {
  const Design& d = sphere();
  test::TempDir dir;
  const std::vector<SheetDrawing> sheets = sheetDrawings(d.layout);
  const auto bytes = [](const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  };
  writeSheetSvg(sheets.front(), d.layout.sheet, dir.file("first.svg"));
  writeSheetsPdf(sheets, d.layout.sheet, dir.file("between.pdf"));
  writeSheetsPng(sheets, d.layout.sheet, dir.file("between.png"));
  writeSheetSvg(sheets.front(), d.layout.sheet, dir.file("second.svg"));
  const std::string first = bytes(dir.file("first.svg"));
  EXPECT_GT(first.size(), 1000u);
  EXPECT_EQ(first, bytes(dir.file("second.svg")));
  // cairo 1.16 names its surface ("surface21"), renumbered to surface1; 1.18 names none.
  EXPECT_FALSE(std::regex_search(first, std::regex("surface([02-9]|1[0-9])"))) << first.substr(0, 400);
}

}  // namespace
}  // namespace sliceform
