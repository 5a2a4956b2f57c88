// SPDX-License-Identifier: LGPL-2.1-or-later
// The assembly's STEP text (planarFacesStep) read back by OCCT's reader: the same faces,
// placed where they were, bounded by the same kinds of curves.
#include <gtest/gtest.h>

#include <BRepAdaptor_Curve.hxx>
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
#include <ElCLib.hxx>
#include <GProp_GProps.hxx>
#include <GeomAPI_Interpolate.hxx>
#include <GeomConvert.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_Circle.hxx>
#include <Geom_Plane.hxx>
#include <STEPControl_Reader.hxx>
#include <TColgp_HArray1OfPnt.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <gp_Elips.hxx>
#include <gp_Hypr.hxx>
#include <gp_Parab.hxx>
#include <gp_Pln.hxx>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <iterator>
#include <map>

#include "assembly/fold.hpp"
#include "assembly/step_text.hpp"
#include "test_support.hpp"

namespace sliceform {
namespace {

TopoDS_Wire wireOf(std::initializer_list<TopoDS_Edge> edges) {
  BRepBuilderAPI_MakeWire w;
  for (const TopoDS_Edge& e : edges) w.Add(e);
  return w.Wire();
}

// The faces the file must carry: straight sides with a round and an elliptic hole; a
// hyperbola's and a parabola's arcs closed by lines (the second face turned over); a
// rational B-spline circle with a periodic B-spline hole; and a plane whose axes are
// left-handed. Each is placed by a turn and a shift.
std::vector<TopoDS_Face> faces() {
  std::vector<TopoDS_Face> out;
  const gp_Ax2 xy(gp_Pnt(0, 0, 0), gp::DZ(), gp::DX());
  {
    BRepBuilderAPI_MakeFace f(gp_Pln(xy),
                              BRepBuilderAPI_MakePolygon(gp_Pnt(0, 0, 0), gp_Pnt(40, 0, 0), gp_Pnt(40, 30, 0),
                                                         gp_Pnt(0, 30, 0), true)
                                  .Wire());
    TopoDS_Wire round =
        wireOf({BRepBuilderAPI_MakeEdge(gp_Circ(gp_Ax2(gp_Pnt(10, 10, 0), gp::DZ()), 4)).Edge()});
    TopoDS_Wire oval =
        wireOf({BRepBuilderAPI_MakeEdge(gp_Elips(gp_Ax2(gp_Pnt(27, 15, 0), gp::DZ(), gp_Dir(1, 1, 0)), 6, 3))
                    .Edge()});
    f.Add(TopoDS::Wire(round.Reversed()));
    f.Add(TopoDS::Wire(oval.Reversed()));
    out.push_back(f.Face());
  }
  {
    const gp_Hypr h(xy, 3, 2);
    const TopoDS_Edge arc = BRepBuilderAPI_MakeEdge(h, -1.2, 1.3).Edge();
    const gp_Pnt a = ElCLib::Value(-1.2, h), b = ElCLib::Value(1.3, h);
    out.push_back(
        BRepBuilderAPI_MakeFace(gp_Pln(xy), wireOf({arc, BRepBuilderAPI_MakeEdge(b, a).Edge()})).Face());
  }
  {
    const gp_Parab p(xy, 2);
    const TopoDS_Edge arc = BRepBuilderAPI_MakeEdge(p, -4, 5).Edge();
    const gp_Pnt a = ElCLib::Value(-4, p), b = ElCLib::Value(5, p);
    out.push_back(
        TopoDS::Face(BRepBuilderAPI_MakeFace(gp_Pln(xy), wireOf({arc, BRepBuilderAPI_MakeEdge(b, a).Edge()}))
                         .Face()
                         .Reversed()));
  }
  {
    const Handle(Geom_BSplineCurve) rim =
        GeomConvert::CurveToBSplineCurve(new Geom_Circle(gp_Ax2(gp_Pnt(0, 0, 0), gp::DZ()), 20));
    const Handle(TColgp_HArray1OfPnt) points = new TColgp_HArray1OfPnt(1, 5);
    const double xs[] = {-5, 4, 7, 1, -6}, ys[] = {-4, -6, 2, 8, 3};
    for (int i = 0; i < 5; ++i) points->SetValue(i + 1, gp_Pnt(xs[i], ys[i], 0));
    GeomAPI_Interpolate through(points, true, 1e-7);
    through.Perform();
    BRepBuilderAPI_MakeFace f(gp_Pln(xy), wireOf({BRepBuilderAPI_MakeEdge(rim).Edge()}));
    f.Add(TopoDS::Wire(wireOf({BRepBuilderAPI_MakeEdge(through.Curve()).Edge()}).Reversed()));
    out.push_back(f.Face());
  }
  {
    gp_Ax3 left(gp_Pnt(0, 0, 2), gp::DZ(), gp::DX());
    left.YReverse();
    const Handle(Geom_Plane) plane = new Geom_Plane(left);
    out.push_back(BRepBuilderAPI_MakeFace(plane, 0, 12, 0, 7, 1e-7).Face());
  }
  for (size_t k = 0; k < out.size(); ++k) {
    gp_Trsf t;
    t.SetRotation(gp_Ax1(gp_Pnt(1, 2, 3), gp_Dir(1, 0.5 * k, 2)), 0.4 + 0.3 * k);
    t.SetTranslationPart(gp_Vec(10.0 * k, -3, 7));
    out[k] = TopoDS::Face(out[k].Moved(TopLoc_Location(t)));
  }
  return out;
}

TopoDS_Compound compoundOf(const std::vector<TopoDS_Face>& faces) {
  TopoDS_Compound all;
  BRep_Builder b;
  b.MakeCompound(all);
  for (const TopoDS_Face& f : faces) b.Add(all, f);
  return all;
}

// What a reader must find of a face: its area (adaptive integration), its normal where its
// centre projects, its box, and its edges by the kind of their curves.
struct Seen {
  double area;
  gp_Dir normal;
  std::array<double, 6> box;
  std::map<int, int> kinds;
};

Seen seen(const TopoDS_Face& f) {
  Seen s;
  GProp_GProps props;
  BRepGProp::SurfaceProperties(f, props, 1e-9);
  s.area = props.Mass();
  const Handle(Geom_Plane) plane = Handle(Geom_Plane)::DownCast(BRep_Tool::Surface(f));
  EXPECT_FALSE(plane.IsNull());
  gp_Dir n = plane.IsNull() ? gp::DZ() : plane->Pln().Axis().Direction();
  if (!plane.IsNull() && !plane->Position().Direct()) n.Reverse();
  if (f.Orientation() == TopAbs_REVERSED) n.Reverse();
  s.normal = n;
  Bnd_Box box;
  BRepBndLib::AddOptimal(f, box, false, false);
  box.Get(s.box[0], s.box[1], s.box[2], s.box[3], s.box[4], s.box[5]);
  for (TopExp_Explorer e(f, TopAbs_EDGE); e.More(); e.Next())
    ++s.kinds[BRepAdaptor_Curve(TopoDS::Edge(e.Current())).GetType()];
  return s;
}

std::vector<TopoDS_Face> readBack(const std::string& path) {
  STEPControl_Reader reader;
  EXPECT_EQ(reader.ReadFile(path.c_str()), IFSelect_RetDone);
  reader.TransferRoots();
  std::vector<TopoDS_Face> out;
  for (TopExp_Explorer f(reader.OneShape(), TopAbs_FACE); f.More(); f.Next())
    out.push_back(TopoDS::Face(f.Current()));
  return out;
}

TEST(StepText, ReadsBackAsTheFacesPlaced) {
  const std::vector<TopoDS_Face> given = faces();
  std::string text;
  ASSERT_TRUE(planarFacesStep(compoundOf(given), text));
  EXPECT_NE(text.find("PRODUCT('patch 5','patch 5'"), std::string::npos);  // no names given
  // The parts named as the patches, an apostrophe written twice.
  const std::vector<std::string> names{"U0", "V1", "U2", "V3", "it's"};
  ASSERT_TRUE(planarFacesStep(compoundOf(given), text, names));
  EXPECT_NE(text.find("PRODUCT('V3','V3'"), std::string::npos);
  EXPECT_NE(text.find("PRODUCT('it''s','it''s'"), std::string::npos);
  EXPECT_EQ(text.find("patch 5"), std::string::npos);
  test::TempDir dir;
  writeShape(compoundOf(given), dir.file("a.step"), names);
  std::ifstream in(dir.file("a.step"));
  const std::string file{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  EXPECT_NE(file.find("Sliceform assembly"), std::string::npos);  // our writer's, not OCCT's
  EXPECT_NE(file.find(".MILLI.,.METRE."), std::string::npos);
  const std::vector<TopoDS_Face> back = readBack(dir.file("a.step"));
  ASSERT_EQ(back.size(), given.size());
  for (size_t k = 0; k < given.size(); ++k) {
    SCOPED_TRACE("face " + std::to_string(k));
    EXPECT_TRUE(BRepCheck_Analyzer(back[k]).IsValid());
    const Seen a = seen(given[k]), b = seen(back[k]);
    EXPECT_NEAR(b.area, a.area, 1e-6 * a.area);
    EXPECT_GT(a.normal.Dot(b.normal), 1 - 1e-9) << "turned over";
    for (int i = 0; i < 6; ++i) EXPECT_NEAR(b.box[i], a.box[i], 1e-6);
    EXPECT_EQ(b.kinds, a.kinds);
  }
}

// What it does not write as OCCT would is left to OCCT's writer: a curved face.
TEST(StepText, LeavesWhatItDoesNotWriteToOcct) {
  std::string text = "x";
  const TopoDS_Shape cylinder = BRepPrimAPI_MakeCylinder(5, 10).Shape();
  TopoDS_Face side;
  for (TopExp_Explorer f(cylinder, TopAbs_FACE); f.More(); f.Next())
    if (BRep_Tool::Surface(TopoDS::Face(f.Current()))->DynamicType() != STANDARD_TYPE(Geom_Plane))
      side = TopoDS::Face(f.Current());
  ASSERT_FALSE(side.IsNull());
  EXPECT_FALSE(planarFacesStep(compoundOf({side}), text));
  EXPECT_TRUE(text.empty());
  // Written all the same, by OCCT.
  test::TempDir dir;
  writeShape(compoundOf({side}), dir.file("c.step"));
  EXPECT_EQ(readBack(dir.file("c.step")).size(), 1u);
}

}  // namespace
}  // namespace sliceform
