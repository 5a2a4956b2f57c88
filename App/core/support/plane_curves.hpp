// SPDX-License-Identifier: LGPL-2.1-or-later
// Planar faces with their edges' 2D curves stored.
#pragma once

#include <TopoDS_Shape.hxx>

namespace sliceform {

// A copy of `shape`'s topology (its curves and surfaces shared; none is changed) whose planar
// faces store their edges' 2D curves. A plane keeps none, and OCCT projects an edge onto it
// again each time its curve is asked for: the STEP writer while it bounds a face (23 s for
// rocker-arm's 26,000 edges), the face classifier for every point (a third of its time on
// occ/Bottom.brep). Stored once, they are looked up, and are the very curves the
// projection makes. `shape` is left as it was.
// `trimmed`: a B-spline curve longer than its edge (or a closed one, of which the edge is
// a piece) is cut to the edge's range. The STEP writer bounds every 2D curve of a face
// once for each of the face's edges (TopoDSToStep_MakeStepEdge makes a
// BRepAdaptor_Surface), and bounding a longer curve copies and cuts it each time (a third
// of the writer's transfer on occ/Bottom.brep). The file is the same: it carries no 2D
// curves. Not for the classifier: the same curve, but its points could differ in the last
// bits.
TopoDS_Shape withPlaneCurves(const TopoDS_Shape& shape, bool trimmed = false);

}  // namespace sliceform
