// SPDX-License-Identifier: LGPL-2.1-or-later
#include "layout/labels.hpp"
#include "layout/label_room.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace sliceform {
namespace {

// Glyphs on a 4 x 6 grid, baseline at y = 0: only what patch ids use (U, V, digits), what
// the sheets' scale marks say ("50 mm", "1/3"), the fit coupon's marks ("0.25", "E2.0",
// "F2.0") and assembly steps ("#12"). Seven-segment shapes stay legible at 1.5 mm and engrave
// quickly.
using Glyph = std::vector<std::vector<Vec2>>;
const std::map<char, Glyph>& font() {
  static const std::map<char, Glyph> glyphs = {
      {'0', {{{0, 0}, {4, 0}, {4, 6}, {0, 6}, {0, 0}}, {{0, 0}, {4, 6}}}},
      {'1', {{{1, 5}, {2, 6}, {2, 0}}, {{1, 0}, {3, 0}}}},
      {'2', {{{0, 6}, {4, 6}, {4, 3}, {0, 3}, {0, 0}, {4, 0}}}},
      {'3', {{{0, 6}, {4, 6}, {4, 0}, {0, 0}}, {{1, 3}, {4, 3}}}},
      {'4', {{{0, 6}, {0, 3}, {4, 3}}, {{4, 6}, {4, 0}}}},
      {'5', {{{4, 6}, {0, 6}, {0, 3}, {4, 3}, {4, 0}, {0, 0}}}},
      {'6', {{{4, 6}, {0, 6}, {0, 0}, {4, 0}, {4, 3}, {0, 3}}}},
      {'7', {{{0, 6}, {4, 6}, {2, 0}}}},
      {'8', {{{0, 0}, {4, 0}, {4, 6}, {0, 6}, {0, 0}}, {{0, 3}, {4, 3}}}},
      {'9', {{{4, 3}, {0, 3}, {0, 6}, {4, 6}, {4, 0}, {0, 0}}}},
      {'U', {{{0, 6}, {0, 1}, {1, 0}, {3, 0}, {4, 1}, {4, 6}}}},
      {'V', {{{0, 6}, {2, 0}, {4, 6}}}},
      {'-', {{{1, 3}, {3, 3}}}},
      {'/', {{{0, 0}, {4, 6}}}},
      {'m', {{{0, 0}, {0, 4}}, {{0, 3}, {1, 4}, {2, 3}, {2, 0}}, {{2, 3}, {3, 4}, {4, 3}, {4, 0}}}},
      {'x', {{{0, 0}, {4, 4}}, {{0, 4}, {4, 0}}}},
      {'.', {{{1.5, 0}, {2.5, 0}, {2.5, 1}, {1.5, 1}, {1.5, 0}}}},
      {'E', {{{4, 6}, {0, 6}, {0, 0}, {4, 0}}, {{0, 3}, {3, 3}}}},
      {'F', {{{4, 6}, {0, 6}, {0, 0}}, {{0, 3}, {3, 3}}}},
      {'#', {{{1, 0}, {1.5, 6}}, {{2.5, 0}, {3, 6}}, {{0, 2}, {4, 2}}, {{0, 4}, {4, 4}}}},
  };
  return glyphs;
}
constexpr double kAdvance = 5.5;  // grid units per character
constexpr double kCap = 6;
constexpr double kEdgeMargin = 0.6;  // mm of paper between a label and any cut

using ClipperLib::cInt;
using ClipperLib::IntPoint;
using ClipperLib::Path;
using ClipperLib::Paths;

// Labels need no micrometres: erosions here round their corners to 0.02 mm (Region2d's
// own offset keeps 1 µm, which makes every round corner hundreds of vertices).
constexpr double kLabelTolerance = 0.02;  // mm
// For tests that only ask whether anything is left (see placeName).
constexpr double kCoarseTolerance = 0.25;  // mm

Region2d erode(const Region2d& region, double mm, double tolerance = kLabelTolerance) {
  ClipperLib::ClipperOffset offsetter;
  offsetter.ArcTolerance = tolerance * Region2d::kUnitsPerMm;
  offsetter.AddPaths(region.paths(), ClipperLib::jtRound, ClipperLib::etClosedPolygon);
  Paths out;
  offsetter.Execute(out, -mm * Region2d::kUnitsPerMm);
  return Region2d::fromPaths(out, FillRule::NonZero);
}

// The paper with vertices closer than the tolerance merged: fewer, longer edges to sweep.
Region2d simplified(const Region2d& paper) {
  Paths paths = paper.paths();
  ClipperLib::CleanPolygons(paths, kLabelTolerance * Region2d::kUnitsPerMm);
  return Region2d::fromPaths(paths, FillRule::NonZero);
}

// Integer box [lo, hi] in Clipper units.
struct UnitBox {
  IntPoint lo, hi;
  bool meets(const UnitBox& o) const {
    return lo.X <= o.hi.X && o.lo.X <= hi.X && lo.Y <= o.hi.Y && o.lo.Y <= hi.Y;
  }
};

Path boxPath(const UnitBox& b) {
  return {{b.lo.X, b.lo.Y}, {b.hi.X, b.lo.Y}, {b.hi.X, b.hi.Y}, {b.lo.X, b.hi.Y}};
}

// What an axis-aligned box of half size (w, h) covers as its centre runs along a chain of
// edges that all head into one quadrant (sx, sy = ±1: none goes left when sx > 0, none
// down when sy > 0): the band between the chain traced by the box's two corners across the
// heading, (sx w, -sy h) and (-sx w, sy h), closed by the box at either end. Above and
// below any x the box reaches, the chain's highest and lowest points lie at the far ends
// of its reach, so those two traces are exactly the band's top and bottom. One polygon
// per run instead of a convex piece per edge: the overlaps Clipper has to resolve are
// those between runs, not those of every edge with its dozens of short neighbours.
void addRun(const Path& run, int sx, int sy, cInt w, cInt h, Paths& out) {
  const cInt cx = sx * w, cy = sy * h;
  Path band;
  band.reserve(2 * run.size() + 2);
  band.push_back({run.front().X - cx, run.front().Y - cy});
  for (const IntPoint& a : run) band.push_back({a.X + cx, a.Y - cy});
  band.push_back({run.back().X + cx, run.back().Y + cy});
  for (size_t i = run.size(); i-- > 0;) band.push_back({run[i].X - cx, run[i].Y + cy});
  // Counter-clockwise when heading up-right or down-left; a mirror image otherwise.
  if (sx * sy < 0) std::reverse(band.begin(), band.end());
  out.push_back(std::move(band));
}

// The bands the boundary of `region` sweeps with a box of half size (w, h), for the edges
// whose band can reach `near`. A box centred at p
// lies in the region exactly when p is in the region and outside every band: a box the
// boundary does not cross holds either none or all of a loop, and then it holds the
// loop's vertices, which the bands of that loop's edges cover.
Paths sweptBands(const Region2d& region, cInt w, cInt h, const UnitBox& near) {
  Paths bands;
  Path run;
  int sx = 0, sy = 0;  // the run's heading; 0 while its edges left it open
  const auto flush = [&] {
    if (run.size() >= 2) addRun(run, sx < 0 ? -1 : 1, sy < 0 ? -1 : 1, w, h, bands);
    run.clear();
    sx = sy = 0;
  };
  for (const Path& loop : region.paths()) {
    for (size_t i = 0, n = loop.size(); i < n; ++i) {
      const IntPoint a = loop[i], b = loop[(i + 1) % n];
      const UnitBox reach{{std::min(a.X, b.X) - w, std::min(a.Y, b.Y) - h},
                          {std::max(a.X, b.X) + w, std::max(a.Y, b.Y) + h}};
      if (!reach.meets(near)) {
        flush();
        continue;
      }
      const int dx = (b.X > a.X) - (b.X < a.X), dy = (b.Y > a.Y) - (b.Y < a.Y);
      if ((dx && sx && dx != sx) || (dy && sy && dy != sy)) flush();
      if (run.empty()) run.push_back(a);
      run.push_back(b);
      if (dx) sx = dx;
      if (dy) sy = dy;
    }
    flush();
  }
  return bands;
}

bool contains(const Region2d& region, IntPoint q) {
  int depth = 0;
  for (const Path& loop : region.paths()) {
    const int in = ClipperLib::PointInPolygon(q, loop);
    if (in != 0) depth += ClipperLib::Orientation(loop) ? 1 : -1;
  }
  return depth > 0;
}

bool contains(const Region2d& region, Vec2 p) {
  return contains(region, IntPoint{Region2d::toUnits(p.x), Region2d::toUnits(p.y)});
}

// The part of `region` inside the box grown by `grow` mm on every side.
Region2d near(const Region2d& region, const Box2& box, double grow) {
  const UnitBox b{{Region2d::toUnits(box.min.x - grow), Region2d::toUnits(box.min.y - grow)},
                  {Region2d::toUnits(box.max.x + grow), Region2d::toUnits(box.max.y + grow)}};
  return region.intersect(Region2d::fromPaths({boxPath(b)}, FillRule::NonZero));
}

// The deepest point of a region, found by eroding it until little is left.
Vec2 deepestPoint(const Region2d& region) {
  const Box2 b = region.bounds();
  double lo = 0, hi = std::max(b.max.x - b.min.x, b.max.y - b.min.y) / 2;
  Region2d core = region;
  bool deeper = false;  // core is an erosion of the region, not the region itself
  for (int i = 0; i < 12; ++i) {
    const double mid = (lo + hi) / 2;
    // Deeper than the last core, the erosion lies inside that core (give or take the
    // rounding of its corners), and only the boundary within `mid` of it shapes it: the
    // region clipped a millimetre beyond that erodes to the same polygon, from far fewer
    // corners to round.
    const Region2d eroded = erode(deeper ? near(region, core.bounds(), mid + 1) : region, mid);
    if (eroded.empty()) {
      hi = mid;
    } else {
      lo = mid;
      core = eroded;
      deeper = true;
    }
  }
  // The centroid of the largest remaining piece, if it is inside it; else a vertex.
  // A sliver can erode to paths with no area and so no components: then the box centre.
  std::vector<Region2d> pieces = core.components();
  if (pieces.empty()) return {(b.min.x + b.max.x) / 2, (b.min.y + b.max.y) / 2};
  const Region2d& best = *std::max_element(
      pieces.begin(), pieces.end(), [](const Region2d& a, const Region2d& c) { return a.area() < c.area(); });
  const Box2 bb = best.bounds();
  const Vec2 centre{(bb.min.x + bb.max.x) / 2, (bb.min.y + bb.max.y) / 2};
  if (contains(best, centre) || best.loops().empty() || best.loops().front().empty()) return centre;
  return best.loops().front().front();
}

}  // namespace

