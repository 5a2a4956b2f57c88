// SPDX-License-Identifier: LGPL-2.1-or-later
// TracedFace's boundary: each contour cut where it crosses the face's edges (or ends on
// one at the parameter box's border), the pieces inside kept (slicing/traced_section.hpp).
#include <BRepAdaptor_Curve.hxx>

#include <algorithm>
#include <cmath>

#include "slicing/traced_section.hpp"

namespace sliceform {
namespace {

// Of the parameter box's size: a contour's end this near a side lies on the boundary.
constexpr double kOnSide = 1e-9;

double distance(const gp_XY& p, const gp_XY& a, const gp_XY& b) {
  const gp_XY e = b - a;
  const double l = e.SquareModulus();
  const double t = l > 0 ? std::clamp((p - a).Dot(e) / l, 0.0, 1.0) : 0;
  return (a + e * t - p).Modulus();
}

}  // namespace

bool TracedFace::contains(const gp_Pnt2d& uv) const {
  bool in = false;
  for (const Side& s : sides_) {
    const gp_XY a = s.a.XY(), b = s.b.XY();
    if ((a.Y() > uv.Y()) != (b.Y() > uv.Y()) &&
        uv.X() < a.X() + (uv.Y() - a.Y()) * (b.X() - a.X()) / (b.Y() - a.Y()))
      in = !in;
  }
  return in;
}

std::optional<std::vector<TracedFace::Contour>> TracedFace::inside(const Contour& c, double d) const {
  const size_t m = c.p.size();
  if (m < 2) return std::nullopt;
  // Where the contour crosses a side: at pos = k + s along it (piece k, 0 <= s < 1), the
  // exact point on the side's edge.
  struct Cut {
    double pos;
    gp_Pnt p;
  };
  std::vector<Cut> cuts;
  // The exact crossing of the plane on the edge of `side`, within it or its neighbours.
  const auto onEdge = [&](const Side& side) -> std::optional<gp_Pnt> {
    const BRepAdaptor_Curve curve(edges_[side.edge]);
    const double step = std::abs(side.tb - side.ta);
    const auto g = [&](double t) { return n_.XYZ().Dot(curve.Value(t).XYZ()) - d; };
    for (const double wider : {0.0, step}) {
      const double lo = std::max(curve.FirstParameter(), std::min(side.ta, side.tb) - wider);
      const double hi = std::min(curve.LastParameter(), std::max(side.ta, side.tb) + wider);
      const double flo = g(lo), fhi = g(hi);
      if ((flo >= 0) == (fhi >= 0)) continue;
      double a = lo, b = hi, fa = flo;
      for (int k = 0; k < 200 && b - a > 1e-15 * (std::abs(a) + std::abs(b) + 1); ++k) {
        const double mid = (a + b) / 2, fm = g(mid);
        if ((fm >= 0) == (fa >= 0))
          a = mid, fa = fm;
        else
          b = mid;
      }
      return curve.Value((a + b) / 2);
    }
    return std::nullopt;
  };
  const size_t pieces = c.closed ? m : m - 1;
  for (size_t k = 0; k < pieces; ++k) {
    const gp_XY a = c.uv[k].XY(), e = c.uv[(k + 1) % m].XY() - a;
    std::vector<std::pair<double, int>> hits;
    for (const int i : cellSides_[c.cell[k]]) {
      const Side& side = sides_[i];
      const gp_XY f = side.b.XY() - side.a.XY(), g = side.a.XY() - a;
      const double across = e ^ f;
      if (across == 0) continue;  // parallel: a touch, found by the pieces' insides below
      const double s = (g ^ f) / across, r = (g ^ e) / across;
      if (s >= 0 && s < 1 && r >= 0 && r < 1) hits.push_back({s, i});
    }
    std::sort(hits.begin(), hits.end());
    for (const auto& [s, i] : hits) {
      const std::optional<gp_Pnt> p = onEdge(sides_[i]);
      if (!p) return std::nullopt;
      cuts.push_back({k + s, *p});
    }
  }
  // An open contour's ends lie on the box's border: on a side there, they are cuts too.
  const gp_XY span(u_.back() - u_.front(), v_.back() - v_.front());
  bool endCut[2] = {false, false};
  if (!c.closed)
    for (const int end : {0, 1}) {
      const size_t k = end ? m - 1 : 0;
      const gp_XY at = c.uv[k].XY();
      for (const int i : cellSides_[c.cell[end ? m - 2 : 0]]) {
        const Side& side = sides_[i];
        if (distance(at, side.a.XY(), side.b.XY()) > kOnSide * span.Modulus()) continue;
        const std::optional<gp_Pnt> p = onEdge(side);
        if (!p) return std::nullopt;
        cuts.insert(end ? cuts.end() : cuts.begin(), Cut{double(k), *p});
        endCut[end] = true;
        break;
      }
    }
  // A crossing found twice (at one place, on the same or the next piece): at an end that
  // lies on a side, by the end's piece too (kept once); anywhere else the plane meets a
  // vertex or touches the boundary. (A contour's two ends may meet at one place: on the seam
  // of a closed face.)
  const auto twice = [&](const Cut& a, const Cut& b) {
    const double apart = std::abs(a.pos - b.pos);
    return a.p.Distance(b.p) <= kSame && (apart <= 1 || (c.closed && apart >= m - 1));
  };
  std::vector<Cut> distinct;
  for (size_t i = 0; i < cuts.size(); ++i) {
    if (distinct.empty() || !twice(distinct.back(), cuts[i])) {
      distinct.push_back(cuts[i]);
      continue;
    }
    const bool atEnd = (endCut[0] && distinct.size() == 1) || (endCut[1] && i + 1 == cuts.size());
    if (!atEnd) return std::nullopt;
    if (endCut[1] && i + 1 == cuts.size()) distinct.back() = cuts[i];
  }
  cuts = std::move(distinct);
  if (c.closed && (cuts.size() % 2 || (cuts.size() > 1 && twice(cuts.back(), cuts.front()))))
    return std::nullopt;
  // Where a position lies on the contour's polygon, in (u, v).
  const auto uvAt = [&](double pos) {
    const size_t k = std::min(static_cast<size_t>(pos), pieces - 1);
    const gp_XY a = c.uv[k].XY(), b = c.uv[(k + 1) % m].XY();
    return gp_Pnt2d(a + (b - a) * (pos - k));
  };
  std::vector<Contour> out;
  if (c.closed && cuts.empty()) {
    if (contains(uvAt(0.5))) out.push_back(c);
    return out;
  }
  // The pieces between consecutive bounds: each inside or out, in turn.
  struct Bound {
    double pos;
    std::optional<gp_Pnt> p;  // none at an open contour's free end
  };
  std::vector<Bound> bounds;
  if (!c.closed && !endCut[0]) bounds.push_back({0, std::nullopt});
  for (const Cut& cut : cuts) bounds.push_back({cut.pos, cut.p});
  if (!c.closed && !endCut[1]) bounds.push_back({double(m - 1), std::nullopt});
  if (c.closed) bounds.push_back({bounds.front().pos + m, bounds.front().p});
  std::optional<bool> before;
  for (size_t i = 0; i + 1 < bounds.size(); ++i) {
    const Bound& x = bounds[i];
    const Bound& y = bounds[i + 1];
    const double mid = std::fmod((x.pos + y.pos) / 2, double(m));
    const bool in = contains(uvAt(mid));
    if (before && *before == in) return std::nullopt;  // two crossings where there is one
    before = in;
    if (!in) continue;
    if (!x.p || !y.p) return std::nullopt;  // inside the face at the box's border, on no side
    Contour piece;
    piece.p.push_back(*x.p), piece.uv.push_back(uvAt(x.pos));
    for (double k = std::floor(x.pos) + 1; k < y.pos; ++k)
      piece.p.push_back(c.p[static_cast<size_t>(k) % m]),
          piece.uv.push_back(c.uv[static_cast<size_t>(k) % m]);
    piece.p.push_back(*y.p), piece.uv.push_back(uvAt(std::fmod(y.pos, double(m))));
    out.push_back(std::move(piece));
  }
  return out;
}

}  // namespace sliceform
