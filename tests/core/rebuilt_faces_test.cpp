// SPDX-License-Identifier: LGPL-2.1-or-later
// Faces rebuilt from exact section edges (exact/rebuilt_faces): unions and slotted sections
// keep their arcs and the Boolean's area, runs meet where their curves cross, and every face
// passes BRepCheck.
#include <gtest/gtest.h>

#include <BRepAdaptor_Curve.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakePolygon.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRep_Tool.hxx>
#include <Geom_Hyperbola.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <gp_Circ.hxx>
#include <gp_Hypr.hxx>
#include <gp_Pln.hxx>

#include <cmath>
#include <vector>

#include "exact/rebuilt_faces.hpp"
#include "slicing/brep_slicer.hpp"
#include "test_support.hpp"

namespace sliceform {
namespace {

using test::area;

// The union of planar `sections` on the plane z = 0, rebuilt from their exact edges.
TopoDS_Shape rebuiltUnion(const std::vector<TopoDS_Shape>& sections, double deflection) {
  return rebuiltFaces(
      sections, [](const std::vector<Region2d>& p) { return Region2d::uniteAll(p); },
      makeSliceFrame({0, 0, 1}, {0, 1, 0}), 0, deflection);
}

// A cylinder's section rebuilt from its slices' exact edges: the union of two discs and of a
// 128-gon whose corners stand 0.5 µm outside the first disc (as the sections of neighbouring
// slices cross each other, within 2 deflections) is two circular arcs, not a run along every
// corner of the polygon, and has the Boolean fuse's area.
TEST(RebuiltFaces, UnionOfSectionsKeepsArcsAndTheFusedArea) {
  const gp_Pln plane(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1));
  const auto disc = [&](double x, double r) {
    const gp_Circ circle(gp_Ax2(gp_Pnt(x, 0, 0), gp_Dir(0, 0, 1)), r);
    return BRepBuilderAPI_MakeFace(plane, BRepBuilderAPI_MakeWire(BRepBuilderAPI_MakeEdge(circle)).Wire())
        .Face();
  };
  BRepBuilderAPI_MakePolygon corners;
  const int n = 128;
  const double corner = 10.0005;  // its edges dip 2.5 µm inside the disc, its corners stand out
  for (int k = 0; k < n; ++k)
    corners.Add(gp_Pnt(corner * std::cos(2 * M_PI * k / n), corner * std::sin(2 * M_PI * k / n), 0));
  corners.Close();
  const std::vector<TopoDS_Shape> sections{disc(0, 10), disc(12, 10),
                                           BRepBuilderAPI_MakeFace(plane, corners.Wire()).Face()};
  const SliceFrame frame = makeSliceFrame({0, 0, 1}, {0, 1, 0});
  const double deflection = 1e-3;
  const TopoDS_Shape rebuilt = rebuiltUnion(sections, deflection);
  ASSERT_FALSE(rebuilt.IsNull());
  EXPECT_TRUE(BRepCheck_Analyzer(rebuilt).IsValid());
  int faces = 0, edges = 0;
  for (TopExp_Explorer f(rebuilt, TopAbs_FACE); f.More(); f.Next()) ++faces;
  for (TopExp_Explorer e(rebuilt, TopAbs_EDGE); e.More(); e.Next()) {
    ++edges;
    EXPECT_EQ(BRepAdaptor_Curve(TopoDS::Edge(e.Current())).GetType(), GeomAbs_Circle);
  }
  EXPECT_EQ(faces, 1);
  EXPECT_LE(edges, 8);  // the two arcs, in a few pieces where runs met (186 edges unmerged)
  for (TopExp_Explorer v(rebuilt, TopAbs_VERTEX); v.More(); v.Next())
    EXPECT_LT(BRep_Tool::Tolerance(TopoDS::Vertex(v.Current())), 1e-5);  // the crossings are exact
  BRepAlgoAPI_Fuse fuse(sections[0], sections[1]);
  // The corners left out lie within 2 deflections of the arc: at most 2e-3 times its length.
  EXPECT_NEAR(area(rebuilt), area(fuse.Shape()), 2 * deflection * 2 * M_PI * 10);
  EXPECT_NEAR(area(rebuilt), area(fuse.Shape()), 1e-3);  // in fact far less: 128 specks
  // Sources whose union runs along no edge of theirs (a region from elsewhere): no answer.
  const TopoDS_Shape stray = rebuiltFaces(
      sections,
      [](const std::vector<Region2d>&) {
        return Region2d::fromLoops({{{0, 0}, {1, 0}, {0, 1}}});
      },
      frame, 0, deflection);
  EXPECT_TRUE(stray.IsNull());
}

// Slots cut from a section by the same rebuild: a disc with a round hole, one slot from
// the top and one from the bottom. The face keeps its arcs (two of the outer circle, the
// hole's circle whole) and each slot's three straight edges, with the Boolean cut's area.
// A disc whose edge's vertex lies off its curve (as sections' vertices do, within their
// tolerance) is rebuilt too.
TEST(RebuiltFaces, SlotsCutFromASectionKeepItsArcs) {
  const gp_Pln plane(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1));
  const auto circle = [](double r) {
    return BRepBuilderAPI_MakeEdge(gp_Circ(gp_Ax2(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), r)).Edge();
  };
  BRepBuilderAPI_MakeFace disc(plane, BRepBuilderAPI_MakeWire(circle(10)).Wire());
  disc.Add(TopoDS::Wire(BRepBuilderAPI_MakeWire(circle(3)).Wire().Reversed()));
  ASSERT_TRUE(disc.IsDone());
  const auto rectangle = [&](double x0, double y0, double x1, double y1) {
    BRepBuilderAPI_MakePolygon p(gp_Pnt(x0, y0, 0), gp_Pnt(x1, y0, 0), gp_Pnt(x1, y1, 0), gp_Pnt(x0, y1, 0),
                                 Standard_True);
    return BRepBuilderAPI_MakeFace(plane, p.Wire()).Face();
  };
  TopoDS_Compound slots;
  BRep_Builder builder;
  builder.MakeCompound(slots);
  builder.Add(slots, rectangle(-0.2, 5, 0.2, 11));
  builder.Add(slots, rectangle(-0.2, -11, 0.2, -5));
  const SliceFrame frame = makeSliceFrame({0, 0, 1}, {0, 1, 0});
  const double deflection = 1e-3;
  const auto cut = [&](const TopoDS_Shape& section) {
    return rebuiltFaces(
        {section, slots}, [](const std::vector<Region2d>& p) { return p[0].subtract(p[1]); }, frame, 0,
        deflection);
  };
  const TopoDS_Shape rebuilt = cut(disc.Face());
  ASSERT_FALSE(rebuilt.IsNull());
  EXPECT_TRUE(BRepCheck_Analyzer(rebuilt).IsValid());
  int faces = 0, lines = 0, arcs = 0;
  for (TopExp_Explorer f(rebuilt, TopAbs_FACE); f.More(); f.Next()) ++faces;
  for (TopExp_Explorer e(rebuilt, TopAbs_EDGE); e.More(); e.Next()) {
    const GeomAbs_CurveType type = BRepAdaptor_Curve(TopoDS::Edge(e.Current())).GetType();
    lines += type == GeomAbs_Line;
    arcs += type == GeomAbs_Circle;
  }
  EXPECT_EQ(faces, 1);
  EXPECT_EQ(lines, 6);
  EXPECT_EQ(arcs, 3);
  for (TopExp_Explorer v(rebuilt, TopAbs_VERTEX); v.More(); v.Next())
    EXPECT_LT(BRep_Tool::Tolerance(TopoDS::Vertex(v.Current())), 1e-5);
  BRepAlgoAPI_Cut boolean(disc.Face(), slots);
  EXPECT_NEAR(area(rebuilt), area(boolean.Shape()), 1e-6);
  // The outer circle's vertex moved 20 µm off it, within a tolerance that covers it: the
  // polygons run from edge to edge through the vertex, and the cut is still rebuilt.
  TopoDS_Edge outer = circle(10);
  TopoDS_Vertex v0, v1;
  TopExp::Vertices(outer, v0, v1);
  builder.UpdateVertex(v0, gp_Pnt(10.00002, 0, 0), 3e-5);
  const TopoDS_Shape off = cut(BRepBuilderAPI_MakeFace(plane, BRepBuilderAPI_MakeWire(outer).Wire()).Face());
  ASSERT_FALSE(off.IsNull());
  const TopoDS_Face whole = BRepBuilderAPI_MakeFace(plane, BRepBuilderAPI_MakeWire(circle(10)).Wire()).Face();
  EXPECT_NEAR(area(off), area(BRepAlgoAPI_Cut(whole, slots).Shape()), 1e-3);
}

