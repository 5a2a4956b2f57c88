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

// Labels need no micrometres: erosions here round their corners to 0.02 mm (Region2d's
// own offset keeps 1 µm, which makes every round corner hundreds of vertices).
constexpr double kLabelTolerance = 0.02;  // mm
// For tests that only ask whether anything is left (see placeName).
constexpr double kCoarseTolerance = 0.25;  // mm

Region2d erode(const Region2d& region, double mm, double tolerance = kLabelTolerance) {
  return region.coarseOffset(-mm, tolerance);
}

// The paper with vertices closer than the tolerance merged: fewer, longer edges to sweep.
Region2d simplified(const Region2d& paper) {
  return paper.simplified(kLabelTolerance);
}

// The part of `region` inside the box grown by `grow` mm on every side.
Region2d near(const Region2d& region, const Box2& box, double grow) {
  const Vec2 lo{box.min.x - grow, box.min.y - grow}, hi{box.max.x + grow, box.max.y + grow};
  return region.intersect(Region2d::fromLoops({{lo, {hi.x, lo.y}, hi, {lo.x, hi.y}}}, FillRule::NonZero));
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
  if (best.contains(centre) || best.loops().empty() || best.loops().front().empty()) return centre;
  return best.loops().front().front();
}

// Where the centre of a patch id `height` high may lie in `inner`; empty where none fits.
// No box fits where a disc as wide as the box's short side does not: a cheap test first.
// Its round corners may be coarse: a rounded erosion's corners lie on the true arcs and
// cut inside them, so it only keeps more than the exact erosion, never less, and calls no
// region empty that a disc, let alone a box, fits (freeFor decides the rest).
Box2 nameWindow(const Region2d& inner, double height) {
  const Region2d disc = erode(inner, height / 2, kCoarseTolerance);
  if (disc.empty()) return {};
  // Every centre that holds the box holds the disc too: the room lies within the disc's
  // erosion, so only the boundary near that needs sweeping (a hundredth of a millimetre
  // more for the rounding of the box to Clipper's units).
  Box2 within = disc.bounds();
  within.min = {within.min.x - 0.01, within.min.y - 0.01};
  within.max = {within.max.x + 0.01, within.max.y + 0.01};
  return within;
}

}  // namespace

Vec2 nearestPoint(const Region2d& region, Vec2 p) {
  if (region.contains(p)) return p;
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

Region2d freeFor(const BoxRoom& inner, const std::vector<Label>& taken, Vec2 half, const Box2& window,
                 const std::vector<Box2>& keepOff) {
  if (inner.region().empty()) return {};
  // Labels already set keep their distance: no centre in their boxes grown by this one
  // and the gap. Nor in the boxes of `keepOff` grown by this one, with no gap.
  std::vector<Box2> avoid;
  avoid.reserve(taken.size() + keepOff.size());
  for (const Label& l : taken) {
    const Vec2 other = halfSize(l.text, l.height, l.vertical);
    const double hx = other.x + half.x + kGap, hy = other.y + half.y + kGap;
    avoid.push_back({{l.at.x - hx, l.at.y - hy}, {l.at.x + hx, l.at.y + hy}, false});
  }
  for (const Box2& b : keepOff)
    avoid.push_back({{b.min.x - half.x, b.min.y - half.y}, {b.max.x + half.x, b.max.y + half.y}, false});
  return inner.boxCentres(half, window, avoid);
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
  return {BoxRoom(erode(simplified(paper), kEdgeMargin + kLabelTolerance)), paper, {}, std::nullopt};
}

const BoxRoom& leaderPaper(const LabelPaper& paper) {
  if (!paper.leaders) paper.leaders.emplace(erode(simplified(paper.paper), kLeaderMargin + kLabelTolerance));
  return *paper.leaders;
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
  const Box2 patch = paper.inner.region().bounds();
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
  const BoxRoom& inner = paper.inner;
  for (const double height : nameHeights()) {
    if (height > maxHeight) continue;
    const auto known = paper.nameWindows.find(height);
    const Box2& within =
        known != paper.nameWindows.end()
            ? known->second
            : paper.nameWindows.emplace(height, nameWindow(inner.region(), height)).first->second;
    if (within.empty) continue;
    for (const bool vertical : {false, true}) {
      const Region2d room = freeFor(inner, taken, halfSize(id, height, vertical), within);
      if (!room.empty()) return setLabel(id, deepestPoint(room), height, vertical);
    }
  }
  return Label{id, {}, 0, false, {}, {}};
}

}  // namespace sliceform
