// SPDX-License-Identifier: LGPL-2.1-or-later
#include "slicing/traced_section.hpp"

#include <BRepAdaptor_Surface.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Geom2dAdaptor_Curve.hxx>
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
// mm from the plane Newton's method must bring a point.
constexpr double kOnPlane = 1e-7;
constexpr double kSame = TracedFace::kSame;
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

// The cells [grid[k], grid[k + 1]] that meet [lo, hi], first and last: a side on the
// grid's last line lies in its last cell.
std::pair<int, int> cellsMeeting(const std::vector<double>& grid, double lo, double hi) {
  const int cells = static_cast<int>(grid.size()) - 1;
  const auto cell = [&](double x) {
    return std::clamp(static_cast<int>(std::upper_bound(grid.begin(), grid.end(), x) - grid.begin()) - 1, 0,
                      cells - 1);
  };
  return {cell(std::min(lo, hi)), cell(std::max(lo, hi))};
}

// The point of the surface nearest `q`, from near `uv` (Newton's method on the distance),
// and its parameters.
gp_Pnt nearest(const BRepAdaptor_Surface& s, const gp_Pnt& q, gp_Pnt2d& uv) {
  gp_Pnt p;
  gp_Vec su, sv;
  for (int k = 0; k < 6; ++k) {
    s.D1(uv.X(), uv.Y(), p, su, sv);
    const gp_Vec r(q, p);
    const double a = su.Dot(su), b = su.Dot(sv), c = sv.Dot(sv), det = a * c - b * b;
    if (!(det > 0)) break;
    const double du = -(c * su.Dot(r) - b * sv.Dot(r)) / det, dv = -(a * sv.Dot(r) - b * su.Dot(r)) / det;
    uv.SetCoord(uv.X() + du, uv.Y() + dv);
    if (std::abs(du) + std::abs(dv) < 1e-14) break;
  }
  return s.Value(uv.X(), uv.Y());
}

// A point on the face and the plane n·p = d, from near `uv` (Newton's method along the
// height's gradient); nullopt where it does not get there.
std::optional<gp_Pnt> onPlane(const BRepAdaptor_Surface& s, const gp_Dir& n, double d, gp_Pnt2d& uv) {
  gp_Pnt p;
  gp_Vec su, sv;
  for (int k = 0; k < 8; ++k) {
    s.D1(uv.X(), uv.Y(), p, su, sv);
    const double g = n.XYZ().Dot(p.XYZ()) - d, gu = n.XYZ().Dot(su.XYZ()), gv = n.XYZ().Dot(sv.XYZ());
    if (std::abs(g) <= 0.1 * kOnPlane) return p;
    const double slope = gu * gu + gv * gv;
    if (!(slope > 0)) return std::nullopt;
    uv.SetCoord(uv.X() - g * gu / slope, uv.Y() - g * gv / slope);
  }
  p = s.Value(uv.X(), uv.Y());
  if (std::abs(n.XYZ().Dot(p.XYZ()) - d) > kOnPlane) return std::nullopt;
  return p;
}

// A cubic B-spline through some of the contour's points, at their chord-length
// parameters, with every point within kTolerance / 2, and its largest distance from them.
// Null where none fits.
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
    if (count == m || count >= kMost) return {nullptr, 0};
  }
}