bool regionContains(const Region2d& region, Vec2 p) {
  return contains(region, p);
}

Vec2 nearestPoint(const Region2d& region, Vec2 p) {
  if (contains(region, p)) return p;
  Vec2 best = p;
  double bestD = HUGE_VAL;
  for (const Region2d::Loop& loop : region.loops())
    for (size_t i = 0; i < loop.size(); ++i) {
      const Vec2 a = loop[i], c = loop[(i + 1) % loop.size()];
      const double dx = c.x - a.x, dy = c.y - a.y, len2 = dx * dx + dy * dy;
      const double t = len2 > 0 ? std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / len2, 0.0, 1.0) : 0.0;
      const Vec2 q{a.x + t * dx, a.y + t * dy};
      const double d = std::hypot(q.x - p.x, q.y - p.y);
      if (d < bestD) bestD = d, best = q;
    }
  return best;
}

Vec2 halfSize(const std::string& text, double height, bool vertical) {
  const double w = labelWidth(text, height) / 2, h = height / 2;
  return vertical ? Vec2{h, w} : Vec2{w, h};
}

// A window needs only the boundary near it: the window minus the bands of the nearby edges
// and the labels' boxes falls into pieces that each lie wholly inside or wholly outside
// `inner` (no band crosses them, and a box that stays clear of the boundary cannot change
// sides), so one vertex of each piece decides it.
Region2d freeFor(const Region2d& inner, const std::vector<Label>& taken, Vec2 half, const Box2& window,
                 const std::vector<Box2>& keepOff) {
  if (inner.empty()) return {};
  const cInt w = Region2d::toUnits(half.x), h = Region2d::toUnits(half.y);
  const UnitBox near{{Region2d::toUnits(window.min.x), Region2d::toUnits(window.min.y)},
                     {Region2d::toUnits(window.max.x), Region2d::toUnits(window.max.y)}};
  Paths clip = sweptBands(inner, w, h, near);
  // Labels already set keep their distance: their boxes, grown by this one and the gap,
  // join the bands (only those that reach the window).
  for (const Label& l : taken) {
    const Vec2 other = halfSize(l.text, l.height, l.vertical);
    const double hx = other.x + half.x + kGap, hy = other.y + half.y + kGap;
    const UnitBox box{{Region2d::toUnits(l.at.x - hx), Region2d::toUnits(l.at.y - hy)},
                      {Region2d::toUnits(l.at.x + hx), Region2d::toUnits(l.at.y + hy)}};
    if (box.meets(near)) clip.push_back(boxPath(box));
  }
  // So do the boxes in `keepOff`, with no gap.
  for (const Box2& b : keepOff) {
    const UnitBox box{{Region2d::toUnits(b.min.x - half.x), Region2d::toUnits(b.min.y - half.y)},
                      {Region2d::toUnits(b.max.x + half.x), Region2d::toUnits(b.max.y + half.y)}};
    if (box.meets(near)) clip.push_back(boxPath(box));
  }
  ClipperLib::Clipper clipper;
  clipper.AddPaths(clip, ClipperLib::ptClip, true);
  clipper.AddPath(boxPath(near), ClipperLib::ptSubject, true);
  ClipperLib::PolyTree pieces;
  clipper.Execute(ClipperLib::ctDifference, pieces, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
  Paths room;
  for (const ClipperLib::PolyNode* node = pieces.GetFirst(); node; node = node->GetNext()) {
    if (node->IsHole() || node->Contour.empty() || !contains(inner, node->Contour.front())) continue;
    room.push_back(node->Contour);
    for (const ClipperLib::PolyNode* hole : node->Childs) room.push_back(hole->Contour);
  }
  return Region2d::fromPaths(room, FillRule::NonZero);
}

double labelWidth(const std::string& text, double height) {
  return text.empty() ? 0.0 : (text.size() * kAdvance - (kAdvance - 4)) * height / kCap;
}

Label setLabel(const std::string& text, Vec2 at, double height, bool vertical) {
  Label label{text, at, height, vertical, {}, {}};
  const double s = height / kCap, w = labelWidth(text, height);
  for (size_t i = 0; i < text.size(); ++i) {
    const auto glyph = font().find(text[i]);
    if (glyph == font().end()) continue;
    for (const std::vector<Vec2>& line : glyph->second) {
      Stroke stroke;
      for (const Vec2& g : line) {
        // Box-centred coordinates, then turned a quarter for upright labels.
        const Vec2 q{(i * kAdvance + g.x) * s - w / 2, g.y * s - height / 2};
        stroke.push_back(vertical ? Vec2{at.x - q.y, at.y + q.x} : Vec2{at.x + q.x, at.y + q.y});
      }
      label.strokes.push_back(stroke);
    }
  }
  return label;
}

LabelPaper labelPaper(const Region2d& paper) {
  // A rounded erosion's arcs are chords with their ends on the true arcs, up to the arc
  // tolerance nearer the cut: eroding that much more keeps the whole margin.
  return {erode(simplified(paper), kEdgeMargin + kLabelTolerance), paper};
}

Region2d leaderPaper(const Region2d& paper) {
  return erode(simplified(paper), kLeaderMargin + kLabelTolerance);
}

Label placeName(const Region2d& paper, const std::string& id) {
  return placeName(labelPaper(paper), id);
}

std::vector<Label> placePartners(const Region2d& paper, const std::vector<LabelSpot>& spots,
                                 const std::vector<Label>& taken, double maxHeight, int& missing) {
  return placePartners(labelPaper(paper), spots, taken, maxHeight, missing);
}

Label placeStep(const LabelPaper& paper, const std::string& text, const Label& name,
                const std::vector<Label>& taken) {
  std::vector<Label> all = taken;
  all.push_back(name);
  const std::vector<Box2> leaders = leaderBoxes(taken);
  const Box2 patch = paper.inner.bounds();
  const double top = std::max(kMinLabelHeight, name.height > 0 ? std::min(name.height / 2, 3.5) : 3.5);
  for (double height = top;; height = std::max(kMinLabelHeight, height * 0.8)) {
    for (const bool vertical : {false, true}) {
      const Vec2 half = halfSize(text, height, vertical),
                 id = halfSize(name.text, name.height, name.vertical);
      // Under the id reading the same way, nearest first; the patch's box when no id is set.
      const Vec2 below = name.height > 0
                             ? Vec2{name.at.x, name.at.y - id.y - kGap - half.y}
                             : Vec2{(patch.min.x + patch.max.x) / 2, (patch.min.y + patch.max.y) / 2};
      const Region2d room = freeFor(paper.inner, all, half, patch, leaders);
      if (!room.empty()) return setLabel(text, nearestPoint(room, below), height, vertical);
    }
    if (height <= kMinLabelHeight) break;
  }
  return Label{text, {}, 0, false, {}, {}};
}

const std::vector<double>& nameHeights() {
  static const std::vector<double> heights{8.0, 6.0, 5.0, 4.0, 3.0, 2.5, 2.0, 1.6, 1.3, kMinLabelHeight};
  return heights;
}

Label placeName(const LabelPaper& paper, const std::string& id, const std::vector<Label>& taken,
                double maxHeight) {
  // Every box size searches the same inner paper, eroded once.
  const Region2d& inner = paper.inner;
  for (const double height : nameHeights()) {
    if (height > maxHeight) continue;
    // No box fits where a disc as wide as the box's short side does not: a cheap test first.
    // Its round corners may be coarse: a rounded erosion's corners lie on the true arcs and
    // cut inside them, so it only keeps more than the exact erosion, never less, and calls
    // no region empty that a disc, let alone a box, fits (freeFor decides the rest).
    const Region2d disc = erode(inner, height / 2, kCoarseTolerance);
    if (disc.empty()) continue;
    // Every centre that holds the box holds the disc too: the room lies within the disc's
    // erosion, so only the boundary near that needs sweeping (a hundredth of a millimetre
    // more for the rounding of the box to Clipper's units).
    Box2 within = disc.bounds();
    within.min = {within.min.x - 0.01, within.min.y - 0.01};
    within.max = {within.max.x + 0.01, within.max.y + 0.01};
    for (const bool vertical : {false, true}) {
      const Region2d room = freeFor(inner, taken, halfSize(id, height, vertical), within);
      if (!room.empty()) return setLabel(id, deepestPoint(room), height, vertical);
    }
  }
  return Label{id, {}, 0, false, {}, {}};
}

}  // namespace sliceform
