// SPDX-License-Identifier: LGPL-2.1-or-later
// Stability certificate: proves that a scaffold is stable and folds flat (Prop. 1) from
// its patches and hinges alone, independently of how the frames were chosen.
//
// Seen along W, every patch is a rigid bar in the cross-section plane and every hinge a
// pin joining two bars. Each bar has three velocity unknowns (vx, vy, omega); each pin
// asks the two bars to move alike at the pin (two rows). With one bar held, a stable
// sliceform keeps exactly one motion: the fold. So the null space must be one-dimensional.
#pragma once

#include <string>
#include <vector>

#include "slicing/slice_set.hpp"

namespace sliceform {

// What the certificate needs of a patch: its family and its position along the family's
// normal (mm). A U-patch is the line u = position in the (u, v) cross-section plane, a
// V-patch the line v = position.
struct BarPatch {
  Family family = Family::U;
  double position = 0;
};

struct PinHinge {
  int a = 0, b = 0;  // indices of a U-patch and a V-patch
};

struct Certificate {
  bool stable = false;
  int nullity = 0;  // dimension of the motions left with one patch held; 1 = the fold
  int patches = 0;
  int pins = 0;        // distinct (U, V) pairs joined by at least one hinge
  std::string reason;  // why it is not stable, for the report
};

// Fails (stable = false) on fewer than two patches, a hinge between patches of the same
// family, or an index out of range, with the reason said.
Certificate certify(const std::vector<BarPatch>& patches, const std::vector<PinHinge>& hinges);

}  // namespace sliceform
