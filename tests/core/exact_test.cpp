// SPDX-License-Identifier: LGPL-2.1-or-later
// Exact patch faces and the folded assembly: arcs stay arcs, slots have their width in the
// exact faces, and the folded sliceform's patches meet only at their hinges.
#include <gtest/gtest.h>

#include <BRepAdaptor_Curve.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepAlgoAPI_Section.hxx>
#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepGProp.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <GProp_GProps.hxx>
#include <Geom_Plane.hxx>
#include <Interface_Static.hxx>
#include <STEPControl_Reader.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <gp_Circ.hxx>
#include <gp_Pln.hxx>

#include <cmath>
#include <fstream>
#include <iterator>

#include "arrangement/arrange.hpp"
#include "assembly/fold.hpp"
#include "assembly/polyline_faces.hpp"
#include "exact/patch_faces.hpp"
#include "geometry/simplify.hpp"
#include "realization/realize.hpp"
#include "slicing/brep_slicer.hpp"
#include "slicing/slice_set.hpp"
#include "support/error.hpp"
#include "support/occt_statics.hpp"
#include "test_support.hpp"
#include "verify/emitted.hpp"

namespace sliceform {
namespace {

struct Design {
  Model model;
  Arrangement arrangement;
  Realization realization;
  std::vector<PatchFace> faces;
};

Design design(const Model& model, int slices = 32) {
  Design d{model, {}, {}, {}};
  ArrangementParams params;
  params.slices = slices;
  params.hinges.slotWidth = SlotParams{}.width();
  d.arrangement = arrange(d.model, params);
  d.realization = realize(realizationInput(d.arrangement, model.meshDeflection), SlotParams{});
  d.faces = exactPatches(d.model, d.arrangement, d.realization);
  return d;
}

using test::area;

// The emitted exact faces of solids with holes and voids: one piece each, no interlocks.
void expectBuildable(const TopoDS_Shape& shape) {
  const Design d = design(modelFromShape(shape, "test solid"));
  std::vector<Region2d> outlines;
  for (const PatchFace& f : d.faces) {
    EXPECT_EQ(f.pieces, 1);
    outlines.push_back(f.outline);
  }
  const Emitted e =
      checkEmitted(realizationInput(d.arrangement, d.model.meshDeflection), outlines, SlotParams{});
  EXPECT_EQ(e.interlocks, 0);
  EXPECT_EQ(e.splitPatches, 0);
  EXPECT_TRUE(e.collisions.empty());
}

TEST(ExactPatches, HollowSphereIsBuildable) {
  expectBuildable(test::makeHollowSphere(60, 45));
}
TEST(ExactPatches, BoxWithWindowsIsBuildable) {
  expectBuildable(test::makeBoxWithWindows(120, 80, 60, 6));
}

// A patch that breaks a rule is emitted as its polygon before the partner of a hinge it
// lost: that partner is replaced only if the hinge is still lost once the outlines are
// checked again. A hinge lost by two patches that break no rule replaces both at once;
// a replaced patch is never chosen again.
TEST(Emitted, APatchBreakingARuleGoesBeforeItsHingePartner) {
  std::vector<ScaffoldHinge> hinges(4);
  const int ends[4][2] = {{0, 3}, {1, 2}, {4, 5}, {1, 6}};
  for (int h = 0; h < 4; ++h) hinges[h].u = ends[h][0], hinges[h].v = ends[h][1], hinges[h].holds = h != 3;
  const std::vector<bool> searchMeets = {true, true, true, true};
  Emitted e;
  e.failing = {0};
  e.meets = {0, 1, 0, 0};  // the fourth does not hold: never a reason
  std::vector<char> replaced(7, 0);
  EXPECT_EQ(patchesToReplace(e, hinges, searchMeets, replaced), (std::vector<int>{0, 4, 5}));
  for (const int k : {0, 4, 5}) replaced[k] = 1;
  e.failing = {};
  e.meets = {1, 1, 1, 0};  // the polygon of 0 holds with 3 again
  EXPECT_TRUE(patchesToReplace(e, hinges, searchMeets, replaced).empty());
  e.meets = {0, 1, 1, 0};  // it does not: 3 goes too
  EXPECT_EQ(patchesToReplace(e, hinges, searchMeets, replaced), (std::vector<int>{3}));
  e.failing = {0};  // the polygon of 0 breaking a rule is not replaced again
  EXPECT_EQ(patchesToReplace(e, hinges, searchMeets, replaced), (std::vector<int>{3}));
}

int edgesOfType(const TopoDS_Shape& shape, GeomAbs_CurveType type) {
  int n = 0;
  for (TopExp_Explorer it(shape, TopAbs_EDGE); it.More(); it.Next())
    n += BRepAdaptor_Curve(TopoDS::Edge(it.Current())).GetType() == type ? 1 : 0;
  return n;
}

double length(const TopoDS_Shape& shape) {
  GProp_GProps props;
  BRepGProp::LinearProperties(shape, props);
  return props.Mass();
}

TEST(ExactPatches, SphereKeepsCircularArcsAndSlotWidth) {
  const Design d = design(modelFromShape(test::makeSphere(60), "sphere"));
  ASSERT_FALSE(d.faces.empty());
  const SlotParams params;
  int slotsMeasured = 0;
  for (size_t k = 0; k < d.faces.size(); ++k) {
    const PatchFace& f = d.faces[k];
    EXPECT_TRUE(f.exact);
    EXPECT_EQ(f.pieces, 1);
    EXPECT_GT(edgesOfType(f.shape, GeomAbs_Circle), 0) << "patch " << k;
    EXPECT_EQ(edgesOfType(f.shape, GeomAbs_BSplineCurve), 0);
    // Every straight edge is a slot wall or end, never a chord of the circle.
    for (TopExp_Explorer it(f.shape, TopAbs_EDGE); it.More(); it.Next())
      if (BRepAdaptor_Curve(TopoDS::Edge(it.Current())).GetType() == GeomAbs_Line)
        EXPECT_LE(length(it.Current()), 62.0);
    // Across each slot, halfway along it, the gap is thickness + clearance wide.
    for (const SlotCut& c : d.realization.cuts[k]) {
      if (c.y.hi - c.y.lo < 2) continue;
      const double y = (c.y.lo + c.y.hi) / 2;
      for (const Interval& gap : [&] {
             std::vector<Interval> gaps;
             const auto row = f.outline.intervalsOnLine({0, y}, {1, 0});
             for (size_t i = 0; i + 1 < row.size(); ++i) gaps.push_back({row[i].hi, row[i + 1].lo});
             return gaps;
           }()) {
        if (gap.lo > c.x || gap.hi < c.x) continue;
        EXPECT_NEAR(gap.hi - gap.lo, params.width(), 1e-3);
        ++slotsMeasured;
      }
    }
  }
  EXPECT_GT(slotsMeasured, 4);
}

// Exact patches of a solid with holes, made from section curves: each has the area of the
// slotted polygon the search checked (within the mesh deflection along its outline), and
// every slot the search cut, thickness + clearance wide, is in the exact face.
TEST(ExactPatches, SlottedFacesFromSectionCurvesHaveEverySlot) {
  const std::vector<test::Hole> holes{{30, 40, 12}, {85, 35, 9}};
  const Design d = design(modelFromShape(test::makeBoxWithHoles(120, 80, 60, holes), "box with holes"));
  ASSERT_FALSE(d.faces.empty());
  const SlotParams params;
  int slots = 0;
  for (size_t k = 0; k < d.faces.size(); ++k) {
    SCOPED_TRACE("patch " + std::to_string(k));
    const PatchFace& f = d.faces[k];
    EXPECT_TRUE(f.exact);
    EXPECT_EQ(f.pieces, 1);
    double outline = 0;
    for (const Region2d::Loop& loop : f.outline.loops())
      for (size_t i = 0, j = loop.size() - 1; i < loop.size(); j = i++)
        outline += std::hypot(loop[i].x - loop[j].x, loop[i].y - loop[j].y);
    EXPECT_NEAR(f.outline.area(), d.realization.slotted[k].area(), outline * d.model.meshDeflection + 1e-6);
    int expected = 0, found = 0;
    for (const SlotCut& c : d.realization.cuts[k]) {
      if (c.y.hi - c.y.lo < 2) continue;
      ++expected;
      // Halfway along the slot, the paper has a gap of the slot's width around its line.
      const auto row = f.outline.intervalsOnLine({0, (c.y.lo + c.y.hi) / 2}, {1, 0});
      for (size_t i = 0; i + 1 < row.size(); ++i)
        if (row[i].hi <= c.x && c.x <= row[i + 1].lo &&
            std::abs(row[i + 1].lo - row[i].hi - params.width()) < 1e-3)
          ++found;
    }
    EXPECT_EQ(found, expected);
    slots += found;
  }
  EXPECT_GT(slots, 8);
}

// Mesh sources keep their polygons: one planar face per patch, holes included.
TEST(ExactPatches, PolygonFacesOfAMesh) {
  const Region2d square =
      Region2d::fromLoops({{{0, 0}, {40, 0}, {40, 40}, {0, 40}}, {{10, 10}, {10, 30}, {30, 30}, {30, 10}}});
  const SliceFrame frame = makeSliceFrame({1, 0, 0}, {0, 0, 1});
  const TopoDS_Shape face = facesFromRegion(square, frame, 7);
  GProp_GProps props;
  BRepGProp::SurfaceProperties(face, props);
  EXPECT_NEAR(props.Mass(), 1600 - 400, 1e-6);
  EXPECT_NEAR(props.CentreOfMass().X(), 7, 1e-9);
  int wires = 0;
  for (TopExp_Explorer it(face, TopAbs_WIRE); it.More(); it.Next()) ++wires;
  EXPECT_EQ(wires, 2);
}

// Holes that touch the outer loop or each other at a point (Clipper's output is not strictly
// simple; diplodocus.off in plywood): the face is still one valid face of that polygon, its
// holes kept, not wires that BRepCheck finds intersecting.
TEST(ExactPatches, PolygonFacesWithTouchingHolesAreValid) {
  const Region2d::Loop outer{{0, 0}, {40, 0}, {40, 40}, {0, 40}};
  const Region2d::Loop onEdge{{0, 20}, {5, 21}, {5, 19}};  // touches x = 0 at (0, 20)
  const Region2d::Loop first{{10, 10}, {10, 15}, {15, 15}, {15, 10}};
  const Region2d::Loop second{{15, 15}, {15, 20}, {20, 20}, {20, 15}};  // touches first at (15, 15)
  const Region2d region = Region2d::fromLoops({outer, onEdge, first, second});
  ASSERT_EQ(region.holeCount(), 3);
  const SliceFrame frame = makeSliceFrame({1, 0, 0}, {0, 0, 1});
  const TopoDS_Shape face = facesFromRegion(region, frame, 7);
  EXPECT_TRUE(BRepCheck_Analyzer(face).IsValid());
  int faces = 0;
  for (TopExp_Explorer it(face, TopAbs_FACE); it.More(); it.Next()) ++faces;
  EXPECT_EQ(faces, 1);
  EXPECT_NEAR(area(face), region.area(), 1e-6);
  EXPECT_NEAR(area(face), 1600 - 5 - 25 - 25, 1e-6);
}

// Only sections that add to a cylinder's union are fused: nested and repeated ones are left
// out, shifted ones kept, and the union of those kept is the union of all.
TEST(ExactPatches, OnlySectionsThatAddToTheUnionAreFused) {
  auto square = [](double x, double y, double side) {
    return Region2d::fromLoops({{{x, y}, {x + side, y}, {x + side, y + side}, {x, y + side}}});
  };
  const std::vector<Region2d> sections{square(0, 0, 10),     square(1, 1, 8),  square(0, 0, 10),
                                       square(0, 0, 10.001), square(5, 0, 10), square(2, 2, 3)};
  const std::vector<size_t> kept = sectionsAddingToUnion(sections, 0.01);
  // The largest (10.001) first, then the one shifted by 5; 10 and its copy lie within 0.01
  // of the largest, 8 and 3 inside it.
  EXPECT_EQ(kept, (std::vector<size_t>{3, 4}));
  std::vector<Region2d> taken;
  for (size_t k : kept) taken.push_back(sections[k]);
  EXPECT_NEAR(Region2d::uniteAll(taken).area(), Region2d::uniteAll(sections).area(), 0.05);
  EXPECT_TRUE(sectionsAddingToUnion({}, 0.01).empty());
  // With no tolerance, the 10 mm squares are still inside the 10.001 mm one.
  EXPECT_EQ(sectionsAddingToUnion(sections, 0).size(), 2u);
}

// Crumbs are holes narrower than the width asked all along: a sliver triangle 4 µm wide
// touching the outer loop (stanford-bunny.obj's, after simplification) and a 3 µm dot go;
// a 1 mm hole and a slit 30 µm wide and 3 mm long stay, and a region with no crumb is
// returned as it was.
TEST(ExactPatches, CrumbHolesAreFilledAndRealHolesStay) {
  const Region2d::Loop outer{{0, 0}, {40, 0}, {40, 30}, {0, 30}};
  const Region2d::Loop hole{{10, 10}, {10, 11}, {11, 11}, {11, 10}};        // clockwise
  const Region2d::Loop slit{{20, 10}, {20, 13}, {20.03, 13}, {20.03, 10}};  // 30 µm wide
  const Region2d::Loop sliver{{0, 5}, {0.2, 5}, {0.2, 5.004}};              // 4 µm wide, touches x = 0
  const Region2d::Loop dot{{30, 20}, {30, 20.003}, {30.003, 20.003}, {30.003, 20}};
  const double width = kOutlineDeflection / 4;
  EXPECT_FALSE(isCrumb(hole, width));
  EXPECT_FALSE(isCrumb(slit, width));
  EXPECT_TRUE(isCrumb(sliver, width));
  EXPECT_TRUE(isCrumb(dot, width));
  const Region2d clean = Region2d::fromLoops({outer, hole, slit});
  const Region2d same = withoutCrumbs(clean, width);
  ASSERT_EQ(same.loops().size(), clean.loops().size());
  for (size_t k = 0; k < same.loops().size(); ++k)
    for (size_t i = 0; i < same.loops()[k].size(); ++i) {
      EXPECT_EQ(same.loops()[k][i].x, clean.loops()[k][i].x);
      EXPECT_EQ(same.loops()[k][i].y, clean.loops()[k][i].y);
    }
  const Region2d crumbed = Region2d::fromLoops({outer, hole, slit, sliver, dot});
  EXPECT_EQ(crumbed.holeCount(), 4);
  const Region2d filled = withoutCrumbs(crumbed, width);
  EXPECT_EQ(filled.holeCount(), 2);
  EXPECT_NEAR(filled.area(), clean.area(), 1e-9);
}

// A mesh patch's outline loses the points that add nothing within the tolerance: a circle of
// 2000 points (as a fine scan gives) with a slot and a hole keeps its slot corners, its hole
// and its area, with far fewer points.
TEST(ExactPatches, MeshOutlinesAreSimplifiedWithinTheTolerance) {
  Region2d::Loop outer;
  for (int k = 0; k < 2000; ++k) {
    const double t = 2 * M_PI * k / 2000;
    outer.push_back({30 * std::cos(t), 30 * std::sin(t)});
  }
  const Region2d disc = Region2d::fromLoops({outer});
  const Region2d slot = Region2d::fromLoops({{{-0.2, 10}, {0.2, 10}, {0.2, 40}, {-0.2, 40}}});
  const Region2d hole = Region2d::fromLoops({{{-10, -10}, {-5, -10}, {-5, -5}, {-10, -5}}});
  const Region2d patch = disc.subtract(slot).subtract(hole);
  const Region2d simpler = simplified(patch, 0.01);
  size_t before = 0, after = 0;
  for (const auto& l : patch.loops()) before += l.size();
  for (const auto& l : simpler.loops()) after += l.size();
  EXPECT_LT(after, before / 4);
  EXPECT_EQ(simpler.holeCount(), 1);
  // Nowhere farther than the tolerance: the two differ by less than a 0.01 mm band.
  const double perimeter = 2 * M_PI * 30 + 60 + 20;
  EXPECT_LT(simpler.subtract(patch).area() + patch.subtract(simpler).area(), 0.01 * perimeter);
  EXPECT_TRUE(simpler.subtract(patch.offset(0.011)).empty());
  EXPECT_TRUE(patch.subtract(simpler.offset(0.011)).empty());
  // The slot is still 0.4 mm wide: its corners are kept.
  int slotCorners = 0;
  for (const auto& l : simpler.loops())
    for (const Vec2& p : l)
      slotCorners += std::fabs(std::fabs(p.x) - 0.2) < 1e-6 && std::fabs(p.y - 10) < 1e-6;
  EXPECT_EQ(slotCorners, 2);
}

TEST(ExactPatches, KerfMovesCutPathsAwayFromThePaper) {
  const Region2d square =
      Region2d::fromLoops({{{0, 0}, {40, 0}, {40, 40}, {0, 40}}, {{10, 10}, {10, 30}, {30, 30}, {30, 10}}});
  const SliceFrame frame = makeSliceFrame({1, 0, 0}, {0, 0, 1});
  const TopoDS_Shape path = kerfCompensated(facesFromRegion(square, frame, 0), 0.2);
  std::vector<double> spans;
  for (TopExp_Explorer it(path, TopAbs_WIRE); it.More(); it.Next()) {
    Bnd_Box box;
    BRepBndLib::AddOptimal(it.Current(), box, false, false);
    double x0, y0, z0, x1, y1, z1;
    box.Get(x0, y0, z0, x1, y1, z1);
    spans.push_back(z1 - z0);  // W is z
  }
  std::sort(spans.begin(), spans.end());
  ASSERT_EQ(spans.size(), 2u);
  EXPECT_NEAR(spans[0], 19.8, 1e-6);  // the hole shrinks
  EXPECT_NEAR(spans[1], 40.2, 1e-6);  // the outline grows
  EXPECT_GT(edgesOfType(path, GeomAbs_Circle), 0) << "outer corners become arcs";
}

// Folded almost flat, the patches still touch only at hinge points: every U/V pair of faces
// meets in isolated points, never along a line (but the 2 kRootGap on the hinge line where
// an up slot and a down slot start past their common root: the hinge line stays the
// patches' common line at every fold angle).
TEST(Fold, FoldedTorusHasNoCollisions) {
  const Design d = design(modelFromShape(test::makeTorus(60, 20), "torus"));
  for (double theta : {90.0, 12.0}) {
    std::vector<TopoDS_Shape> placed;
    std::vector<Bnd_Box> boxes;
    for (size_t k = 0; k < d.faces.size(); ++k) {
      placed.push_back(d.faces[k].shape.Moved(TopLoc_Location(foldTransform(d.arrangement, k, theta))));
      Bnd_Box b;
      BRepBndLib::Add(placed.back(), b);
      boxes.push_back(b);
    }
    int pairs = 0;
    for (size_t a = 0; a < placed.size(); ++a) {
      if (d.arrangement.scaffold.patches[a].family != Family::U) continue;
      for (size_t b = 0; b < placed.size(); ++b) {
        if (d.arrangement.scaffold.patches[b].family != Family::V || boxes[a].IsOut(boxes[b])) continue;
        BRepAlgoAPI_Section section(placed[a], placed[b]);
        ASSERT_TRUE(section.IsDone());
        EXPECT_LT(length(section.Shape()), 2 * kRootGap + 1e-6)
            << "theta " << theta << " patches " << a << ", " << b;
        ++pairs;
      }
    }
    EXPECT_GT(pairs, 10);
  }
  // Popped up, the transform changes nothing; folded, U-patches only translate.
  EXPECT_LT(foldTransform(d.arrangement, 0, 90).TranslationPart().Modulus(), 1e-9);
  for (size_t k = 0; k < d.faces.size(); ++k)
    if (d.arrangement.scaffold.patches[k].family == Family::U)
      EXPECT_EQ(foldTransform(d.arrangement, k, 12).Form(), gp_Translation);
}

TEST(Fold, AssemblyIsWrittenAsStepAndBrep) {
  const Design d = design(modelFromShape(test::makeSphere(40), "sphere"), 24);
  test::TempDir dir;
  const TopoDS_Shape all = assemble(d.arrangement, d.faces, 30);
  writeShape(all, dir.file("a.step"));
  writeShape(all, dir.file("a.brep"));
  EXPECT_GT(std::filesystem::file_size(dir.file("a.step")), 1000u);
  EXPECT_GT(std::filesystem::file_size(dir.file("a.brep")), 1000u);
  EXPECT_THROW(writeShape(all, dir.file("a.obj")), Error);
  EXPECT_FALSE(std::filesystem::exists(dir.file("a.obj")));
}

// Adaptive: the fixed Gauss points miss the corners of a degree-1 spline.
double faceArea(const TopoDS_Shape& s) {
  GProp_GProps props;
  BRepGProp::SurfaceProperties(s, props, 1e-9);
  return props.Mass();
}

// A mesh's polygon patch (a disc of 64 sides with a square hole, turned and moved as the
// fold moves it) as one spline edge per loop (what OCCT's writer is given) is the same
// polygon; and the STEP file keeps its straight edges, and reads back as the same face:
// same area (FreeCAD's fixed Gauss points misread a spline loop's), same holes.
TEST(Fold, PolygonLoopsAsSplinesAndInStep) {
  Region2d::Loop disc, hole = {{-5, -5}, {-5, 5}, {5, 5}, {5, -5}};
  for (int i = 0; i < 64; ++i) disc.push_back({30 * std::cos(i * M_PI / 32), 30 * std::sin(i * M_PI / 32)});
  SliceFrame frame;
  frame.normal = {0, 1, 0}, frame.xAxis = {0, 0, 1}, frame.yAxis = {1, 0, 0};
  gp_Trsf moved;
  moved.SetRotation(gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(1, 1, 0)), 0.3);
  moved.SetTranslationPart(gp_Vec(7, -3, 11));
  const TopoDS_Shape face = facesFromRegion(Region2d::fromLoops({disc, hole}), frame, 12).Moved(moved);
  const double area = faceArea(face);
  EXPECT_NEAR(area, 64 * 0.5 * 30 * 30 * std::sin(M_PI / 32) - 100, 1e-3);  // corners on 10 nm
  const TopoDS_Shape splines = polylineLoopsAsSplines(face);
  int edges = 0, wires = 0;
  for (TopExp_Explorer e(splines, TopAbs_EDGE); e.More(); e.Next()) ++edges;
  for (TopExp_Explorer w(splines, TopAbs_WIRE); w.More(); w.Next()) ++wires;
  EXPECT_EQ(edges, 2);
  EXPECT_EQ(wires, 2);
  EXPECT_NEAR(faceArea(splines), area, 1e-6);
  test::TempDir dir;
  writeShape(face, dir.file("p.step"));
  STEPControl_Reader reader;
  ASSERT_EQ(reader.ReadFile(dir.file("p.step").c_str()), IFSelect_RetDone);
  reader.TransferRoots();
  const TopoDS_Shape back = reader.OneShape();
  EXPECT_NEAR(faceArea(back), area, 1e-3);
  GProp_GProps fixed;
  BRepGProp::SurfaceProperties(back, fixed);
  EXPECT_NEAR(fixed.Mass(), area, 1e-3);
  wires = edges = 0;
  for (TopExp_Explorer w(back, TopAbs_WIRE); w.More(); w.Next()) ++wires;
  for (TopExp_Explorer e(back, TopAbs_EDGE); e.More(); e.Next()) ++edges;
  EXPECT_EQ(wires, 2);
  EXPECT_EQ(edges, 64 + 4);
}

// The STEP writer's settings are OCCT's process-wide statics, which in FreeCAD are FreeCAD's
// export settings too: writing the assembly leaves every one of them as it found it (here set
// to values the writer itself changes), yet writes its own AP214 in millimetres (OCCT 7.8.1
// crashes writing AP203).
TEST(Fold, StepWriterLeavesOcctsGlobalSettingsAsTheyWere) {
  const Design d = design(modelFromShape(test::makeSphere(40), "sphere"), 12);
  test::TempDir dir;
  // A curved face among the patches: only OCCT's writer writes it (planarFacesStep).
  TopoDS_Compound all;
  BRep_Builder builder;
  builder.MakeCompound(all);
  builder.Add(all, assemble(d.arrangement, d.faces, 60));
  for (TopExp_Explorer f(BRepPrimAPI_MakeCylinder(5, 10).Shape(), TopAbs_FACE); f.More(); f.Next())
    if (BRep_Tool::Surface(TopoDS::Face(f.Current()))->DynamicType() != STANDARD_TYPE(Geom_Plane))
      builder.Add(all, f.Current());
  writeShape(all, dir.file("first.step"));  // the STEP statics exist from here on
  const StaticsRestorer asTheOtherTestsHadThem;
  ASSERT_TRUE(Interface_Static::SetCVal("write.step.unit", "INCH"));
  ASSERT_TRUE(Interface_Static::SetIVal("write.surfacecurve.mode", 1));
  ASSERT_TRUE(Interface_Static::SetCVal("write.step.schema", "AP203"));
  const StaticsSnapshot before;
  EXPECT_GT(before.describe().size(), 20u);
  writeShape(all, dir.file("a.step"));
  EXPECT_EQ(StaticsSnapshot().describe(), before.describe());
  EXPECT_STREQ(Interface_Static::CVal("write.step.unit"), "INCH");
  EXPECT_EQ(Interface_Static::IVal("write.surfacecurve.mode"), 1);
  std::ifstream in(dir.file("a.step"));
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  EXPECT_NE(text.find("Open CASCADE"), std::string::npos);  // OCCT's writer wrote it
  EXPECT_NE(text.find(".MILLI.,.METRE."), std::string::npos);
  EXPECT_NE(text.find("AUTOMOTIVE_DESIGN"), std::string::npos);  // AP214, not the statics' AP203
  EXPECT_EQ(text.find(".INCH."), std::string::npos);
  EXPECT_EQ(text.find("PCURVE"), std::string::npos);
  // A snapshot puts back what changed after it, and says how many it put back.
  const StaticsSnapshot saved;
  Interface_Static::SetIVal("write.surfacecurve.mode", 0);
  Interface_Static::SetCVal("write.step.unit", "M");
  EXPECT_EQ(saved.restore(), 2);
  EXPECT_EQ(saved.restore(), 0);
  EXPECT_EQ(StaticsSnapshot().describe(), before.describe());
}

}  // namespace
}  // namespace sliceform

