// SPDX-License-Identifier: LGPL-2.1-or-later
// Planar faces combined without an OCCT Boolean: the region is combined on polygons
// (Clipper, through Region2d), and each stretch of its boundary is traced back to the
// exact edge whose polygon it runs along, which is then trimmed to the stretch. Where two
// stretches meet, the two curves' crossing is found by Newton's method from the polygons'
// crossing. The faces are those edges joined at shared vertices.
//
// Why: a cylinder's section is the union of the sections at several slices, nearly
// coincident and nearly tangent, and the Boolean fuse of them took most of the exact-patch
// stage on CAD parts (occt-misc Axis_of_bearing.brep: 32 fuses of up to 47 faces, 1.2 s
// each; CrankArm.brep: 48 fuses of 9 faces, 0.4 s each). A patch's slots were one Boolean
// cut each, as long again (MODERN_Cooker_1.brep: 124 cuts of ~57 slots, 18 s).
//
// The answer is a null shape wherever a step is unsure, and the caller then runs the
// Boolean: a stretch of the boundary on no edge's polygon, an edge without its 3D curve, a
// face OCCT will not make, or faces whose polygon is not the region (beyond a band of 4
// deflections along its boundary).
#pragma once

#include <TopoDS_Shape.hxx>

#include <functional>
#include <vector>

#include "geometry/region2d.hpp"
#include "slicing/slice_set.hpp"

namespace sliceform {

// The faces of `combine(polygons)`, where polygons[k] is sources[k]'s region: every
// source a planar face (or compound of them) on the plane at `position` of `frame`, each
// edge polygonised within `deflection` mm. The combined region's boundary must run along
// the sources' edges (a union, a difference, an intersection of them).
TopoDS_Shape rebuiltFaces(const std::vector<TopoDS_Shape>& sources,
                          const std::function<Region2d(const std::vector<Region2d>&)>& combine,
                          const SliceFrame& frame, double position, double deflection);

}  // namespace sliceform
