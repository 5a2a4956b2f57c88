// SPDX-License-Identifier: LGPL-2.1-or-later
// The fabrication contract, checked on exactly the outlines that are emitted (report.json,
// the sheets, the 3D assembly), with the tests `../shared/tools/check_report.py` makes from
// the report alone:
//   - which hinges are real: both slotted patches cover 90 % of the segment between them
//     (the others are not listed as hinges, and are no pins of the certificate);
//   - no U/V pair overlaps along the line where their planes meet (a slot must part them);
//   - no interlocked hole loops (Prop. 3);
//   - every patch one piece, by the neck test the slot search uses (SlotCutter);
//   - paper between neighbouring slots: the closest two patches of one family whose
//     outlines overlap seen along their normal, against the spacing rule.
// Rigidity is the certificate's, on the holding hinges this check finds real.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "realization/realize.hpp"

namespace sliceform {

struct Emitted {
  int interlocks = 0;
  int splitPatches = 0;
  std::vector<int> split;                        // which patches those are
  std::vector<std::pair<int, int>> interlocked;  // (U-patch, V-patch) pairs whose loops link
  std::vector<char> meets;                       // per hinge of the scaffold
  std::vector<std::pair<int, int>> collisions;   // (U-patch, V-patch) overlapping on their line
  double worstOverlap = 0;                       // mm, the longest such overlap
  // The closest stacked pair of one family (-1, -1 when no two patches are stacked) and
  // how far apart they are, mm.
  std::pair<int, int> closest{-1, -1};
  double minPatchSpacing = 0;
  std::vector<int> failing;  // patches in a split, a collision or an interlock, sorted
  std::vector<int> pieces;   // per patch: its pieces by the neck test or its outer loops, the more
};

// `outlines`: per patch, in its family frame's 2D coordinates. `spacing` is the spacing
// rule in force (Arrangement::minSpacing). `knownPieces`, when given: Emitted::pieces of an
// earlier check of the same patches, -1 where the outline has changed since; the others
// are not counted again (a patch's pieces depend on its outline alone).
Emitted checkEmitted(const RealizationInput& input, const std::vector<Region2d>& outlines,
                     const SlotParams& params, const std::vector<int>* knownPieces = nullptr);

// Whether an emitted pair of stacked patches breaks the spacing rule.
bool tooClose(const Emitted& e, double spacing);

// Which patches to emit as the search's own polygons next, after `e` checked the outlines:
// those breaking a rule (e.failing), and both ends of a hinge the search made
// (`searchMeets`) that the outlines lost, unless an end breaks a rule itself: that end goes
// first, and the hinge is looked at again once it is replaced, so its partner keeps an
// exact face that did nothing wrong. Patches in `replaced` are never chosen again; empty
// when nothing is left to replace.
std::vector<int> patchesToReplace(const Emitted& e, const std::vector<ScaffoldHinge>& hinges,
                                  const std::vector<bool>& searchMeets, const std::vector<char>& replaced);

}  // namespace sliceform
