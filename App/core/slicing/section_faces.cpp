// SPDX-License-Identifier: LGPL-2.1-or-later
#include "slicing/section_faces.hpp"

#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <ShapeAnalysis_FreeBounds.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_HSequenceOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Vertex.hxx>
#include <TopoDS_Wire.hxx>
#include <gp_Ax3.hxx>
#include <gp_Pln.hxx>

#include <algorithm>
#include <cmath>

#include "geometry/region2d.hpp"
#include "slicing/edge_samples.hpp"

namespace sliceform {
namespace {

gp_Dir toDir(const Vec3& v) {
  return {v.x, v.y, v.z};
}

// A closed chain of section edges and its polygon in the frame's 2D coordinates.
struct Loop {
  TopoDS_Wire wire;
  Region2d::Loop polygon;
  double signedArea = 0;
  double length = 0;  // of the polygon
};

// The polygon of a wire, edges in wire order, each sampled within `deflection`; empty when
// an edge cannot be sampled.
Region2d::Loop polygonise(const TopoDS_Wire& wire, const SliceFrame& frame, double deflection) {
  Region2d::Loop loop;
  for (BRepTools_WireExplorer it(wire); it.More(); it.Next()) {
    const CurveSamples samples = sampleEdge(it.Current(), deflection);
    if (samples.p.empty()) return {};
    std::vector<Vec2> points;
    for (const gp_Pnt& p : samples.p) points.push_back(frame.to2d({p.X(), p.Y(), p.Z()}));
    if (it.Orientation() == TopAbs_REVERSED) std::reverse(points.begin(), points.end());
    loop.insert(loop.end(), points.begin(), points.end() - 1);  // the next edge starts there
  }
  return loop;
}

// Crossing-number test of a point against a closed polygon.
bool inside(Vec2 p, const Region2d::Loop& loop) {
  bool in = false;
  for (size_t i = 0, j = loop.size() - 1; i < loop.size(); j = i++) {
    const Vec2 a = loop[i], b = loop[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y)) in = !in;
  }
  return in;
}

// The closed loops of one plane's section edges; false when a chain stays open (a plane
// tangent to a face, or touching an edge) or an edge cannot be sampled.
bool loopsOf(Handle(TopTools_HSequenceOfShape) edges, const SliceFrame& frame, double deflection,
             std::vector<Loop>& out) {
  Handle(TopTools_HSequenceOfShape) wires = new TopTools_HSequenceOfShape;
  // Shared: the section's edges meet at shared vertices, so no distance is guessed.
  ShapeAnalysis_FreeBounds::ConnectEdgesToWires(edges, Precision::Confusion(), Standard_True, wires);
  for (Standard_Integer i = 1; i <= wires->Length(); ++i) {
    Loop loop;
    loop.wire = TopoDS::Wire(wires->Value(i));
    TopoDS_Vertex first, last;
    TopExp::Vertices(loop.wire, first, last);
    if (first.IsNull() || !first.IsSame(last)) return false;
    loop.polygon = polygonise(loop.wire, frame, deflection);
    if (loop.polygon.size() < 3) return false;
    loop.signedArea = Region2d::signedArea(loop.polygon);
    for (size_t k = 0, j = loop.polygon.size() - 1; k < loop.polygon.size(); j = k++)
      loop.length += std::hypot(loop.polygon[k].x - loop.polygon[j].x, loop.polygon[k].y - loop.polygon[j].y);
    out.push_back(std::move(loop));
  }
  return true;
}

// Faces from nested loops: each loop's parent is the smallest loop around it; loops at
// even depth are outlines, at odd depth holes of their parent. Nothing is added to `into`
// unless every face was made and the nesting reads the loops as the even-odd rule does
// (loops that cross, or a wrong parent, would not).
bool facesOf(std::vector<Loop>& loops, const gp_Pln& plane, BRep_Builder& builder, TopoDS_Compound& into) {
  std::vector<size_t> order(loops.size());
  for (size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    return std::abs(loops[a].signedArea) > std::abs(loops[b].signedArea);
  });
  std::vector<int> parent(loops.size(), -1), depth(loops.size(), 0);
  double area = 0, length = 0;
  std::vector<Region2d::Loop> polygons;
  for (size_t i = 0; i < order.size(); ++i) {
    const Loop& l = loops[order[i]];
    // A point inside an edge, not a vertex, where two loops could touch.
    const Vec2 probe{(l.polygon[0].x + l.polygon[1].x) / 2, (l.polygon[0].y + l.polygon[1].y) / 2};
    for (size_t j = i; j-- > 0;)  // smallest larger loop first
      if (inside(probe, loops[order[j]].polygon)) {
        parent[order[i]] = static_cast<int>(order[j]);
        depth[order[i]] = depth[order[j]] + 1;
        break;
      }
    area += (depth[order[i]] % 2 ? -1 : 1) * std::abs(l.signedArea);
    length += l.length;
    polygons.push_back(l.polygon);
  }
  // The even-odd area differs from the nested one by the grid's rounding (10 nm) at most.
  if (std::abs(Region2d::fromLoops(polygons, FillRule::EvenOdd).area() - area) > 1e-4 * length + 1e-9 * area)
    return false;
  std::vector<TopoDS_Shape> made;
  for (size_t k = 0; k < loops.size(); ++k) {
    if (depth[k] % 2) continue;
    // The frame's normal is the plane's: outlines run counter-clockwise, holes clockwise.
    const auto oriented = [&](size_t i, bool outline) {
      return (loops[i].signedArea > 0) == outline ? loops[i].wire : TopoDS::Wire(loops[i].wire.Reversed());
    };
    BRepBuilderAPI_MakeFace face(plane, oriented(k, true), Standard_False);
    for (size_t h = 0; h < loops.size(); ++h)
      if (parent[h] == static_cast<int>(k)) face.Add(oriented(h, false));
    if (!face.IsDone()) return false;
    made.push_back(face.Face());
  }
  for (const TopoDS_Shape& f : made) builder.Add(into, f);
  return true;
}

}  // namespace

