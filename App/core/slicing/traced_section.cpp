// SPDX-License-Identifier: LGPL-2.1-or-later
#include "slicing/traced_section.hpp"

#include <BRepAdaptor_Surface.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Geom2d_Curve.hxx>
#include <GeomAPI_Interpolate.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Precision.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_HArray1OfReal.hxx>
#include <TColgp_HArray1OfPnt.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Vertex.hxx>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

namespace sliceform {
namespace {

// mm a contour's B-spline may stray from the exact curve, as a torus's loops may
// (slicing/torus_section.cpp: finer made the patches' Booleans slower than the sections
// gained). Its exact points are held to half that: between them it strays a little more.
constexpr double kTolerance = 1e-3;
// mm from the plane Newton's method must bring a point; and two points of a contour closer
// than kSame are one.
constexpr double kOnPlane = 1e-7, kSame = 1e-6;
// Points a contour is interpolated through, at first and at most.
constexpr int kFewest = 8, kMost = 2048;
// Grid steps per span of the surface (between knots), and per direction at most and least
// (more where kFewestSteps asks).
constexpr int kPerSpan = 8, kMostSteps = 256, kFewestSteps = 32;

// The grid's parameters over [lo, hi]: the same number of steps in each of the surface's
// spans there (`breaks`: the spans' ends, sorted).
std::vector<double> gridParameters(const TColStd_Array1OfReal& breaks, double lo, double hi) {
  std::vector<double> ends{lo};
  for (Standard_Integer k = breaks.Lower(); k <= breaks.Upper(); ++k)
    if (breaks(k) > lo + 1e-9 * (hi - lo) && breaks(k) < hi - 1e-9 * (hi - lo)) ends.push_back(breaks(k));
  ends.push_back(hi);
  int spans = static_cast<int>(ends.size()) - 1;
  if (spans > kMostSteps) ends = {lo, hi}, spans = 1;  // knots too dense to follow: even steps
  const int steps = std::max(std::clamp(kMostSteps / spans, 1, kPerSpan), (kFewestSteps + spans - 1) / spans);
  std::vector<double> out;
  for (int s = 0; s < spans; ++s)
    for (int k = 0; k < steps; ++k) out.push_back(ends[s] + (ends[s + 1] - ends[s]) * k / steps);
  out.push_back(hi);
  return out;
}

// Whether every edge of the face lies on the border of its parameter box, in one wire.
bool boundedByBox(const TopoDS_Face& face, double u0, double u1, double v0, double v1) {
  int wires = 0;
  for (TopExp_Explorer w(face, TopAbs_WIRE); w.More(); w.Next()) ++wires;
  if (wires != 1) return false;
  const double eu = 1e-9 * (u1 - u0), ev = 1e-9 * (v1 - v0);
  for (TopExp_Explorer e(face, TopAbs_EDGE); e.More(); e.Next()) {
    double first = 0, last = 0;
    const Handle(Geom2d_Curve) c = BRep_Tool::CurveOnSurface(TopoDS::Edge(e.Current()), face, first, last);
    if (c.IsNull()) return false;
    for (int k = 0; k <= 8; ++k) {
      const gp_Pnt2d p = c->Value(first + (last - first) * k / 8);
      if (std::abs(p.X() - u0) > eu && std::abs(p.X() - u1) > eu && std::abs(p.Y() - v0) > ev &&
          std::abs(p.Y() - v1) > ev)
        return false;
    }
  }
  return true;
}

// A cubic B-spline through some of `points` (at their chord-length `params`; a closed
// contour's one more, its length) with all of them within kTolerance / 2, and its largest
// distance from them; null where none fits.
std::pair<Handle(Geom_BSplineCurve), double> fit(const std::vector<gp_Pnt>& points,
                                                 const std::vector<double>& params, bool closed) {
  const int m = static_cast<int>(points.size());
  for (int count = std::min(kFewest, m);; count = std::min(2 * count, m)) {
    std::vector<int> chosen;
    for (int k = 0; k < count; ++k) {
      const int i = closed ? k * m / count : static_cast<int>(std::lround(double(k) * (m - 1) / (count - 1)));
      if (chosen.empty() || i != chosen.back()) chosen.push_back(i);
    }
    const int n = static_cast<int>(chosen.size());
    Handle(TColgp_HArray1OfPnt) at = new TColgp_HArray1OfPnt(1, n);
    Handle(TColStd_HArray1OfReal) t = new TColStd_HArray1OfReal(1, closed ? n + 1 : n);
    for (int k = 0; k < n; ++k) at->SetValue(k + 1, points[chosen[k]]), t->SetValue(k + 1, params[chosen[k]]);
    if (closed) t->SetValue(n + 1, params[m]);
    GeomAPI_Interpolate interpolation(at, t, closed, Precision::Confusion());
    interpolation.Perform();
    if (!interpolation.IsDone()) return {nullptr, 0};
    const Handle(Geom_BSplineCurve) curve = interpolation.Curve();
    // Each point's distance from the curve, from its own parameter by Newton's method.
    double error = 0;
    for (int i = 0; i < m && error <= kTolerance / 2; ++i) {
      double s = params[i];
      gp_Pnt c;
      gp_Vec d1, d2;
      for (int k = 0; k < 3; ++k) {
        curve->D2(s, c, d1, d2);
        const gp_Vec r(points[i], c);
        const double slope = d1.Dot(d1) + r.Dot(d2);
        if (!(slope > 0)) break;
        s = std::clamp(s - r.Dot(d1) / slope, curve->FirstParameter(), curve->LastParameter());
      }
      error = std::max(error, curve->Value(s).Distance(points[i]));
    }
    if (error <= kTolerance / 2) return {curve, error};
    if (count == m || m > kMost) return {nullptr, 0};
  }
}

}  // namespace

TracedFace::TracedFace(const TopoDS_Face& face, const gp_Dir& n) : face_(face), n_(n) {
  double u0 = 0, u1 = 0, v0 = 0, v1 = 0;
  BRepTools::UVBounds(face, u0, u1, v0, v1);
  if (!(u1 > u0 && v1 > v0) || Precision::IsInfinite(u1 - u0) || Precision::IsInfinite(v1 - v0) ||
      !boundedByBox(face, u0, u1, v0, v1))
    return;
  const BRepAdaptor_Surface s(face, Standard_False);
  TColStd_Array1OfReal ub(1, s.NbUIntervals(GeomAbs_CN) + 1), vb(1, s.NbVIntervals(GeomAbs_CN) + 1);
  s.UIntervals(ub, GeomAbs_CN);
  s.VIntervals(vb, GeomAbs_CN);
  std::vector<double> u = gridParameters(ub, u0, u1), v = gridParameters(vb, v0, v1);
  h_.reserve(u.size() * v.size());
  for (const double b : v)
    for (const double a : u) h_.push_back(n.XYZ().Dot(s.Value(a, b).XYZ()));
  u_ = std::move(u), v_ = std::move(v);
}

std::optional<std::vector<FaceByFace::AloneEdge>> TracedFace::cut(double d) const {
  if (empty()) return std::nullopt;
  try {
    const BRepAdaptor_Surface s(face_, Standard_False);
    const int nu = static_cast<int>(u_.size()), nv = static_cast<int>(v_.size());
    const auto f = [&](int i, int j) { return h_[static_cast<size_t>(j) * nu + i] - d; };
    // Crossings of the grid's lines by the contour, by the line piece they lie on: along u
    // (i, j)-(i+1, j) first, then along v (i, j)-(i, j+1).
    const int alongU = (nu - 1) * nv;
    const auto inU = [&](int i, int j) { return j * (nu - 1) + i; };
    const auto inV = [&](int i, int j) { return alongU + i * (nv - 1) + j; };
    std::map<int, std::array<int, 2>> links;  // each crossing's neighbours on the contour
    bool unsure = false;
    const auto link = [&](int a, int b) {
      for (const auto& [from, to] : {std::pair{a, b}, std::pair{b, a}}) {
        auto& l = links.try_emplace(from, std::array<int, 2>{-1, -1}).first->second;
        if (l[0] < 0)
          l[0] = to;
        else if (l[1] < 0)
          l[1] = to;
        else
          unsure = true;
      }
    };
    for (int j = 0; j + 1 < nv; ++j)
      for (int i = 0; i + 1 < nu; ++i) {
        const bool a = f(i, j) >= 0, b = f(i + 1, j) >= 0, c = f(i + 1, j + 1) >= 0, e = f(i, j + 1) >= 0;
        if (a == b && b == c && c == e) continue;
        const int bottom = inU(i, j), right = inV(i + 1, j), top = inU(i, j + 1), left = inV(i, j);
        std::vector<int> crossed;
        if (a != b) crossed.push_back(bottom);
        if (b != c) crossed.push_back(right);
        if (c != e) crossed.push_back(top);
        if (e != a) crossed.push_back(left);
        if (crossed.size() == 2) {
          link(crossed[0], crossed[1]);
          continue;
        }
        // A saddle: the exact height at the cell's centre tells which corners connect.
        const double centre =
            n_.XYZ().Dot(s.Value((u_[i] + u_[i + 1]) / 2, (v_[j] + v_[j + 1]) / 2).XYZ()) - d;
        if (std::abs(centre) <= kOnPlane) return std::nullopt;
        if ((centre >= 0) == a)
          link(bottom, right), link(top, left);
        else
          link(left, bottom), link(right, top);
      }
    if (unsure) return std::nullopt;

    // A crossing's exact point: the root of the height along its line piece.
    const auto point = [&](int id) -> std::optional<gp_Pnt> {
      const bool onU = id < alongU;
      const int i = onU ? id % (nu - 1) : (id - alongU) / (nv - 1);
      const int j = onU ? id / (nu - 1) : (id - alongU) % (nv - 1);
      double lo = onU ? u_[i] : v_[j], hi = onU ? u_[i + 1] : v_[j + 1];
      double flo = f(i, j), fhi = onU ? f(i + 1, j) : f(i, j + 1);
      double t = lo + (hi - lo) * flo / (flo - fhi);
      for (int k = 0; k < 60; ++k) {
        gp_Pnt p;
        gp_Vec du, dv;
        s.D1(onU ? t : u_[i], onU ? v_[j] : t, p, du, dv);
        const double g = n_.XYZ().Dot(p.XYZ()) - d, slope = n_.XYZ().Dot((onU ? du : dv).XYZ());
        if (std::abs(g) <= 0.1 * kOnPlane) return p;
        if ((g >= 0) == (flo >= 0))
          lo = t, flo = g;
        else
          hi = t, fhi = g;
        const double next = t - g / slope;
        t = slope != 0 && next > lo && next < hi ? next : (lo + hi) / 2;
        if (hi - lo <= 1e-15 * (std::abs(lo) + std::abs(hi) + 1)) break;
      }
      gp_Pnt p = s.Value(onU ? t : u_[i], onU ? v_[j] : t);
      if (std::abs(n_.XYZ().Dot(p.XYZ()) - d) > kOnPlane) return std::nullopt;
      return p;
    };

    // The contours: from each crossing on the grid's border (one neighbour) to the next,
    // then the closed ones.
    std::vector<FaceByFace::AloneEdge> out;
    std::map<int, bool> done;
    const auto trace = [&](int start, bool closed) -> bool {
      std::vector<gp_Pnt> points;
      for (int at = start, from = -1;;) {
        done[at] = true;
        const std::optional<gp_Pnt> p = point(at);
        if (!p) return false;
        if (points.empty() || points.back().Distance(*p) > kSame) points.push_back(*p);
        const std::array<int, 2>& l = links.at(at);
        const int next = l[0] != from ? l[0] : l[1];
        if (next < 0 || next == start) break;
        from = at, at = next;
      }
      if (closed && points.size() > 1 && points.back().Distance(points.front()) <= kSame) points.pop_back();
      if (points.size() < (closed ? 3u : 2u)) return false;
      std::vector<double> params{0};
      for (size_t k = 1; k < points.size(); ++k)
        params.push_back(params.back() + points[k - 1].Distance(points[k]));
      if (closed) params.push_back(params.back() + points.back().Distance(points.front()));
      const auto [curve, error] = fit(points, params, closed);
      if (curve.IsNull()) return false;
      const double tolerance = std::max(2 * error, Precision::Confusion());
      BRep_Builder builder;
      TopoDS_Vertex first, last;
      builder.MakeVertex(first, points.front(), tolerance);
      last = first;
      if (!closed) builder.MakeVertex(last, points.back(), tolerance);
      TopoDS_Edge edge;
      builder.MakeEdge(edge, curve, tolerance);
      builder.Add(edge, first.Oriented(TopAbs_FORWARD));
      builder.Add(edge, last.Oriented(TopAbs_REVERSED));
      builder.Range(edge, curve->FirstParameter(), curve->LastParameter());
      out.push_back({edge, first, last});
      return true;
    };
    for (const auto& [id, l] : links)
      if (l[1] < 0 && !done.count(id) && !trace(id, false)) return std::nullopt;
    for (const auto& [id, l] : links)
      if (!done.count(id) && !trace(id, true)) return std::nullopt;
    return out;
  } catch (const Standard_Failure&) {
    return std::nullopt;
  }
}

}  // namespace sliceform