namespace sliceform {
namespace {

// A face's area against a bound, read from its polygon where the polygon's error cannot
// decide: a disc of radius 1, its polygon 0.04 mm² short of pi within the outline's
// deflection. Near pi the surface integration decides, so the answer is the exact one.
TEST(ExactPatches, AreaAtLeastIsTheExactAreasAnswer) {
  const gp_Circ circle(gp_Ax2(gp_Pnt(3, 4, 0), gp_Dir(0, 0, 1)), 1);
  const TopoDS_Face disc =
      BRepBuilderAPI_MakeFace(gp_Pln(gp::XOY()), BRepBuilderAPI_MakeWire(BRepBuilderAPI_MakeEdge(circle)));
  const Region2d polygon = facePolygons(disc, makeSliceFrame({0, 0, 1}), kOutlineDeflection).front();
  ASSERT_LT(polygon.area(), M_PI - 0.02);
  EXPECT_TRUE(areaAtLeast(disc, polygon, 1));
  EXPECT_FALSE(areaAtLeast(disc, polygon, 10));
  for (int k = -10; k < 10; ++k) {  // bounds 2.5 µm² and more from pi
    const double least = M_PI + 0.005 * k + 0.0025;
    EXPECT_EQ(areaAtLeast(disc, polygon, least), M_PI >= least) << least;
  }
}

}  // namespace
}  // namespace sliceform