// The edge along a piece of a contour (a closed contour's ends one vertex); nullopt where
// none fits. Between its points the B-spline may bulge off the face (1.4 µm next to a
// hole's rim, with points 1/20 apart): its middle between each two points is measured
// against the face, and where it strays, the exact point there is added and it is fitted
// again. The edge claims twice the largest distance found.
std::optional<FaceByFace::AloneEdge> edgeThrough(const std::vector<gp_Pnt>& points,
                                                 const std::vector<gp_Pnt2d>& uvs, bool closed,
                                                 const BRepAdaptor_Surface& s, const gp_Dir& n, double d) {
  std::vector<gp_Pnt> kept;
  std::vector<gp_Pnt2d> uv;
  for (size_t k = 0; k < points.size(); ++k)
    if (kept.empty() || kept.back().Distance(points[k]) > kSame)
      kept.push_back(points[k]), uv.push_back(uvs[k]);
  if (closed && kept.size() > 1 && kept.back().Distance(kept.front()) <= kSame)
    kept.pop_back(), uv.pop_back();
  if (kept.size() < (closed ? 3u : 2u)) return std::nullopt;
  // An open piece's ends are crossings on the face's edges, which may lie off the face
  // (within their tolerance, if the file is right; 0.04 mm on linkrods.step): the curve
  // through them strays that much more near them.
  double slack = 0;
  if (!closed)
    for (const size_t k : {size_t(0), kept.size() - 1}) {
      gp_Pnt2d at = uv[k];
      slack = std::max(slack, nearest(s, kept[k], at).Distance(kept[k]));
    }
  for (int round = 0; round < 4; ++round) {
    std::vector<double> params{0};
    for (size_t k = 1; k < kept.size(); ++k) params.push_back(params.back() + kept[k - 1].Distance(kept[k]));
    if (closed) params.push_back(params.back() + kept.back().Distance(kept.front()));
    const auto [curve, error] = fit(kept, params, closed);
    if (curve.IsNull() || kept.size() > size_t(kMost)) return std::nullopt;
    double worst = error;
    std::vector<gp_Pnt> more;
    std::vector<gp_Pnt2d> moreUv;
    const size_t pieces = closed ? kept.size() : kept.size() - 1;
    for (size_t k = 0; k < kept.size(); ++k) {
      more.push_back(kept[k]), moreUv.push_back(uv[k]);
      if (k >= pieces) continue;
      const size_t next = (k + 1) % kept.size();
      const gp_Pnt q = curve->Value((params[k] + params[k + 1]) / 2);
      gp_Pnt2d at((uv[k].XY() + uv[next].XY()) / 2);
      const double off = nearest(s, q, at).Distance(q);
      worst = std::max(worst, off);
      if (off <= kTolerance / 2 + slack) continue;
      const std::optional<gp_Pnt> exact = onPlane(s, n, d, at);
      if (!exact) return std::nullopt;
      more.push_back(*exact), moreUv.push_back(at);
    }
    if (more.size() == kept.size()) {
      const double tolerance = std::max(2 * worst, Precision::Confusion());
      BRep_Builder builder;
      TopoDS_Vertex first, last;
      builder.MakeVertex(first, kept.front(), tolerance);
      last = first;
      if (!closed) builder.MakeVertex(last, kept.back(), tolerance);
      TopoDS_Edge edge;
      builder.MakeEdge(edge, curve, tolerance);
      builder.Add(edge, first.Oriented(TopAbs_FORWARD));
      builder.Add(edge, last.Oriented(TopAbs_REVERSED));
      builder.Range(edge, curve->FirstParameter(), curve->LastParameter());
      return FaceByFace::AloneEdge{edge, first, last};
    }
    kept = std::move(more), uv = std::move(moreUv);
  }
  return std::nullopt;
}

// The root of g in [lo, hi] where it changes sign there (flo, fhi: g at the ends), by
// Newton's method kept inside the bracket; nullopt where it does not change sign.
template <class G>
std::optional<double> root(const G& g, double lo, double hi, double flo, double fhi) {
  if ((flo >= 0) == (fhi >= 0)) return std::nullopt;
  double t = lo + (hi - lo) * flo / (flo - fhi);
  for (int k = 0; k < 60; ++k) {
    const auto [value, slope] = g(t);
    if (std::abs(value) <= 0.1 * kOnPlane) return t;
    if ((value >= 0) == (flo >= 0))
      lo = t, flo = value;
    else
      hi = t, fhi = value;
    const double next = t - value / slope;
    t = slope != 0 && next > lo && next < hi ? next : (lo + hi) / 2;
    if (hi - lo <= 1e-15 * (std::abs(lo) + std::abs(hi) + 1)) break;
  }
  return t;
}

}  // namespace

