// SPDX-License-Identifier: LGPL-2.1-or-later
#include "support/plane_curves.hpp"

#include <BRepBuilderAPI_Copy.hxx>
#include <BRepLib.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>

namespace sliceform {

TopoDS_Shape withPlaneCurves(const TopoDS_Shape& shape) {
  const TopoDS_Shape copy = BRepBuilderAPI_Copy(shape).Shape();
  for (TopExp_Explorer f(copy, TopAbs_FACE); f.More(); f.Next()) {
    TopTools_ListOfShape edges;
    for (TopExp_Explorer e(f.Current(), TopAbs_EDGE); e.More(); e.Next()) edges.Append(e.Current());
    BRepLib::BuildPCurveForEdgesOnPlane(edges, TopoDS::Face(f.Current()));
  }
  return copy;
}

}  // namespace sliceform