// Slots cut across a nearly straight hyperbola, as a cone's section far from its vertex
// is (occt-misc Top.brep). Its polygon has 3 points over 50 mm, and a parameter
// interpolated along a segment lay up to a millimetre off the point on the curve, too far
// for the slots' crossings to be refined: the rebuild gave up, and every such patch went
// to the Boolean cut. The crossings now lie on both curves, and the face is the Boolean's.
TEST(RebuiltFaces, SlotsCutAcrossANearlyStraightHyperbolaMeetItOnTheCurve) {
  const gp_Pln plane(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1));
  const double a = 4.47, b = 3.72, t0 = 2.58, t1 = 3.42;
  const Handle(Geom_Curve) hyperbola =
      new Geom_Hyperbola(gp_Hypr(gp_Ax2(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), a, b));
  const gp_Pnt p0 = hyperbola->Value(t0), p1 = hyperbola->Value(t1);
  const gp_Vec inward(0.64 * 15, -0.77 * 15, 0);  // across the asymptote, to the branch's inside
  const gp_Pnt q0 = p0.Translated(inward), q1 = p1.Translated(inward);
  BRepBuilderAPI_MakeWire outline(
      BRepBuilderAPI_MakeEdge(hyperbola, t0, t1).Edge(), BRepBuilderAPI_MakeEdge(p1, q1).Edge(),
      BRepBuilderAPI_MakeEdge(q1, q0).Edge(), BRepBuilderAPI_MakeEdge(q0, p0).Edge());
  ASSERT_TRUE(outline.IsDone());
  const TopoDS_Face section = BRepBuilderAPI_MakeFace(plane, outline.Wire()).Face();
  TopoDS_Compound slots;
  BRep_Builder builder;
  builder.MakeCompound(slots);
  for (int k = 1; k <= 5; ++k) {  // upright slots, 0.5 mm wide, from outside to 6 mm in
    const double x = p0.X() + (p1.X() - p0.X()) * k / 6, y = b * std::sinh(std::acosh(x / a));
    BRepBuilderAPI_MakePolygon p(gp_Pnt(x - 0.25, y - 6, 0), gp_Pnt(x + 0.25, y - 6, 0),
                                 gp_Pnt(x + 0.25, y + 3, 0), gp_Pnt(x - 0.25, y + 3, 0), Standard_True);
    builder.Add(slots, BRepBuilderAPI_MakeFace(plane, p.Wire()).Face());
  }
  const SliceFrame frame = makeSliceFrame({0, 0, 1}, {0, 1, 0});
  const TopoDS_Shape rebuilt = rebuiltFaces(
      {section, slots}, [](const std::vector<Region2d>& p) { return p[0].subtract(p[1]); }, frame, 0, 0.0244);
  ASSERT_FALSE(rebuilt.IsNull());
  EXPECT_TRUE(BRepCheck_Analyzer(rebuilt).IsValid());
  int pieces = 0;
  for (TopExp_Explorer e(rebuilt, TopAbs_EDGE); e.More(); e.Next())
    pieces += BRepAdaptor_Curve(TopoDS::Edge(e.Current())).GetType() == GeomAbs_Hyperbola;
  EXPECT_EQ(pieces, 6);
  for (TopExp_Explorer v(rebuilt, TopAbs_VERTEX); v.More(); v.Next())
    EXPECT_LT(BRep_Tool::Tolerance(TopoDS::Vertex(v.Current())), 1e-5);
  EXPECT_NEAR(area(rebuilt), area(BRepAlgoAPI_Cut(section, slots).Shape()), 1e-4);
}