TracedFace::TracedFace(const TopoDS_Face& face, const gp_Dir& n) : face_(face), n_(n) {
  double u0 = 0, u1 = 0, v0 = 0, v1 = 0;
  BRepTools::UVBounds(face, u0, u1, v0, v1);
  if (!(u1 > u0 && v1 > v0) || Precision::IsInfinite(u1 - u0) || Precision::IsInfinite(v1 - v0)) return;
  const BRepAdaptor_Surface s(face, Standard_False);
  TColStd_Array1OfReal ub(1, s.NbUIntervals(GeomAbs_CN) + 1), vb(1, s.NbVIntervals(GeomAbs_CN) + 1);
  s.UIntervals(ub, GeomAbs_CN);
  s.VIntervals(vb, GeomAbs_CN);
  std::vector<double> u = gridParameters(ub, u0, u1), v = gridParameters(vb, v0, v1);
  // Each edge's curve on the face as sides: 8 a span of it, 16 to 512 an edge.
  cellSides_.resize((u.size() - 1) * (v.size() - 1));
  for (TopExp_Explorer e(face, TopAbs_EDGE); e.More(); e.Next()) {
    const TopoDS_Edge edge = TopoDS::Edge(e.Current());
    double first = 0, last = 0;
    const Handle(Geom2d_Curve) c = BRep_Tool::CurveOnSurface(edge, face, first, last);
    if (c.IsNull()) return;
    const int count = std::clamp(8 * Geom2dAdaptor_Curve(c, first, last).NbIntervals(GeomAbs_CN), 16, 512);
    const int index = static_cast<int>(edges_.size());
    edges_.push_back(edge);
    gp_Pnt2d a = c->Value(first);
    for (int k = 0; k < count; ++k) {
      const double ta = first + (last - first) * k / count, tb = first + (last - first) * (k + 1) / count;
      const Side side{a, c->Value(tb), index, ta, tb};
      a = side.b;
      const auto [i0, i1] = cellsMeeting(u, side.a.X(), side.b.X());
      const auto [j0, j1] = cellsMeeting(v, side.a.Y(), side.b.Y());
      for (int j = j0; j <= j1; ++j)
        for (int i = i0; i <= i1; ++i) cellSides_[j * (u.size() - 1) + i].push_back(int(sides_.size()));
      sides_.push_back(side);
    }
  }
  h_.reserve(u.size() * v.size());
  for (const double b : v)
    for (const double a : u) h_.push_back(n.XYZ().Dot(s.Value(a, b).XYZ()));
  u_ = std::move(u), v_ = std::move(v);
}

