// SPDX-License-Identifier: LGPL-2.1-or-later
#include "layout/labels.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace sliceform {
namespace {

// Glyphs on a 4 x 6 grid, baseline at y = 0: only what patch ids use (U, V, digits) and
// what the sheets' scale marks say ("50 mm", "1/3"). Seven-segment shapes stay legible at 1.5 mm and engrave
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
  };
  return glyphs;
}
constexpr double kAdvance = 5.5;  // grid units per character
constexpr double kCap = 6;
constexpr double kEdgeMargin = 0.6;  // mm of paper between a label and any cut
constexpr double kGap = 0.6;         // mm between labels, and between a label and its slot

using ClipperLib::cInt;
using ClipperLib::IntPoint;
using ClipperLib::Path;
using ClipperLib::Paths;

// Labels need no micrometres: erosions here round their corners to 0.02 mm (Region2d's
// own offset keeps 1 µm, which makes every round corner hundreds of vertices).
constexpr double kLabelTolerance = 0.02;  // mm

Region2d erode(const Region2d& region, double mm) {
  ClipperLib::ClipperOffset offsetter;
  offsetter.ArcTolerance = kLabelTolerance * Region2d::kUnitsPerMm;
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

Region2d rect(Vec2 centre, double halfW, double halfH) {
  return Region2d::fromLoops({{{centre.x - halfW, centre.y - halfH},
                               {centre.x + halfW, centre.y - halfH},
                               {centre.x + halfW, centre.y + halfH},
                               {centre.x - halfW, centre.y + halfH}}});
}

// Where the centre of a halfW x halfH box can go so the box stays in `region`: the region
// minus the band its boundary sweeps with the box (an exact Minkowski erosion). The sweep
// only catches boxes that some boundary crosses; a loop lying wholly inside the box (a
// small island or hole) is caught by the box around one of its vertices.
Region2d erodeByBox(const Region2d& region, double halfW, double halfH) {
  if (region.empty()) return {};
  const cInt w = Region2d::toUnits(halfW), h = Region2d::toUnits(halfH);
  const Path box = {{-w, -h}, {w, -h}, {w, h}, {-w, h}};
  Paths sweep;
  for (Path loop : region.paths()) {
    if (loop.empty()) continue;
    loop.push_back(loop.front());  // swept as a closed polyline, its inside left alone
    Paths band;
    ClipperLib::MinkowskiSum(box, loop, band, false);
    sweep.insert(sweep.end(), band.begin(), band.end());
    Path around = box;
    for (IntPoint& q : around) q = {q.X + loop.front().X, q.Y + loop.front().Y};
    sweep.push_back(around);
  }
  return region.subtract(Region2d::fromPaths(sweep, FillRule::NonZero));
}

bool contains(const Region2d& region, Vec2 p) {
  const IntPoint q{Region2d::toUnits(p.x), Region2d::toUnits(p.y)};
  int depth = 0;
  for (const Path& loop : region.paths()) {
    const int in = ClipperLib::PointInPolygon(q, loop);
    if (in != 0) depth += ClipperLib::Orientation(loop) ? 1 : -1;
  }
  return depth > 0;
}

// The deepest point of a region, found by eroding it until little is left.
Vec2 deepestPoint(const Region2d& region) {
  const Box2 b = region.bounds();
  double lo = 0, hi = std::max(b.max.x - b.min.x, b.max.y - b.min.y) / 2;
  Region2d core = region;
  for (int i = 0; i < 12; ++i) {
    const double mid = (lo + hi) / 2;
    const Region2d eroded = erode(region, mid);
    if (eroded.empty()) {
      hi = mid;
    } else {
      lo = mid;
      core = eroded;
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

// The point of `region` nearest to `p` (p itself when inside).
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

// The paper a label of half size `half` may have its centre on: away from every cut, clear
// of the labels already placed, and inside `window` when one is given. The paper is
// clipped to the window first (grown by the box and the margin, so the clipped edges erode
// only outside the window): eroding a small piece is much cheaper than the whole patch.
Region2d freeFor(const Region2d& paper, const std::vector<Label>& taken, Vec2 half, const Region2d* window) {
  Region2d near = paper;
  if (window) {
    const Box2 w = window->bounds();
    const Vec2 grow{half.x + kEdgeMargin + 1, half.y + kEdgeMargin + 1};
    near = paper.intersect(rect({(w.min.x + w.max.x) / 2, (w.min.y + w.max.y) / 2},
                                (w.max.x - w.min.x) / 2 + grow.x, (w.max.y - w.min.y) / 2 + grow.y));
  }
  Region2d room = erodeByBox(erode(near, kEdgeMargin), half.x, half.y);
  if (window) room = room.intersect(*window);
  // Labels already set keep their distance: one subtraction of the boxes that reach the
  // room at all, not one per label (a patch can carry dozens).
  if (room.empty() || taken.empty()) return room;
  const Box2 b = room.bounds();
  std::vector<Region2d::Loop> boxes;
  for (const Label& l : taken) {
    const Vec2 other = halfSize(l.text, l.height, l.vertical);
    const double hx = other.x + half.x + kGap, hy = other.y + half.y + kGap;
    if (l.at.x + hx < b.min.x || l.at.x - hx > b.max.x || l.at.y + hy < b.min.y || l.at.y - hy > b.max.y)
      continue;
    boxes.push_back({{l.at.x - hx, l.at.y - hy},
                     {l.at.x + hx, l.at.y - hy},
                     {l.at.x + hx, l.at.y + hy},
                     {l.at.x - hx, l.at.y + hy}});
  }
  return boxes.empty() ? room : room.subtract(Region2d::fromLoops(boxes, FillRule::NonZero));
}

}  // namespace

double labelWidth(const std::string& text, double height) {
  return text.empty() ? 0.0 : (text.size() * kAdvance - (kAdvance - 4)) * height / kCap;
}

Label setLabel(const std::string& text, Vec2 at, double height, bool vertical) {
  Label label{text, at, height, vertical, {}};
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

Label placeName(const Region2d& paperIn, const std::string& id) {
  const Region2d paper = simplified(paperIn);
  for (const double height : {8.0, 6.0, 5.0, 4.0, 3.0, 2.5, 2.0, 1.6, 1.3, 1.0})
    for (const bool vertical : {false, true}) {
      // No box fits where a disc as wide as the box's short side does not: a cheap test first.
      if (erode(paper, kEdgeMargin + height / 2).empty()) continue;
      const Region2d room = freeFor(paper, {}, halfSize(id, height, vertical), nullptr);
      if (!room.empty()) return setLabel(id, deepestPoint(room), height, vertical);
    }
  return Label{id, {}, 0, false, {}};
}

std::vector<Label> placePartners(const Region2d& paperIn, const std::vector<LabelSpot>& spots,
                                 const std::vector<Label>& taken, double maxHeight, int& missing) {
  const Region2d paper = simplified(paperIn);
  std::vector<Label> placed, all = taken;
  for (const LabelSpot& s : spots) {
    bool done = false;
    for (double height = std::min(maxHeight, 3.5); height >= 1.0 - 1e-9 && !done; height *= 0.8) {
      const Vec2 half = halfSize(s.text, height, false);
      // Beside the slot, over the hinge's stretch of the line, on either side.
      const double reach = s.slotWidth / 2 + kGap + 2 * half.x + kGap;
      const Region2d near = rect({s.x, (s.w.lo + s.w.hi) / 2}, reach, (s.w.hi - s.w.lo) / 2 + half.y);
      const Region2d room = freeFor(paper, all, half, &near);
      if (room.empty()) continue;
      const double side = s.slotWidth / 2 + kGap + half.x;
      const Vec2 right = nearestPoint(room, {s.x + side, s.y}), left = nearestPoint(room, {s.x - side, s.y});
      const bool useRight = std::hypot(right.x - s.x - side, right.y - s.y) <=
                            std::hypot(left.x - s.x + side, left.y - s.y) + 1e-9;
      placed.push_back(setLabel(s.text, useRight ? right : left, height, false));
      all.push_back(placed.back());
      done = true;
    }
    if (!done) ++missing;
  }
  return placed;
}

}  // namespace sliceform
