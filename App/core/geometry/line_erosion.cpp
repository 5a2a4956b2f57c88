// SPDX-License-Identifier: LGPL-2.1-or-later
#include "geometry/line_erosion.hpp"

#include <algorithm>
#include <cmath>

namespace sliceform {
namespace {

// The y at which the line x = c lies nearer than d to the segment a-b: one interval, empty
// (lo >= hi) when the line misses the segment's capsule. The capsule is the union of the
// discs at the ends and the band along the segment; the line crosses each in an interval,
// and their union is one since the capsule is convex.
Interval nearSegment(Vec2 a, Vec2 b, double c, double d) {
  Interval out{HUGE_VAL, -HUGE_VAL};
  const auto add = [&](double lo, double hi) {
    if (hi > lo) out = {std::min(out.lo, lo), std::max(out.hi, hi)};
  };
  for (const Vec2& p : {a, b}) {
    const double dx = c - p.x, r2 = d * d - dx * dx;
    if (r2 <= 0) continue;
    const double h = std::sqrt(r2);
    add(p.y - h, p.y + h);
  }
  const double ex = b.x - a.x, ey = b.y - a.y, len2 = ex * ex + ey * ey, len = std::sqrt(len2);
  if (!(len > 0)) return out;
  // The foot of the perpendicular from (c, y) within the segment:
  // 0 <= (c - a.x) ex + (y - a.y) ey <= len².
  const double u = (c - a.x) * ex;
  double lo = -HUGE_VAL, hi = HUGE_VAL;
  if (ey != 0) {
    const double y0 = a.y - u / ey, y1 = a.y + (len2 - u) / ey;
    lo = std::min(y0, y1), hi = std::max(y0, y1);
  } else if (u < 0 || u > len2) {
    return out;
  }
  // And the distance to the segment's line under d: |ex (y - a.y) - ey (c - a.x)| < d len.
  const double v = ey * (c - a.x);
  if (ex != 0) {
    const double y0 = a.y + (v - d * len) / ex, y1 = a.y + (v + d * len) / ex;
    lo = std::max(lo, std::min(y0, y1)), hi = std::min(hi, std::max(y0, y1));
  } else if (!(std::abs(v) < d * len)) {
    return out;
  }
  add(lo, hi);
  return out;
}

// `in` less the union of `cut` (sorted by lo on return); both sorted lists of intervals.
std::vector<Interval> without(const std::vector<Interval>& in, std::vector<Interval>& cut) {
  std::sort(cut.begin(), cut.end(), [](const Interval& p, const Interval& q) { return p.lo < q.lo; });
  std::vector<Interval> out;
  size_t j = 0;
  for (const Interval& whole : in) {
    double from = whole.lo;
    while (j < cut.size() && cut[j].hi <= from) ++j;
    for (size_t k = j; k < cut.size() && cut[k].lo < whole.hi; ++k) {
      if (cut[k].lo > from) out.push_back({from, cut[k].lo});
      from = std::max(from, cut[k].hi);
    }
    if (whole.hi > from) out.push_back({from, whole.hi});
  }
  return out;
}

}  // namespace

std::vector<std::vector<Interval>> erodedOnVerticalLines(const Region2d& region,
                                                         const std::vector<double>& xs,
                                                         const std::vector<std::vector<Interval>>& full,
                                                         double delta) {
  const SortedLines lines = sortedLines(xs);
  const std::vector<double>& sorted = lines.xs;
  const std::vector<size_t>& order = lines.index;
  // Each edge touches only the lines within delta of its x range.
  std::vector<std::vector<Interval>> near(xs.size());
  for (const Region2d::Loop& loop : region.loops())
    for (size_t i = 0, n = loop.size(); i < n; ++i) {
      const Vec2 a = loop[i], b = loop[(i + 1) % n];
      const double lo = std::min(a.x, b.x) - delta, hi = std::max(a.x, b.x) + delta;
      const auto end = std::lower_bound(sorted.begin(), sorted.end(), hi);
      for (auto it = std::upper_bound(sorted.begin(), sorted.end(), lo); it < end; ++it) {
        const Interval y = nearSegment(a, b, *it, delta);
        if (y.hi > y.lo) near[order[it - sorted.begin()]].push_back(y);
      }
    }
  std::vector<std::vector<Interval>> out(xs.size());
  for (size_t k = 0; k < xs.size(); ++k) out[k] = without(full[k], near[k]);
  return out;
}

}  // namespace sliceform
