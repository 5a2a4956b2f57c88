// SPDX-License-Identifier: LGPL-2.1-or-later
// Planar faces with their edges' 2D curves stored.
#pragma once

#include <TopoDS_Shape.hxx>

namespace sliceform {

// A copy of `shape` whose planar faces store their edges' 2D curves. A plane keeps none,
// and OCCT projects an edge onto it again each time its curve is asked for: the STEP
// writer while it bounds a face (23 s for rocker-arm's 26,000 edges), the face classifier
// for every point (a third of its time on occ/Bottom.brep). Stored once, they are looked
// up, and are the very curves the projection makes. `shape` is left as it was.
TopoDS_Shape withPlaneCurves(const TopoDS_Shape& shape);

}  // namespace sliceform
