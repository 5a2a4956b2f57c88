// SPDX-License-Identifier: LGPL-2.1-or-later
// Interlocking loops (§5, Prop. 3). Let A be a U-patch and B a V-patch, slotted, and H the
// line where their planes meet. A hole loop a of A and a hole loop b of B interlock when an
// odd number of the points where a crosses H lie inside b: then a ring of paper passes
// through a hole of the other patch and the two cannot be put together. Every U/V pair is
// checked, also pairs that do not touch.
//
// Where a crosses H exactly on b's boundary (at a slot root, where both patches' slots end
// on the same point), the point is moved a hair (1 µm) into a's hole along H: with paper of
// no thickness a slot is an opening, and that is where the opening lies.
#pragma once

#include <vector>

#include "geometry/region2d.hpp"
#include "slicing/slice_set.hpp"

namespace sliceform {

// The hole loops of one slotted patch, ready for the test.
struct HoleLoops {
  double position = 0;  // of the patch plane along its family's normal
  std::vector<Region2d::Loop> holes;
  std::vector<Box2> boxes;
};
HoleLoops holeLoops(const Region2d& slotted, double position);

// Interlocked (a, b) hole pairs of U-patch a and V-patch b; uFrame and vFrame are the
// families' slice frames (they share the y axis W).
int interlockCount(const HoleLoops& a, const SliceFrame& uFrame, const HoleLoops& b,
                   const SliceFrame& vFrame);

}  // namespace sliceform
