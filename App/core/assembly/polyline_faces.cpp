// SPDX-License-Identifier: LGPL-2.1-or-later
#include "assembly/polyline_faces.hpp"

#include <BRepAdaptor_Curve.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepTools.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_Plane.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Wire.hxx>

#include <optional>
#include <vector>

namespace sliceform {
namespace {

constexpr int kMinEdgesPerLoop = 8;

// The loop's corners in order, as the face sees it; none if an edge is not straight.
std::optional<std::vector<gp_Pnt>> corners(const TopoDS_Wire& wire, const TopoDS_Face& face) {
  std::vector<gp_Pnt> points;
  for (BRepTools_WireExplorer e(wire, face); e.More(); e.Next()) {
    if (BRepAdaptor_Curve(e.Current()).GetType() != GeomAbs_Line) return std::nullopt;
    points.push_back(BRep_Tool::Pnt(e.CurrentVertex()));
  }
  return points;
}

// A closed degree-1 B-spline through `points`, one knot per corner: the polygon itself.
TopoDS_Wire splineLoop(const std::vector<gp_Pnt>& points) {
  const int n = static_cast<int>(points.size());
  TColgp_Array1OfPnt poles(1, n + 1);
  for (int i = 0; i < n; ++i) poles(i + 1) = points[i];
  poles(n + 1) = points[0];
  TColStd_Array1OfReal knots(1, n + 1);
  TColStd_Array1OfInteger mults(1, n + 1);
  for (int i = 0; i <= n; ++i) knots(i + 1) = i, mults(i + 1) = 1;
  mults(1) = mults(n + 1) = 2;
  const Handle(Geom_BSplineCurve) curve = new Geom_BSplineCurve(poles, knots, mults, 1);
  return BRepBuilderAPI_MakeWire(BRepBuilderAPI_MakeEdge(curve).Edge()).Wire();
}

// The face rebuilt with one spline edge per loop; none if it is not a polygon worth it.
std::optional<TopoDS_Face> splineFace(const TopoDS_Face& original) {
  const TopoDS_Face face = TopoDS::Face(original.Oriented(TopAbs_FORWARD));
  const Handle(Geom_Plane) plane = Handle(Geom_Plane)::DownCast(BRep_Tool::Surface(face));
  if (plane.IsNull()) return std::nullopt;
  std::vector<std::vector<gp_Pnt>> loops;
  size_t edges = 0;
  const TopoDS_Wire outer = BRepTools::OuterWire(face);
  if (outer.IsNull()) return std::nullopt;
  for (TopExp_Explorer w(face, TopAbs_WIRE); w.More(); w.Next()) {
    std::optional<std::vector<gp_Pnt>> points = corners(TopoDS::Wire(w.Current()), face);
    if (!points || points->size() < 3) return std::nullopt;
    edges += points->size();
    // The outer loop first, as MakeFace takes it.
    if (w.Current().IsSame(outer))
      loops.insert(loops.begin(), std::move(*points));
    else
      loops.push_back(std::move(*points));
  }
  if (edges < kMinEdgesPerLoop * loops.size()) return std::nullopt;
  BRepBuilderAPI_MakeFace make(plane->Pln(), splineLoop(loops.front()));
  for (size_t k = 1; k < loops.size(); ++k) make.Add(splineLoop(loops[k]));
  if (!make.IsDone()) return std::nullopt;
  return TopoDS::Face(make.Face().Oriented(original.Orientation()));
}

}  // namespace

TopoDS_Shape polylineLoopsAsSplines(const TopoDS_Shape& shape) {
  BRep_Builder builder;
  TopoDS_Compound out;
  builder.MakeCompound(out);
  for (TopExp_Explorer f(shape, TopAbs_FACE); f.More(); f.Next()) {
    const TopoDS_Face& face = TopoDS::Face(f.Current());
    const std::optional<TopoDS_Face> spline = splineFace(face);
    builder.Add(out, spline ? *spline : face);
  }
  return out;
}

}  // namespace sliceform
