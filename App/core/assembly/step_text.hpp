// SPDX-License-Identifier: LGPL-2.1-or-later
// The assembly's STEP text, written by us: each planar face a part placed in the assembly,
// laid out as OCCT's writer lays it out (AP214, millimetres, no 2D curves). OCCT 7.6's
// writer bounds a face over all its edges again for every edge it writes
// (TopoDSToStep_MakeStepEdge builds a BRepAdaptor_Surface of the face, and reads it only
// for an edge without a 3D curve): quadratic in a face's edges, three quarters of its
// transfer on MODERN_Cooker_1, whose 62 faces have 250 edges each. Here every entity is
// written once.
#pragma once

#include <TopoDS_Shape.hxx>

#include <string>
#include <vector>

namespace sliceform {

// `shape` (a face, or compounds of planar faces, each with a rigid placement) as the text of
// an AP214 file in millimetres, a part for each face. False, with `text` left empty, for
// anything else it does not write as OCCT would: a shape other than a face or a compound,
// a face not on a plane, a placement that scales or mirrors, an edge without a 3D curve or
// on a curve other than a line, conic or B-spline, a loop whose edges do not run end to
// end. The caller then uses OCCT's writer. The parts are named `names`, one a face in order
// (the patch ids a maker reads on the sheets), or `patch 1`, `patch 2`, … when they are not
// as many as the faces.
bool planarFacesStep(const TopoDS_Shape& shape, std::string& text,
                     const std::vector<std::string>& names = {});

}  // namespace sliceform
