// SPDX-License-Identifier: LGPL-2.1-or-later
// Where patches of two cylinders of different families can hinge (§4.2, precomputed per
// cylinder pair). A U-patch of cylinder a at U-slice i and a V-patch of cylinder b at
// V-slice j meet on the line parallel to W through both planes. Every stretch of that line
// inside both sections is a hinge segment (a slot must be cut there, or they collide); it
// holds the scaffold together only if, on both sections eroded by min_slot_edge_distance,
// it is still at least min_hinge_length long. That is the fix for weak slots (Fig. 16a).
// The erosion is min_slot_edge_distance plus half the slot width, so the paper left beside
// a slot's walls, not only beside the hinge line, is at least min_slot_edge_distance.
#pragma once

#include <vector>

#include "cylinders/gca.hpp"
#include "geometry/vec.hpp"
#include "slicing/slice_set.hpp"

namespace sliceform {

struct HingeRules {
  double minHingeLength = 4;       // mm
  double minSlotEdgeDistance = 2;  // mm of material on each side of a slot
  double slotWidth = 0;            // mm, material thickness + clearance
};
inline bool operator==(const HingeRules& a, const HingeRules& b) {
  return a.minHingeLength == b.minHingeLength && a.minSlotEdgeDistance == b.minSlotEdgeDistance &&
         a.slotWidth == b.slotWidth;
}

class HingeTable {
 public:
  HingeTable(const SliceSet& u, const SliceSet& v, const std::vector<Cylinder>& uCylinders,
             const std::vector<Cylinder>& vCylinders, const HingeRules& rules);

  // Hinge segments as W-intervals (mm), empty if the patches do not meet.
  std::vector<Interval> segments(int a, int i, int b, int j) const;
  // Whether the two patches hold each other: some eroded overlap is long enough.
  bool holds(int a, int i, int b, int j) const;
  // The grip of a segment (from segments()): its longest stretch inside both eroded
  // sections, if that is long enough to hold; empty (lo >= hi) when the segment does not
  // hold. Slots start from the middle of the grip, so the promised paper is there.
  Interval grip(int a, int i, int b, int j, const Interval& segment) const;
  const HingeRules& rules() const { return rules_; }

 private:
  // Sections of U-cylinder a on the line of V-slice j: full[a][j], eroded; and mirrored.
  std::vector<std::vector<std::vector<Interval>>> uFull_, uEroded_, vFull_, vEroded_;
  HingeRules rules_;
};

// Pieces of two sorted interval lists that lie in both.
std::vector<Interval> intersectIntervals(const std::vector<Interval>& a, const std::vector<Interval>& b);

}  // namespace sliceform