std::vector<std::optional<SectionFaces>> sectionFaces(const TopoDS_Shape& solid, const FaceByFace* own,
                                                      const SliceFrame& frame,
                                                      const std::vector<double>& positions,
                                                      const gp_Pnt& centre, double halfSize,
                                                      double deflection) {
  const size_t n = positions.size();
  BRep_Builder builder;
  const double centrePosition = frame.position({centre.X(), centre.Y(), centre.Z()});
  std::vector<gp_Pln> planes;
  for (const double position : positions) {
    const gp_Pnt origin = centre.Translated(gp_Vec(toDir(frame.normal)) * (position - centrePosition));
    planes.emplace_back(gp_Ax3(origin, toDir(frame.normal), toDir(frame.xAxis)));
  }
  std::vector<std::optional<SectionFaces>> out(n);
  // Our own intersections first, all the planes at once; OCCT's section for the planes left.
  std::vector<size_t> rest;
  const std::vector<Handle(TopTools_HSequenceOfShape)> byPlane =
      own ? own->edges(planes) : std::vector<Handle(TopTools_HSequenceOfShape)>(n);
  for (size_t k = 0; k < n; ++k) {
    const Handle(TopTools_HSequenceOfShape)& edges = byPlane[k];
    if (!edges.IsNull() && edges->IsEmpty()) {
      out[k] = SectionFaces{TopoDS_Shape(), SectionRoute::FaceByFace};
      continue;
    }
    std::vector<Loop> loops;
    TopoDS_Compound faces;
    builder.MakeCompound(faces);
    if (!edges.IsNull() && loopsOf(edges, frame, deflection, loops) &&
        facesOf(loops, planes[k], builder, faces))
      out[k] = SectionFaces{faces, SectionRoute::FaceByFace};
    else
      rest.push_back(k);
  }
  if (rest.empty()) return out;
  TopoDS_Compound cutters;
  builder.MakeCompound(cutters);
  for (const size_t k : rest)
    builder.Add(cutters, BRepBuilderAPI_MakeFace(planes[k], -halfSize, halfSize, -halfSize, halfSize).Face());
  // A warning here (a too small edge) still leaves curves the checks below take or refuse.
  const TopoDS_Shape section = sectionCurves(solid, cutters, false);
  if (section.IsNull()) return out;
  // Each edge to its plane; a plane with an edge off it is left to the Common.
  std::vector<double> at;
  for (const size_t k : rest) at.push_back(positions[k]);
  const std::vector<std::optional<std::vector<TopoDS_Edge>>> curves =
      edgesByPlane(section, toDir(frame.normal), at);
  for (size_t i = 0; i < rest.size(); ++i) {
    if (!curves[i]) continue;  // unsure: the Common
    Handle(TopTools_HSequenceOfShape) edges = new TopTools_HSequenceOfShape;
    for (const TopoDS_Edge& e : *curves[i]) edges->Append(e);
    std::vector<Loop> loops;
    TopoDS_Compound faces;
    builder.MakeCompound(faces);
    if (edges->IsEmpty())
      out[rest[i]] = SectionFaces{TopoDS_Shape(), SectionRoute::Curves};
    else if (loopsOf(edges, frame, deflection, loops) && facesOf(loops, planes[rest[i]], builder, faces))
      out[rest[i]] = SectionFaces{faces, SectionRoute::Curves};
  }
  return out;
}

}  // namespace sliceform
