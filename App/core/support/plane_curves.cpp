// SPDX-License-Identifier: LGPL-2.1-or-later
#include "support/plane_curves.hpp"

#include <algorithm>

#include <BRepBuilderAPI_Copy.hxx>
#include <BRepLib.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Geom2d_BSplineCurve.hxx>
#include <Standard_Failure.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>

namespace sliceform {

TopoDS_Shape withPlaneCurves(const TopoDS_Shape& shape, bool trimmed) {
  // The topology copied, its curves and surfaces shared: the 2D curves added below go to
  // the copy's edges alone, and nothing here changes a curve or a surface.
  const TopoDS_Shape copy = BRepBuilderAPI_Copy(shape, /*copyGeom=*/Standard_False).Shape();
  BRep_Builder builder;
  for (TopExp_Explorer f(copy, TopAbs_FACE); f.More(); f.Next()) {
    const TopoDS_Face& face = TopoDS::Face(f.Current());
    TopTools_ListOfShape edges;
    for (TopExp_Explorer e(face, TopAbs_EDGE); e.More(); e.Next()) edges.Append(e.Current());
    BRepLib::BuildPCurveForEdgesOnPlane(edges, face);
    if (!trimmed) continue;
    for (TopTools_ListOfShape::Iterator e(edges); e.More(); e.Next()) {
      const TopoDS_Edge& edge = TopoDS::Edge(e.Value());
      double first = 0, last = 0;
      const Handle(Geom2d_BSplineCurve) curve =
          Handle(Geom2d_BSplineCurve)::DownCast(BRep_Tool::CurveOnSurface(edge, face, first, last));
      if (curve.IsNull() || BRep_Tool::IsClosed(edge, face)) continue;
      double from = first, to = last;
      if (curve->IsPeriodic()) {
        // A piece of a closed curve (a section's loop between two slots) is cut too, as the
        // writer's bounding does each time; the whole loop is left as it is.
        if (!(to - from > 1e-9) || to - from >= curve->Period() - 1e-9) continue;
      } else {
        from = std::max(first, curve->FirstParameter()), to = std::min(last, curve->LastParameter());
        if ((from <= curve->FirstParameter() && to >= curve->LastParameter()) || !(to - from > 1e-9))
          continue;
      }
      // Where OCCT cannot cut it, the curve stays whole: the writer only bounds it longer.
      try {
        const Handle(Geom2d_BSplineCurve) piece = Handle(Geom2d_BSplineCurve)::DownCast(curve->Copy());
        piece->Segment(from, to);
        builder.UpdateEdge(edge, piece, face, BRep_Tool::Tolerance(edge));
      } catch (const Standard_Failure&) {
      }
    }
  }
  return copy;
}

}  // namespace sliceform
