// SPDX-License-Identifier: LGPL-2.1-or-later
#include "geometry/region2d.hpp"

#include <algorithm>
#include <cmath>

#include "support/error.hpp"

namespace sliceform {
namespace {

using ClipperLib::Clipper;
using ClipperLib::Paths;

ClipperLib::PolyFillType toClipper(FillRule rule) {
  return rule == FillRule::EvenOdd ? ClipperLib::pftEvenOdd : ClipperLib::pftNonZero;
}

Paths boolean(const Paths& a, const Paths& b, ClipperLib::ClipType op) {
  Clipper clipper;
  clipper.AddPaths(a, ClipperLib::ptSubject, true);
  clipper.AddPaths(b, ClipperLib::ptClip, true);
  Paths out;
  clipper.Execute(op, out, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
  return out;
}

}  // namespace

ClipperLib::cInt Region2d::toUnits(double mm) {
  const double units = std::round(mm * kUnitsPerMm);
  // Clipper's full range is 2^62; stay well inside it so sums cannot overflow.
  if (!std::isfinite(units) || std::fabs(units) > 4.0e18 / 4)
    throw Error(ErrorKind::BadInput, "coordinate out of range: " + std::to_string(mm) + " mm");
  return static_cast<ClipperLib::cInt>(units);
}

Region2d Region2d::fromLoops(const std::vector<Loop>& loops, FillRule rule) {
  Paths paths;
  paths.reserve(loops.size());
  for (const Loop& loop : loops) {
    ClipperLib::Path path;
    path.reserve(loop.size());
    for (const Vec2& p : loop) path.push_back({toUnits(p.x), toUnits(p.y)});
    if (path.size() >= 3) paths.push_back(std::move(path));
  }
  return fromPaths(paths, rule);
}

Region2d Region2d::fromPaths(const Paths& paths, FillRule rule) {
  Region2d region;
  Clipper clipper;
  clipper.AddPaths(paths, ClipperLib::ptSubject, true);
  clipper.Execute(ClipperLib::ctUnion, region.paths_, toClipper(rule), toClipper(rule));
  // Drop zero-area slivers the union can leave (collinear spikes of mesh sections).
  ClipperLib::CleanPolygons(region.paths_, 1.415);
  region.paths_.erase(std::remove_if(region.paths_.begin(), region.paths_.end(),
                                     [](const ClipperLib::Path& p) { return p.size() < 3; }),
                      region.paths_.end());
  return region;
}

Region2d Region2d::withoutHoles() const {
  Paths outer;
  for (const ClipperLib::Path& p : paths_)
    if (ClipperLib::Orientation(p)) outer.push_back(p);
  return fromPaths(outer, FillRule::NonZero);
}

Region2d Region2d::uniteAll(const std::vector<Region2d>& regions) {
  // Pairwise, as a balanced tree: one sweep over every outline at once pays for every
  // crossing of every pair (hundreds of stacked, similar slices: quadratic), while a union
  // of two similar shapes is about one shape again.
  if (regions.empty()) return {};
  std::vector<Region2d> level = regions;
  while (level.size() > 1) {
    std::vector<Region2d> next;
    next.reserve((level.size() + 1) / 2);
    for (size_t i = 0; i + 1 < level.size(); i += 2) {
      Paths both = level[i].paths_;
      both.insert(both.end(), level[i + 1].paths_.begin(), level[i + 1].paths_.end());
      next.push_back(fromPaths(both, FillRule::NonZero));
    }
    if (level.size() % 2) next.push_back(level.back());
    level = std::move(next);
  }
  // A single region is normalised too (its own overlaps united), as before.
  return fromPaths(level.front().paths_, FillRule::NonZero);
}

std::vector<Region2d::Loop> Region2d::loops() const {
  std::vector<Loop> out;
  out.reserve(paths_.size());
  for (const ClipperLib::Path& path : paths_) {
    Loop loop;
    loop.reserve(path.size());
    for (const ClipperLib::IntPoint& p : path) loop.push_back({toMm(p.X), toMm(p.Y)});
    out.push_back(std::move(loop));
  }
  return out;
}

double Region2d::area() const {
  double sum = 0;
  for (const ClipperLib::Path& path : paths_) sum += ClipperLib::Area(path);
  return sum / (kUnitsPerMm * kUnitsPerMm);
}

Box2 Region2d::bounds() const {
  Box2 box;
  for (const ClipperLib::Path& path : paths_) {
    for (const ClipperLib::IntPoint& p : path) {
      const Vec2 q{toMm(p.X), toMm(p.Y)};
      if (box.empty) {
        box = {q, q, false};
        continue;
      }
      box.min = {std::min(box.min.x, q.x), std::min(box.min.y, q.y)};
      box.max = {std::max(box.max.x, q.x), std::max(box.max.y, q.y)};
    }
  }
  return box;
}

int Region2d::holeCount() const {
  return static_cast<int>(std::count_if(
      paths_.begin(), paths_.end(), [](const ClipperLib::Path& p) { return !ClipperLib::Orientation(p); }));
}

std::vector<Region2d> Region2d::components() const {
  Clipper clipper;
  clipper.AddPaths(paths_, ClipperLib::ptSubject, true);
  ClipperLib::PolyTree tree;
  clipper.Execute(ClipperLib::ctUnion, tree, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
  std::vector<Region2d> out;
  forEachComponent(tree,
                   [&](const Paths& paths) { out.push_back(Region2d::fromPaths(paths, FillRule::NonZero)); });
  return out;
}

std::vector<Region2d> Region2d::subtractComponents(const Region2d& other) const {
  Clipper clipper;
  clipper.AddPaths(paths_, ClipperLib::ptSubject, true);
  clipper.AddPaths(other.paths_, ClipperLib::ptClip, true);
  ClipperLib::PolyTree tree;
  clipper.Execute(ClipperLib::ctDifference, tree, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
  std::vector<Region2d> out;
  forEachComponent(tree,
                   [&](const Paths& paths) { out.push_back(Region2d::fromPaths(paths, FillRule::NonZero)); });
  return out;
}

Region2d Region2d::unite(const Region2d& other) const {
  Region2d r;
  r.paths_ = boolean(paths_, other.paths_, ClipperLib::ctUnion);
  return r;
}

Region2d Region2d::intersect(const Region2d& other) const {
  Region2d r;
  r.paths_ = boolean(paths_, other.paths_, ClipperLib::ctIntersection);
  return r;
}

Region2d Region2d::subtract(const Region2d& other) const {
  Region2d r;
  r.paths_ = boolean(paths_, other.paths_, ClipperLib::ctDifference);
  return r;
}

Region2d Region2d::offset(double deltaMm) const {
  ClipperLib::ClipperOffset offsetter;
  // Arc tolerance 1 µm: round corners stay round at any print size.
  offsetter.ArcTolerance = 0.001 * kUnitsPerMm;
  offsetter.AddPaths(paths_, ClipperLib::jtRound, ClipperLib::etClosedPolygon);
  Region2d r;
  offsetter.Execute(r.paths_, deltaMm * kUnitsPerMm);
  return r;
}

std::vector<Interval> Region2d::intervalsOnLine(Vec2 point, Vec2 dir) const {
  // Half-open side test (s > 0 versus s <= 0) so a vertex exactly on the line is counted
  // once and edges along the line not at all: the crossings always pair up.
  std::vector<double> ts;
  for (const ClipperLib::Path& path : paths_) {
    const size_t n = path.size();
    for (size_t i = 0; i < n; ++i) {
      const Vec2 a{toMm(path[i].X) - point.x, toMm(path[i].Y) - point.y};
      const Vec2 b{toMm(path[(i + 1) % n].X) - point.x, toMm(path[(i + 1) % n].Y) - point.y};
      const double sa = dir.x * a.y - dir.y * a.x;
      const double sb = dir.x * b.y - dir.y * b.x;
      if ((sa > 0) == (sb > 0)) continue;
      const double f = sa / (sa - sb);
      const Vec2 c{a.x + f * (b.x - a.x), a.y + f * (b.y - a.y)};
      ts.push_back(c.x * dir.x + c.y * dir.y);
    }
  }
  std::sort(ts.begin(), ts.end());
  std::vector<Interval> out;
  for (size_t i = 0; i + 1 < ts.size(); i += 2) {
    if (ts[i + 1] > ts[i]) out.push_back({ts[i], ts[i + 1]});
  }
  return out;
}

double Region2d::signedArea(const Loop& loop) {
  double twice = 0;
  for (size_t i = 0, n = loop.size(); i < n; ++i)
    twice += loop[i].x * loop[(i + 1) % n].y - loop[(i + 1) % n].x * loop[i].y;
  return twice / 2;
}

}  // namespace sliceform