// Two curves that cross on a third: the union of a rectangle below the x axis and two
// discs whose circles both meet the axis at the origin, at right angles, touching each
// other there. Each circle's polygon crosses the axis a little beside the origin, so the
// union's polygon runs a few micrometres along the rectangle's edge between them; the exact
// crossings both lie at the origin, and that run has no length. The rebuild drops it and
// joins the circles (occt-misc Motor-c.brep: two ellipses on a slot's wall; the patch went
// to the Boolean fuse).
TEST(RebuiltFaces, ARunTheCrossingsLeaveNoLengthIsDropped) {
  const gp_Pln plane(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1));
  const auto disc = [&](double x) {  // the seam away from the origin: no polygon vertex there
    const gp_Circ circle(gp_Ax2(gp_Pnt(x, 0, 0), gp_Dir(0, 0, 1), gp_Dir(0, 1, 0)), 5);
    return BRepBuilderAPI_MakeFace(plane, BRepBuilderAPI_MakeWire(BRepBuilderAPI_MakeEdge(circle)).Wire())
        .Face();
  };
  BRepBuilderAPI_MakePolygon below(gp_Pnt(-12, -8, 0), gp_Pnt(12, -8, 0), gp_Pnt(12, 0, 0), gp_Pnt(-12, 0, 0),
                                   Standard_True);
  const std::vector<TopoDS_Shape> sections{BRepBuilderAPI_MakeFace(plane, below.Wire()).Face(), disc(-5),
                                           disc(5)};
  const double deflection = 1e-3;
  const TopoDS_Shape rebuilt = rebuiltUnion(sections, deflection);
  ASSERT_FALSE(rebuilt.IsNull());
  EXPECT_TRUE(BRepCheck_Analyzer(rebuilt).IsValid());
  // Every straight edge is a stretch of the rectangle's outline more than a micrometre long,
  // and the circles meet at the origin.
  for (TopExp_Explorer e(rebuilt, TopAbs_EDGE); e.More(); e.Next()) {
    const BRepAdaptor_Curve curve(TopoDS::Edge(e.Current()));
    if (curve.GetType() != GeomAbs_Line) continue;
    EXPECT_GT(curve.Value(curve.FirstParameter()).Distance(curve.Value(curve.LastParameter())), 1e-3);
  }
  bool origin = false;
  for (TopExp_Explorer v(rebuilt, TopAbs_VERTEX); v.More(); v.Next()) {
    const TopoDS_Vertex& vertex = TopoDS::Vertex(v.Current());
    origin = origin || BRep_Tool::Pnt(vertex).Distance(gp_Pnt(0, 0, 0)) < 1e-6;
    EXPECT_LT(BRep_Tool::Tolerance(vertex), 1e-5);
  }
  EXPECT_TRUE(origin);
  const TopoDS_Shape fused =
      BRepAlgoAPI_Fuse(BRepAlgoAPI_Fuse(sections[0], sections[1]).Shape(), sections[2]).Shape();
  EXPECT_NEAR(area(rebuilt), area(fused), 1e-4);
}