std::optional<std::vector<TracedFace::Contour>> TracedFace::contours(double d) const {
  const BRepAdaptor_Surface s(face_, Standard_False);
  const int nu = static_cast<int>(u_.size()), nv = static_cast<int>(v_.size());
  const auto f = [&](int i, int j) { return h_[static_cast<size_t>(j) * nu + i] - d; };
  // Crossings of the grid's lines by the contour, by the line piece they lie on: along u
  // (i, j)-(i+1, j) first, then along v (i, j)-(i, j+1).
  const int alongU = (nu - 1) * nv;
  const auto inU = [&](int i, int j) { return j * (nu - 1) + i; };
  const auto inV = [&](int i, int j) { return alongU + i * (nv - 1) + j; };
  // Each crossing's neighbours on the contour, and the cell between it and each.
  std::map<int, std::array<std::pair<int, int>, 2>> links;
  bool unsure = false;
  const auto link = [&](int a, int b, int cell) {
    for (const auto& [from, to] : {std::pair{a, b}, std::pair{b, a}}) {
      auto& l =
          links.try_emplace(from, std::array<std::pair<int, int>, 2>{{{-1, -1}, {-1, -1}}}).first->second;
      if (l[0].first < 0)
        l[0] = {to, cell};
      else if (l[1].first < 0)
        l[1] = {to, cell};
      else
        unsure = true;
    }
  };
  for (int j = 0; j + 1 < nv; ++j)
    for (int i = 0; i + 1 < nu; ++i) {
      const bool a = f(i, j) >= 0, b = f(i + 1, j) >= 0, c = f(i + 1, j + 1) >= 0, e = f(i, j + 1) >= 0;
      if (a == b && b == c && c == e) continue;
      const int cell = j * (nu - 1) + i;
      const int bottom = inU(i, j), right = inV(i + 1, j), top = inU(i, j + 1), left = inV(i, j);
      std::vector<int> crossed;
      if (a != b) crossed.push_back(bottom);
      if (b != c) crossed.push_back(right);
      if (c != e) crossed.push_back(top);
      if (e != a) crossed.push_back(left);
      if (crossed.size() == 2) {
        link(crossed[0], crossed[1], cell);
        continue;
      }
      // A saddle: the exact height at the cell's centre tells which corners connect.
      const double centre = n_.XYZ().Dot(s.Value((u_[i] + u_[i + 1]) / 2, (v_[j] + v_[j + 1]) / 2).XYZ()) - d;
      if (std::abs(centre) <= kOnPlane) return std::nullopt;
      if ((centre >= 0) == a)
        link(bottom, right, cell), link(top, left, cell);
      else
        link(left, bottom, cell), link(right, top, cell);
    }
  if (unsure) return std::nullopt;

  // A crossing's exact point: the root of the height along its line piece.
  const auto point = [&](int id, gp_Pnt& p, gp_Pnt2d& uv) {
    const bool onU = id < alongU;
    const int i = onU ? id % (nu - 1) : (id - alongU) / (nv - 1);
    const int j = onU ? id / (nu - 1) : (id - alongU) % (nv - 1);
    const auto at = [&](double t) { return onU ? gp_Pnt2d(t, v_[j]) : gp_Pnt2d(u_[i], t); };
    const auto g = [&](double t) {
      gp_Vec du, dv;
      s.D1(at(t).X(), at(t).Y(), p, du, dv);
      return std::pair{n_.XYZ().Dot(p.XYZ()) - d, n_.XYZ().Dot((onU ? du : dv).XYZ())};
    };
    const std::optional<double> t =
        root(g, onU ? u_[i] : v_[j], onU ? u_[i + 1] : v_[j + 1], f(i, j), onU ? f(i + 1, j) : f(i, j + 1));
    if (!t) return false;
    uv = at(*t);
    p = s.Value(uv.X(), uv.Y());
    return std::abs(n_.XYZ().Dot(p.XYZ()) - d) <= kOnPlane;
  };

  // From each crossing on the grid's border (one neighbour) to the next, then the closed ones.
  std::vector<Contour> out;
  std::map<int, bool> done;
  const auto trace = [&](int start, bool closed) {
    Contour c;
    c.closed = closed;
    for (int at = start, from = -1;;) {
      done[at] = true;
      gp_Pnt p;
      gp_Pnt2d uv;
      if (!point(at, p, uv)) return false;
      c.p.push_back(p), c.uv.push_back(uv);
      const auto& l = links.at(at);
      const auto& next = l[0].first != from ? l[0] : l[1];
      if (next.first < 0) break;
      c.cell.push_back(next.second);
      if (next.first == start) break;
      from = at, at = next.first;
    }
    out.push_back(std::move(c));
    return true;
  };
  for (const auto& [id, l] : links)
    if (l[1].first < 0 && !done.count(id) && !trace(id, false)) return std::nullopt;
  for (const auto& [id, l] : links)
    if (!done.count(id) && !trace(id, true)) return std::nullopt;
  return out;
}

std::optional<std::vector<FaceByFace::AloneEdge>> TracedFace::cut(double d) const {
  if (empty()) return std::nullopt;
  try {
    const std::optional<std::vector<Contour>> all = contours(d);
    if (!all) return std::nullopt;
    const BRepAdaptor_Surface s(face_, Standard_False);
    std::vector<FaceByFace::AloneEdge> out;
    for (const Contour& c : *all) {
      const std::optional<std::vector<Contour>> pieces = inside(c, d);
      if (!pieces) return std::nullopt;
      for (const Contour& piece : *pieces) {
        const std::optional<FaceByFace::AloneEdge> edge =
            edgeThrough(piece.p, piece.uv, piece.closed, s, n_, d);
        if (!edge) return std::nullopt;
        out.push_back(*edge);
      }
    }
    return out;
  } catch (const Standard_Failure&) {
    return std::nullopt;
  }
}

}  // namespace sliceform
