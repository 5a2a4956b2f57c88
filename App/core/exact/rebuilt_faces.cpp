// SPDX-License-Identifier: LGPL-2.1-or-later
#include "exact/rebuilt_faces.hpp"

#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Geom_Curve.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Vertex.hxx>
#include <TopoDS_Wire.hxx>
#include <gp_Ax3.hxx>
#include <gp_Pln.hxx>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <unordered_map>

#include "geometry/simplify.hpp"
#include "slicing/brep_slicer.hpp"
#include "slicing/edge_samples.hpp"
#include "slicing/surface_sections.hpp"

namespace sliceform {
namespace {

// How far a vertex of the combined polygon may lie from the polygon it came from: Clipper
// rounds to 10 nm units, and its cleaning drops vertices within 1.415 units of a line.
constexpr double kOnPolygon = 4 / Region2d::kUnitsPerMm;
// The sine of the shallowest crossing (1°) whose place refineCrossing seeks beyond its
// fixed reach: below it the curves touch more than they cross.
constexpr double kShallowest = 0.0175;
// mm: a run shorter than this that turns back along its neighbour is a spike of rounding,
// no edge (a micrometre, ten thousand times OCCT's Precision::Confusion).
constexpr double kShortestEdge = 1e-3;
// The cosine beyond which two directions are one line, turned back.
constexpr double kAntiParallel = 0.999;

// One exact edge and its polygon, in parameter order.
struct Source {
  Handle(Geom_Curve) curve;  // in the plane's place (the edge's location applied)
  double tolerance = 0;
  std::vector<double> t;
  std::vector<Vec2> p;
};

// Where a point lies on a source's polygon: the parameter interpolated in a segment.
struct Match {
  int source, segment;
  double t;
};

double distanceToSegment(Vec2 q, Vec2 a, Vec2 b, double& fraction) {
  const double dx = b.x - a.x, dy = b.y - a.y, len2 = dx * dx + dy * dy;
  fraction = len2 > 0 ? std::clamp(((q.x - a.x) * dx + (q.y - a.y) * dy) / len2, 0.0, 1.0) : 0.0;
  return std::hypot(q.x - a.x - fraction * dx, q.y - a.y - fraction * dy);
}

// The sources' polygon segments by grid cell, to find the ones a point lies on.
class SegmentGrid {
 public:
  SegmentGrid(const std::vector<Source>& sources, double cell) : sources_(sources), cell_(cell) {
    for (int s = 0; s < static_cast<int>(sources.size()); ++s)
      for (int i = 0; i + 1 < static_cast<int>(sources[s].p.size()); ++i) {
        const Vec2 a = sources[s].p[i], b = sources[s].p[i + 1];
        for (long long x = key(std::min(a.x, b.x) - kOnPolygon); x <= key(std::max(a.x, b.x) + kOnPolygon);
             ++x)
          for (long long y = key(std::min(a.y, b.y) - kOnPolygon); y <= key(std::max(a.y, b.y) + kOnPolygon);
               ++y)
            cells_[x * 1000003 + y].push_back({s, i});
      }
  }
  std::vector<Match> at(Vec2 q) const {
    std::vector<Match> out;
    const auto it = cells_.find(key(q.x) * 1000003 + key(q.y));
    if (it == cells_.end()) return out;
    for (const auto& [s, i] : it->second) {
      const Source& src = sources_[s];
      double f;
      if (distanceToSegment(q, src.p[i], src.p[i + 1], f) <= kOnPolygon)
        out.push_back({s, i, src.t[i] + f * (src.t[i + 1] - src.t[i])});
    }
    return out;
  }
  // Whether q lies within `radius` (at most a cell) of source s's polygon.
  bool near(Vec2 q, int s, double radius) const {
    for (long long dx = -1; dx <= 1; ++dx)
      for (long long dy = -1; dy <= 1; ++dy) {
        const auto it = cells_.find((key(q.x) + dx) * 1000003 + key(q.y) + dy);
        if (it == cells_.end()) continue;
        for (const auto& [t, i] : it->second) {
          double f;
          if (t == s && distanceToSegment(q, sources_[t].p[i], sources_[t].p[i + 1], f) <= radius)
            return true;
        }
      }
    return false;
  }

