// SPDX-License-Identifier: LGPL-2.1-or-later
// An edge's curve as points within a deflection, with their parameters: the one sampler of
// exact edges (section polygons, rebuilt faces, the sheets' cut outlines).
//
// GCPnts_QuasiUniformDeflection alone is not enough. On a curve that is only C1 (OCCT's
// section curves: degree-8 B-splines with knots of multiplicity 7) it gave the two ends of
// a B-spline of 135 poles in occt-misc Bottom.brep, at any deflection: a straight line
// where the curve bulges 1.27 mm, so the patch's outline on the sheets was straight where
// its STEP face bulges. On each C2 piece alone it samples right (OCCT 7.6.3:
// GCPnts_UniformDeflection gave 24 points, the pieces 24). And each chord of a curve that is
// not a line or a conic is checked at its middle and quarters and halved until they lie
// within the deflection (the middle alone let chords through 11 times the deflection off).
#pragma once

#include <Adaptor3d_Curve.hxx>
#include <TopoDS_Edge.hxx>
#include <gp_Pnt.hxx>

#include <vector>

namespace sliceform {

struct CurveSamples {
  std::vector<double> t;  // increasing, from the range's first parameter to its last
  std::vector<gp_Pnt> p;
};

// The curve on [first, last]; empty where OCCT cannot sample it.
CurveSamples sampleCurve(const Adaptor3d_Curve& curve, double first, double last, double deflection);
// The edge's curve on its range (its location applied), in the curve's direction: reverse
// it for a reversed edge.
CurveSamples sampleEdge(const TopoDS_Edge& edge, double deflection);

}  // namespace sliceform
