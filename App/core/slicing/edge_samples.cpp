// SPDX-License-Identifier: LGPL-2.1-or-later
#include "slicing/edge_samples.hpp"

#include <BRepAdaptor_Curve.hxx>
#include <GCPnts_QuasiUniformDeflection.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <gp_Vec.hxx>

#include <algorithm>

namespace sliceform {
namespace {

// How far p lies from the segment a-b.
double offChord(const gp_Pnt& p, const gp_Pnt& a, const gp_Pnt& b) {
  const gp_Vec ab(a, b), ap(a, p);
  const double len2 = ab.SquareMagnitude();
  if (len2 <= 0) return ap.Magnitude();
  const double f = std::min(1.0, std::max(0.0, ap.Dot(ab) / len2));
  return (ap - ab * f).Magnitude();
}

// The points strictly between (t0, p0) and (t1, p1), halving while the curve's middle or
// quarters lie off the chord. The middle alone let a chord through whose curve bends away
// near an end (occt-misc Bottom.brep: a section's B-spline 0.26 mm off its 3-point polygon
// at a deflection of 0.023 mm, its middles within 0.013). 2^20 pieces of one chord is far
// past any deflection we ask for.
void refine(const Adaptor3d_Curve& curve, double t0, const gp_Pnt& p0, double t1, const gp_Pnt& p1,
            double deflection, int depth, CurveSamples& out) {
  const double tm = (t0 + t1) / 2;
  const gp_Pnt pm = curve.Value(tm);
  const auto on = [&](double t) { return offChord(curve.Value(t), p0, p1) <= deflection; };
  if (depth >= 20 || (offChord(pm, p0, p1) <= deflection && on((t0 + tm) / 2) && on((tm + t1) / 2))) return;
  refine(curve, t0, p0, tm, pm, deflection, depth + 1, out);
  out.t.push_back(tm);
  out.p.push_back(pm);
  refine(curve, tm, pm, t1, p1, deflection, depth + 1, out);
}

}  // namespace

CurveSamples sampleCurve(const Adaptor3d_Curve& curve, double first, double last, double deflection) {
  CurveSamples out;
  // Lines and conics are sampled right as they are (their chords are even steps of a known
  // curvature; but see the two-point answer below); only the others pay for a check of every
  // chord.
  const GeomAbs_CurveType type = curve.GetType();
  const bool check = type != GeomAbs_Line && type != GeomAbs_Circle && type != GeomAbs_Ellipse &&
                     type != GeomAbs_Hyperbola && type != GeomAbs_Parabola;
  // The pieces between the curve's C2 breaks (a section's B-spline: knots of multiplicity 7
  // at degree 8), each sampled on its own.
  std::vector<double> breaks{first};
  if (curve.Continuity() < GeomAbs_C2) {
    const int n = curve.NbIntervals(GeomAbs_C2);
    TColStd_Array1OfReal bounds(1, n + 1);
    curve.Intervals(bounds, GeomAbs_C2);
    for (int i = 2; i <= n; ++i)
      if (bounds(i) > first && bounds(i) < last) breaks.push_back(bounds(i));
  }
  breaks.push_back(last);
  for (size_t k = 0; k + 1 < breaks.size(); ++k) {
    GCPnts_QuasiUniformDeflection sampler(curve, deflection, breaks[k], breaks[k + 1]);
    if (!sampler.IsDone() || sampler.NbPoints() < 2) return {};
    // OCCT 7.6.3 gives an ellipse's arc of more than about 6.1 radians (short of a whole
    // turn, or a whole turn not starting at 0) as its two ends alone: occt-misc Bottom.brep's
    // holes, rebuilt from a section's ellipse, were lost from their polygons. Two points of a
    // curve that is not a line are checked as any other curve's are.
    const bool checkPiece = check || (type != GeomAbs_Line && sampler.NbPoints() == 2);
    for (int i = out.t.empty() ? 1 : 2; i <= sampler.NbPoints(); ++i) {
      if (checkPiece && !out.t.empty())
        refine(curve, out.t.back(), out.p.back(), sampler.Parameter(i), sampler.Value(i), deflection, 0, out);
      out.t.push_back(sampler.Parameter(i));
      out.p.push_back(sampler.Value(i));
    }
  }
  return out;
}

CurveSamples sampleEdge(const TopoDS_Edge& edge, double deflection) {
  const BRepAdaptor_Curve curve(edge);
  return sampleCurve(curve, curve.FirstParameter(), curve.LastParameter(), deflection);
}

}  // namespace sliceform