 private:
  long long key(double v) const { return static_cast<long long>(std::floor(v / cell_)); }
  const std::vector<Source>& sources_;
  double cell_;
  std::unordered_map<long long, std::vector<std::pair<int, int>>> cells_;
};

// The crossing of two curves on the plane near a(ta), b(tb), by Gauss-Newton on
// |a(ta) - b(tb)|²; the start where it does not converge (tangent curves).
void refineCrossing(const Source& a, double& ta, const Source& b, double& tb, double deflection) {
  double sa = ta, sb = tb;
  gp_Pnt pa, pb;
  gp_Vec da, db;
  for (int k = 0; k < 8; ++k) {
    a.curve->D1(sa, pa, da);
    b.curve->D1(sb, pb, db);
    const gp_Vec r(pb, pa);
    if (r.Magnitude() < 1e-9) break;
    // J = [da, -db]; (JᵀJ) step = -Jᵀ r.
    const double m11 = da.Dot(da), m12 = -da.Dot(db), m22 = db.Dot(db);
    const double g1 = da.Dot(r), g2 = -db.Dot(r);
    const double det = m11 * m22 - m12 * m12;
    if (std::abs(det) < 1e-12 * m11 * m22) return;
    sa -= (m22 * g1 - m12 * g2) / det;
    sb -= (m11 * g2 - m12 * g1) / det;
  }
  a.curve->D1(sa, pa, da);
  b.curve->D1(sb, pb, db);
  const gp_Pnt a0 = a.curve->Value(ta), b0 = b.curve->Value(tb);
  // Kept only where it closed the gap without running off along the curves to another
  // crossing. Each polygon lies within a deflection of its curve, so the polygons cross
  // up to 2 deflections / sin(angle) along the curves from where the curves do: at a
  // shallow crossing further than a fixed reach (occt-misc Ball.brep: a section's circle
  // meets a slot's wall at 5°, its polygon's crossing 0.3 mm off). Trimmed at the polygons'
  // crossing, the curves cross again beside the vertex, and the face's wire crosses itself.
  // Curves that touch (under kShallowest) have no one crossing to find: Newton slides along
  // them (Bottom.brep: 0.95 mm from a gap of 8 µm), and only the fixed reach holds.
  const double sine = da.Magnitude() > 0 && db.Magnitude() > 0
                          ? da.Crossed(db).Magnitude() / (da.Magnitude() * db.Magnitude())
                          : 0.0;
  const double reach = 10 * deflection + (sine >= kShallowest ? 4 * deflection / sine : 0.0);
  if (pa.Distance(pb) < a0.Distance(b0) && pa.Distance(a0) < reach && pb.Distance(b0) < reach)
    ta = sa, tb = sb;
}

// Whether two parameters of a source name one vertex of the loop. Clipper rounds a vertex
// to its 10 nm grid, and one vertex between two sample points' segments then projects onto
// each at a slightly different place: as far apart as kOnPolygon allows, along the curve.
bool sameParameter(const Source& s, double a, double b) {
  gp_Pnt p;
  gp_Vec d;
  s.curve->D1(a, p, d);
  return std::abs(b - a) * d.Magnitude() <= 2 * kOnPolygon;
}

// b moved by whole periods to within half a period of a, on a periodic source: a run goes
// on across a closed curve's seam (a circle's arc past its parameter 0 is one edge).
double unwrapped(const Source& s, double a, double b) {
  if (!s.curve->IsPeriodic()) return b;
  const double period = s.curve->Period();
  return b + period * std::round((a - b) / period);
}

// Whether source s's polygon between parameters t0 and t1 (either order) lies within
// `radius` of the polyline.
bool staysNear(const Source& s, double t0, double t1, const std::vector<Vec2>& line, double radius) {
  const double lo = std::min(t0, t1), hi = std::max(t0, t1);
  for (size_t i = 0; i < s.t.size(); ++i) {
    const double t = unwrapped(s, (lo + hi) / 2, s.t[i]);
    if (t <= lo || t >= hi) continue;
    double nearest = std::numeric_limits<double>::max(), f;
    for (size_t k = 0; k + 1 < line.size(); ++k)
      nearest = std::min(nearest, distanceToSegment(s.p[i], line[k], line[k + 1], f));
    if (nearest > radius) return false;
  }
  return true;
}

// A stretch of one loop along one source, vertices first..last of the loop.
struct Run {
  int source;
  double t0, t1;
  std::vector<Vec2> points;  // the loop's vertices along it, its ends included
};

// Whether q lies on source s's polygon.
bool onSource(const SegmentGrid& grid, Vec2 q, int s) {
  const std::vector<Match> matches = grid.at(q);
  return std::any_of(matches.begin(), matches.end(), [&](const Match& m) { return m.source == s; });
}

// Whether the segment a-b runs along source s's polygon (both ends and its middle on it).
bool along(const SegmentGrid& grid, Vec2 a, Vec2 b, int s) {
  const Vec2 mid{(a.x + b.x) / 2, (a.y + b.y) / 2};
  return onSource(grid, a, s) && onSource(grid, b, s) && onSource(grid, mid, s);
}

// The loop with the vertices Clipper's cleaning dropped put back where a segment runs along
// two sources: where the sections of two slices meet on nearly one line, the step between
// them (under 14 nm) is cleaned away, and the segment then lies on neither polygon alone.
// The vertex put back is the sample point of a source that ends the stretch on it.
std::optional<Region2d::Loop> withSteps(const Region2d::Loop& loop, const std::vector<Source>& sources,
                                        const SegmentGrid& grid) {
  Region2d::Loop out;
  for (size_t j = 0; j < loop.size(); ++j) {
    Vec2 a = loop[j];
    const Vec2 b = loop[(j + 1) % loop.size()];
    out.push_back(a);
    for (int inserted = 0;; ++inserted) {
      std::vector<int> at;
      for (const Match& m : grid.at(a)) at.push_back(m.source);
      if (std::any_of(at.begin(), at.end(), [&](int s) { return along(grid, a, b, s); })) break;
      if (inserted == 8) return std::nullopt;
      // The farthest sample point towards b, near the line, that a's source runs to.
      const double dx = b.x - a.x, dy = b.y - a.y, len = std::hypot(dx, dy);
      double best = 0;
      std::optional<Vec2> step;
      for (const int s : at)
        for (const Vec2& c : sources[s].p) {
          const double f = ((c.x - a.x) * dx + (c.y - a.y) * dy) / (len * len);
          const double off = std::abs((c.x - a.x) * dy - (c.y - a.y) * dx) / len;
          if (f > best && f < 1 && off <= kOnPolygon && along(grid, a, c, s)) best = f, step = c;
        }
      if (!step) return std::nullopt;
      out.push_back(*step);
      a = *step;
    }
  }
  return out;
}

// Whether the faces' polygon is the region. They may differ in bands along the boundary:
// each is within a deflection of the curves, and an excursion kept on its curve (below) is
// within 2 deflections of the region; so no band is wider than 4 deflections, and eroding
// by 2 leaves nothing of them. A slot left uncut, a loop that crosses itself or an arc
// taken the long way round is wider, and stays. (It replaces BRepCheck_Analyzer, whose
// test of a wire crossing itself is quadratic: 130 ms for a patch with 57 slots, as long
// as the Boolean cut it saves.)
bool sameRegion(const Region2d& made, const Region2d& region, double deflection) {
  const Region2d differ = made.subtract(region).unite(region.subtract(made));
  return differ.offset(-2 * deflection).empty();
}

// The parameter of q's foot on the source's curve, from t found on its polygon. A match's
// parameter is interpolated along a polygon segment, which puts it off the point where the
// curve's speed varies along the segment: a nearly straight hyperbola of occt-misc Top.brep,
// sampled at 3 points over 50 mm, was off by up to a millimetre, and its crossings with the
// slots then too far to refine, so the patch went to the Boolean cut. Where c(t) lies within
// the deflection of q, t is kept as it is; else the foot (footOnCurve), kept inside the
// curve and only where it comes nearer.
double footParameter(const Source& s, double t, const gp_Pnt& q, double deflection) {
  const double start = s.curve->Value(t).Distance(q);
  if (start <= deflection) return t;
  double u = footOnCurve(*s.curve, q, t);
  if (!s.curve->IsPeriodic()) u = std::clamp(u, s.curve->FirstParameter(), s.curve->LastParameter());
  return s.curve->Value(u).Distance(q) < start ? u : t;
}

// The stretch of the source's curve a run stands for, lo < hi: within a curve's range, at
// most a period of a closed one. False where none is left.
bool stretch(const Source& s, const Run& run, double& lo, double& hi) {
  lo = std::min(run.t0, run.t1), hi = std::max(run.t0, run.t1);
  if (!s.curve->IsPeriodic())
    lo = std::max(lo, s.curve->FirstParameter()), hi = std::min(hi, s.curve->LastParameter());
  else
    hi = std::min(hi, lo + s.curve->Period());
  return hi > lo;
}

// The edges of one loop of the combined region, in its order; empty where unsure.
std::vector<TopoDS_Edge> loopEdges(const Region2d::Loop& original, const std::vector<Source>& sources,
                                   const SegmentGrid& grid, const SliceFrame& frame, double position,
                                   double deflection) {
  const std::optional<Region2d::Loop> stepped = withSteps(original, sources, grid);
  if (!stepped) return {};
  const Region2d::Loop& loop = *stepped;
  const size_t n = loop.size();
  std::vector<std::vector<Match>> matches(n);
  for (size_t j = 0; j < n; ++j) matches[j] = grid.at(loop[j]);
  // Each segment's source (the previous segment's where it can), and its ends' parameters
  // on it, the nearest pair.
  std::vector<int> source(n, -1);
  std::vector<double> ta(n), tb(n);
  for (size_t pass = 0; pass < 2; ++pass)  // the second pass lets segment 0 follow the last
    for (size_t j = 0; j < n; ++j) {
      const size_t k = (j + 1) % n;
      const Vec2 mid{(loop[j].x + loop[k].x) / 2, (loop[j].y + loop[k].y) / 2};
      const int previous = source[(j + n - 1) % n];
      int chosen = -1;
      double best = 0;
      for (const Match& a : matches[j])
        for (const Match& b : matches[k]) {
          if (a.source != b.source || !onSource(grid, mid, a.source)) continue;
          const double span = std::abs(b.t - a.t);
          const bool better = chosen < 0 || (a.source == previous && chosen != previous) ||
                              ((a.source == previous) == (chosen == previous) && span < best);
          if (better) chosen = a.source, best = span, ta[j] = a.t, tb[j] = b.t;
        }
      if (chosen < 0) return {};
      source[j] = chosen;
    }
  const auto at = [&](Vec2 q) {
    const Vec3 p = frame.to3d(q, position);
    return gp_Pnt(p.x, p.y, p.z);
  };
  for (size_t j = 0; j < n; ++j) {
    const Source& s = sources[source[j]];
    ta[j] = footParameter(s, ta[j], at(loop[j]), deflection);
    tb[j] = footParameter(s, tb[j], at(loop[(j + 1) % n]), deflection);
  }
  // Runs: consecutive segments on one source whose parameters continue.
  const auto continues = [&](size_t j) {  // segment j continues segment j - 1
    const size_t i = (j + n - 1) % n;
    const Source& s = sources[source[j]];
    return source[i] == source[j] && sameParameter(s, tb[i], unwrapped(s, tb[i], ta[j])) &&
           (tb[i] - ta[i]) * (tb[j] - ta[j]) > 0;
  };
  size_t start = n;
  for (size_t j = 0; j < n && start == n; ++j)
    if (!continues(j)) start = j;
  if (start == n) start = 0;  // a closed curve all round (a hole's circle): one edge
  std::vector<Run> runs;
  for (size_t step = 0; step < n; ++step) {
    const size_t j = (start + step) % n;
    if (step == 0 || !continues(j))
      runs.push_back({source[j], ta[j], tb[j], {loop[j]}});
    else
      runs.back().t1 = tb[j] + unwrapped(sources[source[j]], runs.back().t1, ta[j]) - ta[j];
    runs.back().points.push_back(loop[(j + 1) % n]);
  }
  // Excursions merged: where the boundary leaves a source for others and comes back to it,
  // all the while within 2 deflections of it, the run stays on it. Sections of neighbouring
  // slices cross each other many times within nanometres, and the union would otherwise
  // run along each in turn; 2 deflections is what sectionsAddingToUnion leaves out too.
  // Twice, the runs turned half round between: an excursion across the loop's first vertex
  // is in the middle the second time.
  const double stay = 2 * deflection;
  const auto merge = [&] {
    for (size_t i = 0; i + 1 < runs.size();) {
      bool merged = false;
      for (size_t j = i + 1; j < runs.size() && j <= i + 8; ++j) {
        if (runs[j].source != runs[i].source) continue;
        const Run &a = runs[i], &b = runs[j];
        // Two runs of one source side by side (split where the loop began) join where their
        // parameters meet; across an excursion they go on the same way.
        const double shift = unwrapped(sources[a.source], a.t1, b.t0) - b.t0;
        bool within = (a.t1 - a.t0) * (b.t1 - b.t0) > 0 &&
                      (j == i + 1 ? sameParameter(sources[a.source], a.t1, b.t0 + shift)
                                  : (a.t1 - a.t0) * (b.t0 + shift - a.t1) >= 0);
        std::vector<Vec2> excursion;
        for (size_t k = i + 1; k < j && within; ++k) {
          for (const Vec2& q : runs[k].points) within = within && grid.near(q, a.source, stay);
          excursion.insert(excursion.end(), runs[k].points.begin(), runs[k].points.end());
        }
        // And the source itself stays near the excursion all the way it would stand for it:
        // the excursion's points near some part of the source are not enough, as a source
        // may leave the boundary between them and come back.
        within = within && (j == i + 1 || staysNear(sources[a.source], a.t1, b.t0 + shift, excursion, stay));
        if (within) {
          runs[i].t1 = b.t1 + shift;
          runs[i].points.insert(runs[i].points.end(), b.points.begin(), b.points.end());
          runs.erase(runs.begin() + static_cast<long>(i) + 1, runs.begin() + static_cast<long>(j) + 1);
          merged = true;  // the merged run may take the next excursion too
        }
        if (merged || j > i + 1) break;  // an adjacent run that does not join: look further
      }
      if (!merged) ++i;
    }
  };
  merge();
  std::rotate(runs.begin(), runs.begin() + static_cast<long>(runs.size() / 2), runs.end());
  merge();
  // Where run r ends and run r + 1 begins: the curves' crossing. Both parameters of a
  // crossing are refined before either is read, so the order does not matter.
  const auto refine = [&](size_t r) {
    Run& a = runs[r];
    Run& b = runs[(r + 1) % runs.size()];
    if (a.source != b.source) refineCrossing(sources[a.source], a.t1, sources[b.source], b.t0, deflection);
  };
  for (size_t r = 0; r < runs.size(); ++r) refine(r);
  // A run its crossings leave no stretch of its curve is dropped, and its neighbours cross
  // each other: two curves that cross on a third (occt-misc Motor-c.brep: two ellipses on a
  // slot's wall, their polygons 2 µm apart there). So is a spike: a run under
  // kShortestEdge that turns back along its neighbour (MODERN_Exhaust_1.brep: 0.16 µm back
  // along a slot's wall, an edge BRepCheck finds crossing the one before). A short run
  // square to its neighbours is a step, and stays (MODERN_Sink_1.brep: dropped, its
  // neighbours' crossing split a patch).
  const auto spike = [&](size_t r, double lo, double hi) {
    const Run& run = runs[r];
    const Source& s = sources[run.source];
    if (s.curve->Value(lo).Distance(s.curve->Value(hi)) >= kShortestEdge) return false;
    const auto direction = [&](const Run& x, double t) {
      gp_Pnt p;
      gp_Vec d;
      sources[x.source].curve->D1(t, p, d);
      return d.Magnitude() > 0 ? (x.t1 < x.t0 ? -d : d) / d.Magnitude() : d;
    };
    const gp_Vec own = direction(run, (run.t0 + run.t1) / 2);
    const Run& before = runs[(r + runs.size() - 1) % runs.size()];
    const Run& after = runs[(r + 1) % runs.size()];
    return own.Dot(direction(before, before.t1)) < -kAntiParallel ||
           own.Dot(direction(after, after.t0)) < -kAntiParallel;
  };
  double lo, hi;
  for (size_t r = 0; r < runs.size() && runs.size() > 2;) {
    if (stretch(sources[runs[r].source], runs[r], lo, hi) && !spike(r, lo, hi)) {
      ++r;
      continue;
    }
    runs.erase(runs.begin() + static_cast<long>(r));
    refine((r + runs.size() - 1) % runs.size());
    r = 0;
  }
  BRep_Builder builder;
  std::vector<TopoDS_Vertex> ends(runs.size());
  for (size_t r = 0; r < runs.size(); ++r) {
    const Run& a = runs[r];
    const Run& b = runs[(r + 1) % runs.size()];
    const gp_Pnt pa = sources[a.source].curve->Value(a.t1), pb = sources[b.source].curve->Value(b.t0);
    const gp_Pnt mid((pa.XYZ() + pb.XYZ()) / 2);
    builder.MakeVertex(ends[r], mid, std::max(Precision::Confusion(), 1.01 * pa.Distance(pb) / 2));
  }
  std::vector<TopoDS_Edge> out;
  for (size_t r = 0; r < runs.size(); ++r) {
    const Run& run = runs[r];
    const Source& s = sources[run.source];
    const TopoDS_Vertex& first = ends[(r + runs.size() - 1) % runs.size()];
    const TopoDS_Vertex& last = ends[r];
    const bool forward = run.t1 > run.t0;
    if (!stretch(s, run, lo, hi)) return {};
    const TopoDS_Vertex& vlo = forward ? first : last;
    const TopoDS_Vertex& vhi = forward ? last : first;
    for (const auto& [t, v] : {std::pair{lo, vlo}, std::pair{hi, vhi}}) {
      const double gap = s.curve->Value(t).Distance(BRep_Tool::Pnt(v));
      if (gap > BRep_Tool::Tolerance(v)) builder.UpdateVertex(v, gap * 1.01);
    }
    TopoDS_Edge edge;
    builder.MakeEdge(edge, s.curve, s.tolerance);
    builder.Add(edge, vlo.Oriented(TopAbs_FORWARD));
    builder.Add(edge, vhi.Oriented(TopAbs_REVERSED));
    builder.Range(edge, lo, hi);
    out.push_back(forward ? edge : TopoDS::Edge(edge.Reversed()));
  }
  return out;
}

}  // namespace

TopoDS_Shape rebuiltFaces(const std::vector<TopoDS_Shape>& shapes,
                          const std::function<Region2d(const std::vector<Region2d>&)>& combine,
                          const SliceFrame& frame, double position, double deflection) try {
  std::vector<Source> sources;
  std::vector<Region2d> polygons;
  for (const TopoDS_Shape& shape : shapes) {
    std::vector<Region2d> pieces;
    for (TopExp_Explorer f(shape, TopAbs_FACE); f.More(); f.Next()) {
      const TopoDS_Face& face = TopoDS::Face(f.Current());
      std::vector<Region2d::Loop> loops;
      for (TopExp_Explorer w(face, TopAbs_WIRE); w.More(); w.Next()) {
        Region2d::Loop loop;
        for (BRepTools_WireExplorer it(TopoDS::Wire(w.Current()), face); it.More(); it.Next()) {
          const TopoDS_Edge& edge = it.Current();
          TopLoc_Location location;
          double first, last;
          const Handle(Geom_Curve) curve = BRep_Tool::Curve(edge, location, first, last);
          if (curve.IsNull()) return {};
          Source s;
          s.curve = location.IsIdentity()
                        ? curve
                        : Handle(Geom_Curve)::DownCast(curve->Transformed(location.Transformation()));
          s.tolerance = BRep_Tool::Tolerance(edge);
          const CurveSamples samples = sampleEdge(edge, deflection);
          if (samples.p.size() < 2) return {};
          s.t = samples.t;
          for (const gp_Pnt& p : samples.p) s.p.push_back(frame.to2d({p.X(), p.Y(), p.Z()}));
          // The polygon ends at the edge's vertices, not its curve's ends: they may lie apart by
          // up to the vertices' tolerance (linkrods.step: far more than kOnPolygon), and the
          // loop must run on from one edge's polygon onto the next's.
          TopoDS_Vertex v0, v1;
          TopExp::Vertices(edge, v0, v1);
          for (const auto& [v, end] : {std::pair{v0, &s.p.front()}, std::pair{v1, &s.p.back()}})
            if (!v.IsNull()) {
              const gp_Pnt q = BRep_Tool::Pnt(v);
              *end = frame.to2d({q.X(), q.Y(), q.Z()});
            }
          std::vector<Vec2> points = s.p;
          if (it.Orientation() == TopAbs_REVERSED) std::reverse(points.begin(), points.end());
          loop.insert(loop.end(), points.begin(), points.end() - 1);  // the next edge starts there
          sources.push_back(std::move(s));
        }
        loops.push_back(std::move(loop));
      }
      pieces.push_back(Region2d::fromLoops(loops, FillRule::EvenOdd));
    }
    polygons.push_back(Region2d::uniteAll(pieces));
  }
  const Region2d region = combine(polygons);
  if (region.empty()) return {};
  const SegmentGrid grid(sources, std::max(0.5, 20 * deflection));
  const Vec3 o = frame.normal * position;
  const gp_Pln plane(gp_Ax3(gp_Pnt(o.x, o.y, o.z), gp_Dir(frame.normal.x, frame.normal.y, frame.normal.z),
                            gp_Dir(frame.xAxis.x, frame.xAxis.y, frame.xAxis.z)));
  BRep_Builder builder;
  TopoDS_Compound out;
  builder.MakeCompound(out);
  for (const Region2d& piece : region.components()) {
    std::vector<Region2d::Loop> loops = piece.loops();  // outer (counter-clockwise) first
    std::stable_partition(loops.begin(), loops.end(),
                          [](const Region2d::Loop& l) { return Region2d::signedArea(l) > 0; });
    std::optional<BRepBuilderAPI_MakeFace> face;
    for (const Region2d::Loop& loop : loops) {
      // A hole narrower than a quarter of a deflection is a crumb of rounding, no hole:
      // where a slice is tangent to a cylinder (occt-misc Bottom.brep at 35°), two 5 µm arcs
      // of one ellipse enclose no area and touch the outer loop, and the face fails
      // BRepCheck ("intersecting wires"). sameRegion below still compares the face with the
      // region, crumb included.
      if (face && isCrumb(loop, deflection / 4)) continue;
      const std::vector<TopoDS_Edge> edges = loopEdges(loop, sources, grid, frame, position, deflection);
      if (edges.empty()) return {};
      TopoDS_Wire wire;
      builder.MakeWire(wire);
      for (const TopoDS_Edge& e : edges) builder.Add(wire, e);
      wire.Closed(Standard_True);
      if (!face)
        face.emplace(plane, wire, Standard_False);  // outer loops run counter-clockwise: no check
      else
        face->Add(wire);
      if (!face->IsDone()) return {};
    }
    const TopoDS_Face made = face->Face();
    builder.Add(out, made);
  }
  if (!sameRegion(polygoniseFaces(out, frame, deflection), region, deflection)) return {};
  return out;
} catch (const Standard_Failure&) {
  return {};
}

}  // namespace sliceform
