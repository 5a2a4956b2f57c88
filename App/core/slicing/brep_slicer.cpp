// SPDX-License-Identifier: LGPL-2.1-or-later
#include "slicing/brep_slicer.hpp"

#include <BRepAlgoAPI_Common.hxx>
#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepGProp.hxx>
#include <BRepTools.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <GProp_GProps.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <gp_Ax3.hxx>
#include <gp_Pln.hxx>

#include <Standard_Failure.hxx>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>
#include <thread>

#include "slicing/edge_samples.hpp"
#include "slicing/face_by_face.hpp"
#include "slicing/section_faces.hpp"
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
    const CurveSamples samples = sampleEdge(edge, deflection);
    if (samples.p.empty()) throw Error(ErrorKind::Geometry, "cannot sample a section edge");
    std::vector<Vec2> points;
    for (const gp_Pnt& p : samples.p) points.push_back(frame.to2d({p.X(), p.Y(), p.Z()}));
    if (it.Orientation() == TopAbs_REVERSED) std::reverse(points.begin(), points.end());
    // The last point of an edge is the first of the next one.
    loop.insert(loop.end(), points.begin(), points.end() - (points.empty() ? 0 : 1));
  }
  return loop;
}

// Several planes are cut in one Boolean: its set-up (the solid's own edges and faces, their
// boxes) is then paid once per batch instead of once per plane, 1.5x faster on
// step/screw.step. The planes are parallel, so the cutters never meet each other.
std::vector<TopoDS_Shape> commonFaces(const std::vector<TopoDS_Shape>& solids, const SliceFrame& frame,
                                      const std::vector<double>& positions, const gp_Pnt& centre,
                                      double halfSize) {
  TopoDS_Compound cutters;
  BRep_Builder builder;
  builder.MakeCompound(cutters);
  const double centrePosition = frame.position({centre.X(), centre.Y(), centre.Z()});
  for (const double position : positions) {
    // A square face on the plane, centred on the model and larger than it; Common with the
    // solid leaves exactly the section faces.
    const gp_Pnt origin = centre.Translated(gp_Vec(toDir(frame.normal)) * (position - centrePosition));
    const gp_Pln plane(gp_Ax3(origin, toDir(frame.normal), toDir(frame.xAxis)));
    builder.Add(cutters, BRepBuilderAPI_MakeFace(plane, -halfSize, halfSize, -halfSize, halfSize).Face());
  }
  std::vector<TopoDS_Compound> faces(positions.size());
  std::vector<bool> any(positions.size(), false);
  for (TopoDS_Compound& f : faces) builder.MakeCompound(f);
  for (const TopoDS_Shape& piece : solids) {
    BRepAlgoAPI_Common common;
    TopTools_ListOfShape arguments, tools;
    arguments.Append(piece);
    tools.Append(cutters);
    common.SetArguments(arguments);
    common.SetTools(tools);
    // Non-destructive: the solid is shared by the threads cutting other planes, and a
    // destructive run may enlarge tolerances of its sub-shapes in place.
    common.SetNonDestructive(Standard_True);
    // On OCCT's threads too: the few planes that come here are the stage's longest, and
    // the last of them ran on one core while the other waited (occ/Bottom.brep: 0.75 s at
    // the end of the exact patches; the stage 1.30-1.58 -> 1.19-1.21 s). The same faces.
    common.SetRunParallel(Standard_True);
    common.Build();
    if (!common.IsDone() || common.HasErrors()) {
      std::ostringstream report;
      common.DumpErrors(report);
      throw Error(ErrorKind::Geometry, "the sections at " + std::to_string(positions.front()) + " to " +
                                           std::to_string(positions.back()) + " mm failed: " + report.str());
    }
    // Each face back to its plane: the nearest position (they are sorted by the caller's
    // order, not necessarily by value, so all are looked at).
    for (TopExp_Explorer it(common.Shape(), TopAbs_FACE); it.More(); it.Next()) {
      // A vertex of the face lies on its plane (the face's surface may be the solid's own
      // face where it lies on the plane, not our cutter's plane).
      const TopExp_Explorer vertex(it.Current(), TopAbs_VERTEX);
      if (!vertex.More()) throw Error(ErrorKind::Geometry, "a section face has no vertex");
      const gp_Pnt at = BRep_Tool::Pnt(TopoDS::Vertex(vertex.Current()));
      const double p = frame.position({at.X(), at.Y(), at.Z()});
      size_t nearest = 0;
      for (size_t k = 1; k < positions.size(); ++k)
        if (std::abs(positions[k] - p) < std::abs(positions[nearest] - p)) nearest = k;
      builder.Add(faces[nearest], it.Current());
      any[nearest] = true;
    }
  }
  std::vector<TopoDS_Shape> out(positions.size());
  for (size_t k = 0; k < positions.size(); ++k)
    if (any[k]) out[k] = faces[k];
  return out;
}

