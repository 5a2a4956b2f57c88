// SPDX-License-Identifier: LGPL-2.1-or-later
#include "frames/hinge_table.hpp"

#include <algorithm>

namespace sliceform {
namespace {

// Intervals of `section` along the vertical lines of every slice of `other`.
std::vector<std::vector<Interval>> onLines(const Region2d& section, const SliceFrame& frame,
                                           const SliceSet& other) {
  std::vector<double> xs;
  for (const Slice& s : other.slices) xs.push_back(lineX(frame, other.frame, s.position));
  return section.intervalsOnVerticalLines(xs);
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
  for (const Cylinder& c : uCylinders) {
    uFull_.push_back(onLines(c.section, u.frame, v));
    uEroded_.push_back(onLines(c.section.offset(-erosion), u.frame, v));
  }
  for (const Cylinder& c : vCylinders) {
    vFull_.push_back(onLines(c.section, v.frame, u));
    vEroded_.push_back(onLines(c.section.offset(-erosion), v.frame, u));
  }
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
