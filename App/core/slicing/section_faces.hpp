// SPDX-License-Identifier: LGPL-2.1-or-later
// Plane sections of a solid as faces built from section curves: BRepAlgoAPI_Section gives
// the curves where the planes cut the solid's faces (no Boolean of solids, no faces split),
// the curves are chained into closed loops, the loops nested by their polygons (even depth
// = outline, odd = hole), and each face is made on the plane from its exact wires. A plane
// is left to the caller (the Boolean Common, slower but whole) wherever this route is in
// doubt: a chain that does not close, a face OCCT cannot make, loops whose even-odd area is
// not their nested area (loops that cross, a wrong parent).
#pragma once

#include <TopoDS_Shape.hxx>
#include <gp_Pnt.hxx>

#include <optional>
#include <vector>

#include "slicing/slice_set.hpp"

namespace sliceform {

// The section faces of `solids` (each cut on its own) by the planes of `frame` at
// `positions`: one compound per plane (a null shape where the plane misses), or nullopt for
// a plane this route could not make. The cutters are squares of half side `halfSize` about
// `centre`'s projection; `deflection` is the polygon deflection of the nesting test.
std::vector<std::optional<TopoDS_Shape>> sectionFaces(const std::vector<TopoDS_Shape>& solids,
                                                      const SliceFrame& frame,
                                                      const std::vector<double>& positions,
                                                      const gp_Pnt& centre, double halfSize,
                                                      double deflection);

}  // namespace sliceform
