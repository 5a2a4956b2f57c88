// SPDX-License-Identifier: LGPL-2.1-or-later
#include "slicing/brep_slicer.hpp"

#include <BRepAdaptor_Curve.hxx>
#include <BRepAlgoAPI_Common.hxx>
#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepGProp.hxx>
#include <BRepTools.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <BRep_Builder.hxx>
#include <Bnd_Box.hxx>
#include <GCPnts_QuasiUniformDeflection.hxx>
#include <GProp_GProps.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <gp_Ax3.hxx>
#include <gp_Pln.hxx>

#include <algorithm>
#include <sstream>

#include "support/error.hpp"
#include "support/occt_guard.hpp"
#include "support/parallel.hpp"

namespace sliceform {
namespace {

gp_Dir toDir(const Vec3& v) {
  return {v.x, v.y, v.z};
}

// One loop of a face: its edges in wire order, each sampled within `deflection`.
Region2d::Loop polygoniseWire(const TopoDS_Wire& wire, const TopoDS_Face& face, const SliceFrame& frame,
                              double deflection) {
  Region2d::Loop loop;
  for (BRepTools_WireExplorer it(wire, face); it.More(); it.Next()) {
    const TopoDS_Edge& edge = it.Current();
    BRepAdaptor_Curve curve(edge);
    GCPnts_QuasiUniformDeflection sampler(curve, deflection);
    if (!sampler.IsDone()) throw Error(ErrorKind::Geometry, "cannot sample a section edge");
    std::vector<Vec2> points;
    for (Standard_Integer i = 1; i <= sampler.NbPoints(); ++i) {
      const gp_Pnt p = sampler.Value(i);
      points.push_back(frame.to2d({p.X(), p.Y(), p.Z()}));
    }
    if (it.Orientation() == TopAbs_REVERSED) std::reverse(points.begin(), points.end());
    // The last point of an edge is the first of the next one.
    loop.insert(loop.end(), points.begin(), points.end() - (points.empty() ? 0 : 1));
  }
  return loop;
}

ExactSlice sliceAt(const TopoDS_Shape& solid, const SliceFrame& frame, double position, const gp_Pnt& centre,
                   double halfSize, double deflection, SliceDetail detail) {
  // A square face on the plane, centred on the model and larger than it; Common with the
  // solid leaves exactly the section faces.
  const gp_Pnt origin = centre.Translated(gp_Vec(toDir(frame.normal)) *
                                          (position - frame.position({centre.X(), centre.Y(), centre.Z()})));
  const gp_Pln plane(gp_Ax3(origin, toDir(frame.normal), toDir(frame.xAxis)));
  const TopoDS_Face cutter = BRepBuilderAPI_MakeFace(plane, -halfSize, halfSize, -halfSize, halfSize);
  TopoDS_Compound faces;
  BRep_Builder builder;
  builder.MakeCompound(faces);
  bool any = false;
  // Each solid is cut on its own: a compound of solids that touch or overlap is not a valid
  // Boolean argument, and OCCT then returned only parts of the section, without an error
  // (occ/Motor-c.brep: 542 of 4233 mm²). A solid without faces is skipped: Booleans take it
  // for an infinite solid (occ/Axis_of_bearing.brep holds one). Overlapping solids give
  // overlapping faces.
  std::vector<TopoDS_Shape> solids;
  for (TopExp_Explorer it(solid, TopAbs_SOLID); it.More(); it.Next())
    if (TopExp_Explorer(it.Current(), TopAbs_FACE).More()) solids.push_back(it.Current());
  if (solids.empty() && !TopExp_Explorer(solid, TopAbs_SOLID).More()) solids.push_back(solid);
  for (const TopoDS_Shape& piece : solids) {
    BRepAlgoAPI_Common common;
    TopTools_ListOfShape arguments, tools;
    arguments.Append(piece);
    tools.Append(cutter);
    common.SetArguments(arguments);
    common.SetTools(tools);
    // Non-destructive: the solid is shared by the threads cutting other planes, and a
    // destructive run may enlarge tolerances of its sub-shapes in place.
    common.SetNonDestructive(Standard_True);
    common.SetRunParallel(Standard_False);
    common.Build();
    if (!common.IsDone() || common.HasErrors()) {
      std::ostringstream report;
      common.DumpErrors(report);
      throw Error(ErrorKind::Geometry,
                  "the section at " + std::to_string(position) + " mm failed: " + report.str());
    }
    for (TopExp_Explorer it(common.Shape(), TopAbs_FACE); it.More(); it.Next()) {
      builder.Add(faces, it.Current());
      any = true;
    }
  }
  ExactSlice slice;
  slice.position = position;
  if (!any) return slice;
  slice.faces = faces;
  if (detail == SliceDetail::FacesOnly) return slice;
  GProp_GProps props;
  // With a relative precision, the adaptive integration: the default fixed-order one was
  // 1.6% off on a face with a B-spline edge (occ/Pump_TopCover.brep: 4512 for 4587 mm²).
  BRepGProp::SurfaceProperties(faces, props, 1e-9);
  slice.area = props.Mass();
  slice.region = polygoniseFaces(faces, frame, deflection);
  return slice;
}

}  // namespace

Region2d polygoniseFaces(const TopoDS_Shape& faces, const SliceFrame& frame, double deflection) {
  std::vector<Region2d> pieces;
  for (TopExp_Explorer f(faces, TopAbs_FACE); f.More(); f.Next()) {
    const TopoDS_Face& face = TopoDS::Face(f.Current());
    std::vector<Region2d::Loop> loops;
    for (TopExp_Explorer w(face, TopAbs_WIRE); w.More(); w.Next())
      loops.push_back(polygoniseWire(TopoDS::Wire(w.Current()), face, frame, deflection));
    // A face's holes lie inside its outer wire: even-odd needs no orientation.
    pieces.push_back(Region2d::fromLoops(loops, FillRule::EvenOdd));
  }
  return Region2d::uniteAll(pieces);
}

std::vector<ExactSlice> sliceBrep(const TopoDS_Shape& solid, const SliceFrame& frame,
                                  const std::vector<double>& positions, double deflection,
                                  SliceDetail detail) {
  if (!(deflection > 0)) throw Error(ErrorKind::BadParameter, "the polygon deflection must be positive");
  Bnd_Box box;
  occtGuard("measuring the shape", [&] { BRepBndLib::Add(solid, box); });
  if (box.IsVoid()) throw Error(ErrorKind::BadInput, "the shape to slice is empty");
  const gp_Pnt centre = (box.CornerMin().XYZ() + box.CornerMax().XYZ()) / 2;
  const double halfSize = box.CornerMin().Distance(box.CornerMax());
  std::vector<ExactSlice> slices(positions.size());
  // Booleans only read the solid, so planes can be cut on all cores at once.
  parallelFor(positions.size(), [&](size_t i) {
    slices[i] = occtGuard("cutting a section", [&] {
      return sliceAt(solid, frame, positions[i], centre, halfSize, deflection, detail);
    });
  });
  return slices;
}

}  // namespace sliceform
