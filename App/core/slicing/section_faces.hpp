// SPDX-License-Identifier: LGPL-2.1-or-later
// Plane sections of a solid as faces built from section curves: ours, face by face
// (slicing/face_by_face.hpp), and for the planes that route is unsure of,
// BRepAlgoAPI_Section's (no Boolean of solids, no faces split). The curves are chained into
// closed loops, the loops nested by their polygons (even depth = outline, odd = hole), and
// each face is made on the plane from its exact wires. A plane is left to the caller (the
// Boolean Common, slower but whole) wherever both are in doubt: a chain that does not
// close, a face OCCT cannot make, loops whose even-odd area is not their nested area (loops
// that cross, a wrong parent).
#pragma once

#include <TopoDS_Shape.hxx>
#include <gp_Pnt.hxx>

#include <optional>
#include <vector>

#include "slicing/brep_slicer.hpp"
#include "slicing/face_by_face.hpp"
#include "slicing/slice_set.hpp"

namespace sliceform {

// A plane's section faces (a null shape where the plane misses) and the route that made them.
struct SectionFaces {
  TopoDS_Shape faces;
  SectionRoute route = SectionRoute::Curves;
};

// The section faces of `solid` by the planes of `frame` at `positions`: first by `own`
// (face by face; may be null), then by BRepAlgoAPI_Section for the planes left; nullopt for
// a plane neither could make. The section's cutters are squares of half side `halfSize`
// about `centre`'s projection; `deflection` is the polygon deflection of the nesting test.
std::vector<std::optional<SectionFaces>> sectionFaces(const TopoDS_Shape& solid, const FaceByFace* own,
                                                      const SliceFrame& frame,
                                                      const std::vector<double>& positions,
                                                      const gp_Pnt& centre, double halfSize,
                                                      double deflection);

}  // namespace sliceform
