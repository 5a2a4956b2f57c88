// SPDX-License-Identifier: LGPL-2.1-or-later
// Planar faces bounded by straight edges only (a mesh's polygon patches) rewritten with one
// edge per loop: a degree-1 B-spline through the loop's corners, exactly the same polygon.
// A STEP writer spends its time per edge (an edge, its vertices, points, line, vector and
// direction entities each); a mesh patch has thousands of short edges and one loop or two.
#pragma once

#include <TopoDS_Shape.hxx>

namespace sliceform {

// Faces that have any curved edge, and everything that is not a face, are kept as they
// are; so are faces with fewer than 8 edges per loop on average (nothing to gain). The
// result is a compound of the faces alone.
TopoDS_Shape polylineLoopsAsSplines(const TopoDS_Shape& shape);

}  // namespace sliceform