// A solid to cut and where it lies along the frame's normal.
struct Piece {
  TopoDS_Shape solid;
  double lo = 0, hi = 0;
  std::shared_ptr<const FaceByFace> faces;  // null: the route does not start there
};

// One batch of planes, solid by solid, each solid only at the planes that reach it (a
// bearing's balls meet a few planes each): by section curves where that route is sure of
// its faces, by the Common elsewhere.
std::vector<ExactSlice> sliceBatch(const std::vector<Piece>& pieces, const SliceFrame& frame,
                                   const std::vector<double>& positions, const gp_Pnt& centre,
                                   double halfSize, double deflection, SliceDetail detail,
                                   SectionRoute route) {
  const size_t n = positions.size();
  BRep_Builder builder;
  std::vector<TopoDS_Compound> faces(n);
  for (TopoDS_Compound& f : faces) builder.MakeCompound(f);
  std::vector<bool> any(n, false);
  std::vector<SectionRoute> routes(n, route);
  for (const Piece& piece : pieces) {
    std::vector<size_t> meeting;
    std::vector<double> at;
    for (size_t k = 0; k < n; ++k)
      if (positions[k] >= piece.lo && positions[k] <= piece.hi)
        meeting.push_back(k), at.push_back(positions[k]);
    if (meeting.empty()) continue;
    std::vector<std::optional<TopoDS_Shape>> made(at.size());
    if (route != SectionRoute::Common) {
      std::vector<std::optional<SectionFaces>> curves(at.size());
      try {
        curves = sectionFaces(piece.solid, piece.faces.get(), frame, at, centre, halfSize, deflection);
      } catch (const Standard_Failure&) {
        // The Common below makes every plane of the batch.
      }
      // A plane's route is the last one any of its solids needed.
      for (size_t i = 0; i < at.size(); ++i)
        if (curves[i])
          made[i] = curves[i]->faces, routes[meeting[i]] = std::max(routes[meeting[i]], curves[i]->route);
    }
    std::vector<double> rest;
    for (size_t i = 0; i < at.size(); ++i)
      if (!made[i]) rest.push_back(at[i]), routes[meeting[i]] = SectionRoute::Common;
    if (!rest.empty()) {
      const std::vector<TopoDS_Shape> cut = commonFaces({piece.solid}, frame, rest, centre, halfSize);
      for (size_t i = 0, j = 0; i < at.size(); ++i)
        if (!made[i]) made[i] = cut[j++];
    }
    for (size_t i = 0; i < at.size(); ++i)
      for (TopExp_Explorer f(*made[i], TopAbs_FACE); f.More(); f.Next()) {
        builder.Add(faces[meeting[i]], f.Current());
        any[meeting[i]] = true;
      }
  }
  std::vector<ExactSlice> out(n);
  for (size_t k = 0; k < n; ++k) {
    ExactSlice& slice = out[k];
    slice.position = positions[k];
    slice.route = routes[k];
    if (!any[k]) continue;
    slice.faces = faces[k];
    if (detail == SliceDetail::FacesOnly) continue;
    GProp_GProps props;
    // With a relative precision, the adaptive integration: the default fixed-order one was
    // 1.6% off on a face with a B-spline edge (occ/Pump_TopCover.brep: 4512 for 4587 mm²).
    BRepGProp::SurfaceProperties(slice.faces, props, 1e-9);
    slice.area = props.Mass();
    slice.region = polygoniseFaces(slice.faces, frame, deflection);
  }
  return out;
}

}  // namespace

