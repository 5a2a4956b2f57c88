// SPDX-License-Identifier: LGPL-2.1-or-later
#include "layout/flat_patch.hpp"

#include <BRepAdaptor_Curve.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Wire.hxx>
#include <algorithm>

#include <cmath>
#include <set>

#include "layout/labels.hpp"
#include "slicing/edge_samples.hpp"
#include "support/occt_guard.hpp"
#include "support/parallel.hpp"
#include "support/per_family.hpp"

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

// The partner of every hinge of `patch` that is still a hinge once slotted.
std::vector<LabelSpot> partnerSpots(const LayoutInput& d, int patch) {
  const Arrangement& a = d.arrangement;
  const Realization& r = d.realization;
  const Family family = a.scaffold.patches[patch].family;
  const SliceFrame& f = a.slices(family).frame;
  const SliceFrame& g = a.slices(other(family)).frame;
  std::vector<LabelSpot> spots;
  for (size_t h = 0; h < a.scaffold.hinges.size(); ++h) {
    const ScaffoldHinge& hinge = a.scaffold.hinges[h];
    if (hinge.patch(family) != patch || !d.meets[h]) continue;
    const int partner = hinge.patch(other(family));
    const Slot slot = familySlot(family, r.slots[h]);
    const Interval& at = hinge.holds ? hinge.grip : hinge.w;
    const double root = (at.lo + at.hi) / 2;
    // The slot's stretch of the hinge: above the root for an up slot, below for down; its
    // label beside the middle of that.
    const Interval cut = slot == Slot::Up        ? Interval{root, hinge.w.hi}
                         : slot == Slot::Down    ? Interval{hinge.w.lo, root}
                         : slot == Slot::Through ? hinge.w
                                                 : Interval{root, root};
    const double y = slot == Slot::Through ? root : (cut.lo + cut.hi) / 2;
    spots.push_back({patchId(a.scaffold, partner), lineX(f, g, a.scaffold.patches[partner].position), hinge.w,
                     y, r.params.width(), cut});
  }
  return spots;
}

}  // namespace

Vec2 pointAt(const CutElement& e, double t) {
  switch (e.kind) {
    case CutElement::Kind::Line:
      return {e.a.x + t * (e.b.x - e.a.x), e.a.y + t * (e.b.y - e.a.y)};
    case CutElement::Kind::Circle: {
      const double angle = t * kTwoPi;
      return {e.centre.x + e.radius * std::cos(angle), e.centre.y + e.radius * std::sin(angle)};
    }
    case CutElement::Kind::Arc: {
      double sweep = e.ccw ? e.end - e.start : e.start - e.end;
      sweep = std::fmod(sweep + 2 * kTwoPi, kTwoPi);
      const double angle = e.start + (e.ccw ? 1 : -1) * t * sweep;
      return {e.centre.x + e.radius * std::cos(angle), e.centre.y + e.radius * std::sin(angle)};
    }
  }
  return e.a;
}

std::vector<Vec2> sample(const CutElement& e, double deflection) {
  if (e.kind == CutElement::Kind::Line) return {e.a};
  // Chord error r (1 - cos(step / 2)) <= deflection.
  const double step = 2 * std::acos(std::max(-1.0, 1 - deflection / std::max(e.radius, 1e-9)));
  double sweep = kTwoPi;
  if (e.kind == CutElement::Kind::Arc)
    sweep = std::fmod((e.ccw ? e.end - e.start : e.start - e.end) + 2 * kTwoPi, kTwoPi);
  const int n = std::max(2, static_cast<int>(std::ceil(sweep / step)));
  std::vector<Vec2> points;
  for (int i = 0; i < n; ++i) points.push_back(pointAt(e, static_cast<double>(i) / n));
  return points;
}

std::vector<CutLoop> cutPaths(const LayoutInput& d, int k) {
  const PatchPlane plane = patchPlane(d.arrangement, k);
  return cutLoops(kerfCompensated(d.patches[k].shape, d.realization.params.kerf),
                  PlaneMap{plane.xAxis, plane.yAxis});
}

FlatPatch flattenPatch(const LayoutInput& d, int k) {
  const Arrangement& a = d.arrangement;
  FlatPatch flat;
  flat.patch = k;
  flat.id = patchId(a.scaffold, k);
  flat.family = a.scaffold.patches[k].family;
  flat.outline = d.patches[k].outline;
  flat.cut = cutPaths(d, k);
  const LabelPaper paper = labelPaper(flat.outline);
  const std::vector<int>& order = d.realization.assemblyOrder;
  const auto at = std::find(order.begin(), order.end(), k);
  flat.step = at == order.end() ? 0 : static_cast<int>(at - order.begin()) + 1;
  const std::vector<LabelSpot> spots = partnerSpots(d, k);
  PatchLabels labels = labelPatch(paper, flat.id, spots, flat.step);
  flat.name = std::move(labels.name);
  flat.stepLabel = std::move(labels.step);
  flat.partners = std::move(labels.partners);
  // The slots left without, by their partner's id, so the user knows where to write one.
  std::multiset<std::string> labelled;
  for (const Label& l : flat.partners) labelled.insert(l.text);
  for (const LabelSpot& s : spots) {
    const auto found = labelled.find(s.text);
    if (found == labelled.end())
      flat.unlabelled.push_back({s.text, {s.x, s.y}});
    else
      labelled.erase(found);
  }
  for (const Label& l : flat.partners) flat.partnersOnLeaders += !l.leader.empty();
  return flat;
}

}  // namespace sliceform
