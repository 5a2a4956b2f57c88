// SPDX-License-Identifier: LGPL-2.1-or-later
// Scaffold (§4.2.5): the chosen patches and every hinge between them. A patch is a
// cross-section of a cylinder at one slice position; its shape is the cylinder's section.
#pragma once

#include <string>
#include <vector>

#include "geometry/vec.hpp"
#include "slicing/slice_set.hpp"

namespace sliceform {

struct ScaffoldPatch {
  Family family = Family::U;
  int cylinder = 0;     // index into its family's cylinders
  int slice = 0;        // index into its family's slice set
  double position = 0;  // along the family's normal, mm
};

struct ScaffoldHinge {
  int u = 0, v = 0;    // patch indices of the U-patch and the V-patch
  Interval w;          // the segment along W, mm
  bool holds = false;  // long enough, with enough paper beside its slot, to carry load
  Interval grip;       // where it holds (inside both eroded sections); slots start at its middle

  int patch(Family f) const { return f == Family::U ? u : v; }  // its patch of family f
};

enum class Scheme { DominantU, DominantV, Both };

struct Scaffold {
  std::vector<ScaffoldPatch> patches;
  std::vector<ScaffoldHinge> hinges;
  std::vector<int> uncoveredU, uncoveredV;  // cylinders that must have a patch but could not

  std::vector<int>& uncovered(Family f) { return f == Family::U ? uncoveredU : uncoveredV; }
};

std::string patchId(const Scaffold& scaffold, int patch);  // "U3", "V7": family and number

}  // namespace sliceform