std::vector<Region2d> facePolygons(const TopoDS_Shape& faces, const SliceFrame& frame, double deflection) {
  std::vector<Region2d> pieces;
  for (TopExp_Explorer f(faces, TopAbs_FACE); f.More(); f.Next()) {
    const TopoDS_Face& face = TopoDS::Face(f.Current());
    std::vector<Region2d::Loop> loops;
    for (TopExp_Explorer w(face, TopAbs_WIRE); w.More(); w.Next())
      loops.push_back(polygoniseWire(TopoDS::Wire(w.Current()), face, frame, deflection));
    // A face's holes lie inside its outer wire: even-odd needs no orientation.
    pieces.push_back(Region2d::fromLoops(loops, FillRule::EvenOdd));
  }
  return pieces;
}

Region2d polygoniseFaces(const TopoDS_Shape& faces, const SliceFrame& frame, double deflection) {
  return Region2d::uniteAll(facePolygons(faces, frame, deflection));
}

std::vector<ExactSlice> sliceBrep(const TopoDS_Shape& solid, const SliceFrame& frame,
                                  const std::vector<double>& positions, double deflection, SliceDetail detail,
                                  SectionRoute route) {
  if (!(deflection > 0)) throw Error(ErrorKind::BadParameter, "the polygon deflection must be positive");
  Bnd_Box box;
  occtGuard("measuring the shape", [&] { BRepBndLib::Add(solid, box); });
  if (box.IsVoid()) throw Error(ErrorKind::BadInput, "the shape to slice is empty");
  const gp_Pnt centre = (box.CornerMin().XYZ() + box.CornerMax().XYZ()) / 2;
  const double halfSize = box.CornerMin().Distance(box.CornerMax());
  // Each solid is cut on its own: a compound of solids that touch or overlap is not a valid
  // Boolean argument, and OCCT then returned only parts of the section, without an error
  // (occ/Motor-c.brep: 542 of 4233 mm²). A solid without faces is skipped: Booleans take it
  // for an infinite solid (occ/Axis_of_bearing.brep holds one). Overlapping solids give
  // overlapping faces.
  std::vector<Piece> solids;
  for (TopExp_Explorer it(solid, TopAbs_SOLID); it.More(); it.Next())
    if (TopExp_Explorer(it.Current(), TopAbs_FACE).More()) solids.push_back({it.Current(), 0, 0, nullptr});
  if (solids.empty() && !TopExp_Explorer(solid, TopAbs_SOLID).More())
    solids.push_back({solid, 0, 0, nullptr});
  occtGuard("measuring the solids", [&] {
    for (Piece& piece : solids) {
      Bnd_Box own;
      BRepBndLib::Add(piece.solid, own);  // enlarged by the shape's tolerances: never too small
      piece.lo = std::numeric_limits<double>::max(), piece.hi = std::numeric_limits<double>::lowest();
      for (const double x : {own.CornerMin().X(), own.CornerMax().X()})
        for (const double y : {own.CornerMin().Y(), own.CornerMax().Y()})
          for (const double z : {own.CornerMin().Z(), own.CornerMax().Z()}) {
            const double p = frame.position({x, y, z});
            piece.lo = std::min(piece.lo, p), piece.hi = std::max(piece.hi, p);
          }
      if (route == SectionRoute::FaceByFace) try {
          piece.faces = std::make_shared<const FaceByFace>(piece.solid, toDir(frame.normal));
        } catch (const Standard_Failure&) {
          // No faces to cut one by one: every plane of this solid goes to the section.
        }
    }
  });
  // Batches of up to 16 planes (larger ones gained nothing on screw.step), at least four
  // per core so the cores finish together.
  const size_t cores = std::max(1u, std::thread::hardware_concurrency());
  const size_t batch = std::clamp<size_t>(positions.size() / (4 * cores), 1, 16);
  const size_t batches = (positions.size() + batch - 1) / batch;
  std::vector<ExactSlice> slices(positions.size());
  // Booleans only read the solid, so batches can be cut on all cores at once.
  parallelFor(batches, [&](size_t b) {
    const size_t first = b * batch, last = std::min(positions.size(), first + batch);
    const std::vector<double> some(positions.begin() + first, positions.begin() + last);
    const std::vector<ExactSlice> cut = occtGuard("cutting sections", [&] {
      return sliceBatch(solids, frame, some, centre, halfSize, deflection, detail, route);
    });
    std::copy(cut.begin(), cut.end(), slices.begin() + first);
  });
  return slices;
}

}  // namespace sliceform
