// SPDX-License-Identifier: LGPL-2.1-or-later
// Exact slicer: the cross-sections of a BRep solid as OCCT planar faces with their true
// edges (a section of a cylinder is a circle, not a polygon), plus the polygonised region
// the search stages use.
#pragma once

#include <TopoDS_Shape.hxx>

#include <vector>

#include "slicing/slice_set.hpp"

namespace sliceform {

// How the section faces are made. FaceByFace: our own plane/face intersections (OCCT's
// section of one face alone where it is not a quadric) chained into loops and faces made
// from them on the plane (slicing/face_by_face.hpp); a plane it
// is unsure of goes on to Curves. Curves: BRepAlgoAPI_Section's curves, the same loops and
// faces (slicing/section_faces.hpp); a plane it is unsure of goes on to Common. Common:
// BRepAlgoAPI_Common of the solid with a face on each plane, the faces as the Boolean splits
// them (several times slower: it builds the split faces of the solid too). A route asked
// for is where a plane starts.
enum class SectionRoute { FaceByFace, Curves, Common };

struct ExactSlice {
  double position = 0;
  TopoDS_Shape faces;  // compound of planar faces in 3D, null where the plane misses
  double area = 0;     // of the faces, mm², from OCCT's surface integration (where solids
                       // overlap, their faces overlap and count twice)
  Region2d region;     // the faces' boundaries polygonised within `deflection`
  SectionRoute route = SectionRoute::Common;  // how the faces were made
};

// The polygon deflection used for a model triangulated within `meshDeflection`: ten times
// finer, but never below 1 µm.
inline double exactDeflection(double meshDeflection) {
  return meshDeflection / 10 > 1e-3 ? meshDeflection / 10 : 1e-3;
}

// Faces only leaves area and region empty: the exact patches need only the faces, and the
// adaptive area integration and the polygons are work they would throw away (4 % of a
// slice on screw.step in the stage benchmark: 8.26 against 7.95 ms).
enum class SliceDetail { Measured, FacesOnly };

// `deflection` is the largest distance, in mm, between an edge and its polygon.
std::vector<ExactSlice> sliceBrep(const TopoDS_Shape& solid, const SliceFrame& frame,
                                  const std::vector<double>& positions, double deflection,
                                  SliceDetail detail = SliceDetail::Measured,
                                  SectionRoute route = SectionRoute::FaceByFace);

// The outer and hole loops of planar faces, polygonised, in the frame's 2D coordinates.
Region2d polygoniseFaces(const TopoDS_Shape& faces, const SliceFrame& frame, double deflection);
// The same, face by face, in the order the faces come: polygoniseFaces unites them.
std::vector<Region2d> facePolygons(const TopoDS_Shape& faces, const SliceFrame& frame, double deflection);

}  // namespace sliceform