// A crossing at a shallow angle: a rectangle's top edge and a large circle that rises
// 0.38 mm above it, meeting it at 5°. Each polygon lies within the deflection of its curve,
// so the polygons cross 0.6 mm along the edge from where the curves do: further than ten
// deflections. The edges still end where the curves cross, and the face's wire does not
// cross itself (occt-misc Ball.brep: a section's circle meets a slot's wall at 5°; the
// faces trimmed at the polygons' crossing failed BRepCheck as self-intersecting).
TEST(RebuiltFaces, AShallowCrossingIsWhereTheCurvesCross) {
  const gp_Pln plane(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1));
  const double radius = 100, rise = radius * (1 - std::cos(5 * M_PI / 180));
  const gp_Circ circle(gp_Ax2(gp_Pnt(0, rise - radius, 0), gp_Dir(0, 0, 1), gp_Dir(0, -1, 0)), radius);
  const TopoDS_Face disc =
      BRepBuilderAPI_MakeFace(plane, BRepBuilderAPI_MakeWire(BRepBuilderAPI_MakeEdge(circle)).Wire()).Face();
  BRepBuilderAPI_MakePolygon box(gp_Pnt(-20, -8, 0), gp_Pnt(20, -8, 0), gp_Pnt(20, 0, 0), gp_Pnt(-20, 0, 0),
                                 Standard_True);
  const std::vector<TopoDS_Shape> sections{BRepBuilderAPI_MakeFace(plane, box.Wire()).Face(), disc};
  const double deflection = 0.025;
  const TopoDS_Shape rebuilt = rebuiltUnion(sections, deflection);
  ASSERT_FALSE(rebuilt.IsNull());
  EXPECT_TRUE(BRepCheck_Analyzer(rebuilt).IsValid());
  // The circle meets the top edge at x = ±R sin 5°, y = 0: a vertex there, tight.
  const double x = radius * std::sin(5 * M_PI / 180);
  int crossings = 0;
  for (TopExp_Explorer v(rebuilt, TopAbs_VERTEX); v.More(); v.Next()) {
    const TopoDS_Vertex& vertex = TopoDS::Vertex(v.Current());
    const gp_Pnt p = BRep_Tool::Pnt(vertex);
    crossings += std::abs(std::abs(p.X()) - x) < 1e-6 && std::abs(p.Y()) < 1e-6;
    EXPECT_LT(BRep_Tool::Tolerance(vertex), 1e-5);
  }
  EXPECT_EQ(crossings, 2 * 2);  // each crossing is the vertex of two edges
  EXPECT_NEAR(area(rebuilt), area(BRepAlgoAPI_Fuse(sections[0], sections[1]).Shape()), 1e-4);
}

}  // namespace
}  // namespace sliceform
