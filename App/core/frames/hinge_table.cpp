// SPDX-License-Identifier: LGPL-2.1-or-later
#include "frames/hinge_table.hpp"

#include <algorithm>

#include "geometry/line_erosion.hpp"
#include "support/parallel.hpp"

namespace sliceform {
namespace {

// Where the lines of every slice of `other` lie in `frame`: x = c.
std::vector<double> linesOf(const SliceFrame& frame, const SliceSet& other) {
  std::vector<double> xs;
  for (const Slice& s : other.slices) xs.push_back(lineX(frame, other.frame, s.position));
  return xs;
}

}  // namespace

std::vector<Interval> intersectIntervals(const std::vector<Interval>& a, const std::vector<Interval>& b) {
  std::vector<Interval> out;
  size_t i = 0, j = 0;
  while (i < a.size() && j < b.size()) {
    const double lo = std::max(a[i].lo, b[j].lo), hi = std::min(a[i].hi, b[j].hi);
    if (hi > lo) out.push_back({lo, hi});
    (a[i].hi < b[j].hi) ? ++i : ++j;
  }
  return out;
}

HingeTable::HingeTable(const SliceSet& u, const SliceSet& v, const std::vector<Cylinder>& uCylinders,
                       const std::vector<Cylinder>& vCylinders, const HingeRules& rules)
    : rules_(rules) {
  const double erosion = rules.minSlotEdgeDistance + rules.slotWidth / 2;
  // Each cylinder on its own, on every core. The eroded sections are met on the lines
  // alone (erodedOnVerticalLines): eroding a whole section with Clipper's offset was 12 % of
  // occ/Motor-c.brep's CPU, most of it in the direction search's estimates.
  const auto fill = [&](const std::vector<Cylinder>& cylinders, const SliceFrame& frame,
                        const SliceSet& other, std::vector<std::vector<std::vector<Interval>>>& full,
                        std::vector<std::vector<std::vector<Interval>>>& eroded) {
    const std::vector<double> xs = linesOf(frame, other);
    full.resize(cylinders.size());
    eroded.resize(cylinders.size());
    parallelFor(cylinders.size(), [&](size_t k) {
      full[k] = cylinders[k].section.intervalsOnVerticalLines(xs);
      eroded[k] = erodedOnVerticalLines(cylinders[k].section, xs, full[k], erosion);
    });
  };
  fill(uCylinders, u.frame, v, uFull_, uEroded_);
  fill(vCylinders, v.frame, u, vFull_, vEroded_);
}

std::vector<Interval> HingeTable::segments(int a, int i, int b, int j) const {
  return intersectIntervals(uFull_[a][j], vFull_[b][i]);
}

bool HingeTable::holds(int a, int i, int b, int j) const {
  for (const Interval& s : intersectIntervals(uEroded_[a][j], vEroded_[b][i]))
    if (s.hi - s.lo >= rules_.minHingeLength) return true;
  return false;
}

Interval HingeTable::grip(int a, int i, int b, int j, const Interval& segment) const {
  Interval best{0, 0};
  for (const Interval& s : intersectIntervals(uEroded_[a][j], vEroded_[b][i]))
    if (s.hi - s.lo >= rules_.minHingeLength && s.lo >= segment.lo && s.hi <= segment.hi &&
        s.hi - s.lo > best.hi - best.lo)
      best = s;
  return best;
}

}  // namespace sliceform
