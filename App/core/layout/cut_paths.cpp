// SPDX-License-Identifier: LGPL-2.1-or-later
#include "layout/cut_paths.hpp"

#include <BRepAdaptor_Curve.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Wire.hxx>

#include <cmath>
#include <optional>

#include "slicing/edge_samples.hpp"
#include "support/error.hpp"
#include "support/occt_guard.hpp"

namespace sliceform {
namespace {

constexpr double kTwoPi = 2 * M_PI;

double turn(Vec2 a, Vec2 b, Vec2 c) {  // (b - a) x (c - a): > 0 when a, b, c turn left
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

CutElement line(Vec2 a, Vec2 b) {
  CutElement e;
  e.a = a;
  e.b = b;
  return e;
}

struct PlaneMap {
  Vec3 xAxis, yAxis;
  Vec2 operator()(const gp_Pnt& p) const {
    const Vec3 q{p.X(), p.Y(), p.Z()};
    return {dot(q, xAxis), dot(q, yAxis)};
  }
};

// One edge, walked in the wire's direction, as lines and arcs in the plane's coordinates.
void addEdge(const TopoDS_Edge& edge, const PlaneMap& to2d, CutLoop& loop) {
  const BRepAdaptor_Curve curve(edge);
  const bool reversed = edge.Orientation() == TopAbs_REVERSED;
  double first = curve.FirstParameter(), last = curve.LastParameter();
  const Vec2 a = to2d(curve.Value(reversed ? last : first)), b = to2d(curve.Value(reversed ? first : last));
  // An edge of no length (its ends within a nanometre) is left out: OCCT's offset leaves a
  // corner arc of 1e-8 rad where two corners meet (a kerf round the pole of a sphere's
  // patch), and an arc whose ends meet is a whole circle to a DXF reader and to pointAt.
  const bool lineOrCircle = curve.GetType() == GeomAbs_Line || curve.GetType() == GeomAbs_Circle;
  if (lineOrCircle && last - first < 1e-3 && std::hypot(b.x - a.x, b.y - a.y) < 1e-6) return;
  if (curve.GetType() == GeomAbs_Line) {
    loop.push_back(line(a, b));
    return;
  }
  if (curve.GetType() == GeomAbs_Circle) {
    const gp_Circ circle = curve.Circle();
    CutElement e = line(a, b);
    e.kind = CutElement::Kind::Circle;
    e.centre = to2d(circle.Location());
    e.radius = circle.Radius();
    if (last - first < kTwoPi - 1e-9) {
      const Vec2 mid = to2d(curve.Value((first + last) / 2));
      e.kind = CutElement::Kind::Arc;
      e.start = std::atan2(a.y - e.centre.y, a.x - e.centre.x);
      e.end = std::atan2(b.y - e.centre.y, b.x - e.centre.x);
      // Three points met in order along a circle turn the way the circle is walked.
      e.ccw = turn(a, mid, b) > 0;
    }
    loop.push_back(e);
    return;
  }
  // Anything else (B-splines, ellipses) as a polyline within the output deflection.
  const CurveSamples points = sampleCurve(curve, first, last, kOutlineDeflection);
  if (points.p.size() < 2) {
    loop.push_back(line(a, b));
    return;
  }
  const int n = static_cast<int>(points.p.size());
  for (int i = 0; i + 1 < n; ++i) {
    const int p = reversed ? n - 1 - i : i, q = reversed ? n - 2 - i : i + 1;
    loop.push_back(line(to2d(points.p[p]), to2d(points.p[q])));
  }
}

std::vector<CutLoop> cutLoops(const TopoDS_Shape& shape, const PlaneMap& to2d) {
  return occtGuard("flattening a patch", [&] {
    std::vector<CutLoop> loops;
    for (TopExp_Explorer w(shape, TopAbs_WIRE); w.More(); w.Next()) {
      CutLoop loop;
      for (BRepTools_WireExplorer e(TopoDS::Wire(w.Current())); e.More(); e.Next())
        addEdge(e.Current(), to2d, loop);
      if (!loop.empty()) loops.push_back(loop);
    }
    return loops;
  });
}

// The kerf rounds the cut path round every convex corner of the paper (OCCT's offset, an arc
// of half the kerf about the corner). Where that arc turns less than this, the path goes
// straight on to where its two sides meet instead (a mitre). The paper stays the same: the
// beam's circle about the mitre touches both sides at the corner and no more, as about the
// arc. Only waste is cut, at most r (1 / cos(turn / 2) - 1) beyond the arc (r at 120°). A
// polygon's path turns at every vertex (a mesh's sections, curves drawn as lines), and
// every slot's mouth has two 90° corners: fandisk at 0.1 mm had 3,242 arcs beside 7,637
// lines, and FreeCAD 0.20's TechDraw took 4.45 s to draw its sheets after a Kerf edit (a
// Margin edit: 0.75 s at no kerf, 3.97 s at 0.1 mm).
constexpr double kMitredTurn = 120 * M_PI / 180;

// Whether `e` is a corner arc of the kerf's offset: an arc of half the kerf, `radius`.
bool cornerArc(const CutElement& e, double radius) {
  return e.kind == CutElement::Kind::Arc && std::abs(e.radius - radius) <= 1e-9 * (1 + radius);
}

Vec2 along(Vec2 from, Vec2 to) {
  const double l = std::hypot(to.x - from.x, to.y - from.y);
  return l > 0 ? Vec2{(to.x - from.x) / l, (to.y - from.y) / l} : Vec2{0, 0};
}

// Whether the paper lies left of the cut path `loop`, `radius` (half the kerf) away from
// it: asked of `paper` beside its longest line. None when the loop has no line.
std::optional<bool> paperOnTheLeft(const CutLoop& loop, const Region2d& paper, double radius) {
  const CutElement* longest = nullptr;
  double length = 0;
  for (const CutElement& e : loop)
    if (e.kind == CutElement::Kind::Line && std::hypot(e.b.x - e.a.x, e.b.y - e.a.y) > length)
      longest = &e, length = std::hypot(e.b.x - e.a.x, e.b.y - e.a.y);
  if (!longest) return std::nullopt;
  const Vec2 u = along(longest->a, longest->b),
             m{(longest->a.x + longest->b.x) / 2, (longest->a.y + longest->b.y) / 2};
  return paper.contains({m.x - 2 * radius * u.y, m.y + 2 * radius * u.x});
}

// Where the ray from `o` along the unit vector `u` first meets the circle about `c` of
// radius `r`, as the distance along it; none when it does not.
std::optional<double> rayMeetsCircle(Vec2 o, Vec2 u, Vec2 c, double r) {
  const Vec2 d{o.x - c.x, o.y - c.y};
  const double b = u.x * d.x + u.y * d.y, q = d.x * d.x + d.y * d.y - r * r, disc = b * b - q;
  if (disc < 0) return std::nullopt;
  const double root = std::sqrt(disc);
  if (-b - root >= 0) return -b - root;
  if (-b + root >= 0) return -b + root;
  return std::nullopt;
}

// Where a corner arc's two neighbours, each drawn on past it (a line straight on, an arc
// round its circle), meet; none where both are arcs or they do not meet near the corner.
std::optional<Vec2> mitre(const CutElement& before, const CutElement& arc, const CutElement& after) {
  const bool lineBefore = before.kind == CutElement::Kind::Line,
             lineAfter = after.kind == CutElement::Kind::Line;
  // Not onto another corner arc (a zero-length one OCCT leaves where two corners meet).
  if (before.kind == CutElement::Kind::Circle || after.kind == CutElement::Kind::Circle ||
      (!lineBefore && !lineAfter) || cornerArc(before, arc.radius) || cornerArc(after, arc.radius))
    return std::nullopt;
  const double reach = arc.radius * std::tan(sweepOf(arc) / 2);
  Vec2 m;
  if (lineBefore && lineAfter) {
    // Both tangent to the arc at its ends: they meet r tan(sweep / 2) beyond them.
    const Vec2 u = along(before.a, before.b), v = along(after.a, after.b);
    m = {(before.b.x + reach * u.x + after.a.x - reach * v.x) / 2,
         (before.b.y + reach * u.y + after.a.y - reach * v.y) / 2};
  } else {
    const CutElement& line = lineBefore ? before : after;
    const CutElement& round = lineBefore ? after : before;
    const Vec2 o = lineBefore ? line.b : line.a;
    const Vec2 u = lineBefore ? along(line.a, line.b) : along(line.b, line.a);
    const std::optional<double> t = rayMeetsCircle(o, u, round.centre, round.radius);
    if (!t) return std::nullopt;
    m = {o.x + *t * u.x, o.y + *t * u.y};
  }
  // Near the corner, as a mitre of less than kMitredTurn is (the arc's own ends are 2r
  // apart at most): not the far side of an arc's circle.
  const double far = 2 * arc.radius / std::cos(kMitredTurn / 2) + 1e-9;
  if (std::hypot(m.x - arc.a.x, m.y - arc.a.y) > far || std::hypot(m.x - arc.b.x, m.y - arc.b.y) > far)
    return std::nullopt;
  return m;
}

// `e` with one end moved to `p` (`start`: its start, else its end), an arc's angle with it.
void moveEnd(CutElement& e, bool start, Vec2 p) {
  (start ? e.a : e.b) = p;
  if (e.kind == CutElement::Kind::Arc)
    (start ? e.start : e.end) = std::atan2(p.y - e.centre.y, p.x - e.centre.x);
}

// The loop with each corner arc of `radius` round the paper (turning toward it) that turns
// less than kMitredTurn replaced by the point where its neighbours meet (mitre()).
CutLoop mitred(const CutLoop& loop, double radius, const Region2d& paper) {
  const size_t n = loop.size();
  const std::optional<bool> left = n >= 3 ? paperOnTheLeft(loop, paper, radius) : std::nullopt;
  if (!left) return loop;
  std::vector<char> drop(n, 0);
  CutLoop out = loop;
  for (size_t i = 0; i < n; ++i) {
    const CutElement& e = loop[i];
    const size_t b = (i + n - 1) % n, a = (i + 1) % n;
    if (!cornerArc(e, radius) || e.ccw != *left || sweepOf(e) >= kMitredTurn || drop[b] || drop[a]) continue;
    const std::optional<Vec2> m = mitre(out[b], e, out[a]);
    if (!m) continue;
    CutElement before = out[b], after = out[a];
    moveEnd(before, false, *m);
    moveEnd(after, true, *m);
    // An arc drawn on goes on past its end, a little: it neither turns back nor wraps round.
    const auto drawnOn = [](const CutElement& was, const CutElement& now) {
      if (now.kind != CutElement::Kind::Arc) return true;
      const double grown = sweepOf(now) - sweepOf(was);
      return grown >= 0 && grown < kMitredTurn;
    };
    if (!drawnOn(out[b], before) || !drawnOn(out[a], after)) continue;
    out[b] = before, out[a] = after;
    drop[i] = 1;
  }
  CutLoop kept;
  for (size_t i = 0; i < n; ++i)
    if (!drop[i]) kept.push_back(out[i]);
  return kept;
}

// `paper` (a polygon) moved out by Clipper, half the kerf: its corners mitred up to
// kMitredTurn and cut square beyond, tangent to the round corner (the paper the same).
std::vector<CutLoop> polygonPaths(const Region2d& paper, double kerf) {
  std::vector<CutLoop> loops;
  for (const Region2d::Loop& polygon : paper.mitredOffset(kerf / 2, 1 / std::cos(kMitredTurn / 2)).loops()) {
    CutLoop loop;
    for (size_t i = 0; i < polygon.size(); ++i)
      loop.push_back(line(polygon[i], polygon[(i + 1) % polygon.size()]));
    loops.push_back(std::move(loop));
  }
  return loops;
}

// Whether every edge of `shape` is a line or a circle: what OCCT's offset moves exactly,
// and what the sheets keep as lines and arcs.
bool linesAndCircles(const TopoDS_Shape& shape) {
  return occtGuard("reading a patch's edges", [&] {
    for (TopExp_Explorer e(shape, TopAbs_EDGE); e.More(); e.Next()) {
      const GeomAbs_CurveType type = BRepAdaptor_Curve(TopoDS::Edge(e.Current())).GetType();
      if (type != GeomAbs_Line && type != GeomAbs_Circle) return false;
    }
    return true;
  });
}

}  // namespace

std::vector<CutLoop> cutPaths(const LayoutInput& d, int k) {
  const PatchPlane plane = patchPlane(d.arrangement, k);
  const PlaneMap to2d{plane.xAxis, plane.yAxis};
  const double kerf = d.realization.params.kerf;
  const PatchFace& patch = d.patches[k];
  if (kerf <= 0) return cutLoops(patch.shape, to2d);
  // A polygon patch (a mesh's, or one put back to the slot search's polygon) is its polygon
  // moved out: what OCCT's offset and the mitres below make of it, to Clipper's 10 nm, but
  // for corners sharper than kMitredTurn (cut square, not round), in a fraction of the time
  // (OCCT's offset: 12 ms a patch of fandisk's). So is an exact face with an edge of another
  // kind (an ellipse, a B-spline): OCCT offsets it as B-splines it fits (the box minus a
  // cylinder turned 45° about X, its hole's ellipses: 18 ms a face, 0.35 s of a Kerf edit),
  // and the sheets draw those as lines all the same.
  if (!patch.exact || !linesAndCircles(patch.shape)) return polygonPaths(patch.outline, kerf);
  std::vector<CutLoop> loops;
  try {
    loops = cutLoops(kerfCompensated(patch.shape, kerf), to2d);
  } catch (const Error& e) {
    if (e.kind() != ErrorKind::Geometry) throw;
    // OCCT's offset fails on some exact faces (at 0.15 mm, a patch or more of occt-misc's
    // Axis_of_bearing, Ball, Bottom, Motor-c and Top: a wire it finds open, or no result;
    // the design was refused). The paper's polygon, within kOutlineDeflection of the face,
    // is moved out instead.
    return polygonPaths(patch.outline, kerf);
  }
  for (CutLoop& loop : loops) loop = mitred(loop, kerf / 2, patch.outline);
  return loops;
}

}  // namespace sliceform
