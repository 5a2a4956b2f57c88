// SPDX-License-Identifier: LGPL-2.1-or-later
// Grazes: hinges no slot can be cut at without cutting one of the two patches in pieces.
// Where the line of one family runs almost tangent to the surface, both sections are thin
// at the same height inside the hinge; the two slots together clear the whole hinge, so
// one of them crosses the thin spot and cuts a lobe off, whichever way they point (measured
// on man, bones and the dragon: ../shared/notes/split-patches.md). No slot search can
// repair that; moving one of the two patches by a slice or two does.
//
// Each hinge is tested alone: every slot pair it may take (up/down, down/up, and for a
// hinge that does not hold also through/none), each patch cut with that one slot and
// nothing else, by the search's own piece count (SlotCutter). A hinge is grazing when
// every pair splits a patch. Then a patch of the hinge is moved within its cylinder by
// one or two slices (kMoves), where the spacing rule allows it and the scaffold stays
// certified, to the first slice where none of its hinges graze. Where none does, the
// smaller patch of the two is taken out if the scaffold stays certified without it.
#pragma once

#include <vector>

#include "arrangement/arrange.hpp"
#include "realization/realize.hpp"

namespace sliceform {

// Indices of the grazing hinges among `hinges` (all of input's when empty).
std::vector<int> grazingHinges(const RealizationInput& input, const SlotParams& params,
                               const std::vector<int>& hinges = {}, CutterCache* cutters = nullptr);

struct GrazeRepair {
  int found = 0;               // grazing hinges before
  int moved = 0;               // patches moved
  int dropped = 0;             // patches taken out where no move helped
  int remaining = 0;           // grazing hinges after
  int splitMoved = 0;          // patches the slot search left split, moved and searched again
  int splitDropped = 0;        // split patches taken out, the scaffold still certified
  bool timedOut = false;       // the deadline passed while moving patches off grazes
  bool splitTimedOut = false;  // the deadline passed while repairing patches left in pieces
  bool splitLeft = false;      // too many in pieces to repair: left to other frames (designPatches)
};

// Moves patches off grazes (see above); the arrangement's scaffold, hinges, certificate
// and quality are brought up to date. `tolerance` as for realizationInput.
GrazeRepair avoidGrazes(Arrangement& arrangement, const SlotParams& params, double tolerance,
                        const Deadline& deadline = {});

// The last resort for patches the slot search leaves split (or pairs that lost every
// holding hinge): move a split patch by a slice or two, or failing that take it out where
// the scaffold stays certified without it, and search again; a change is kept when fewer
// patches are broken. `realization` is replaced by the search on the changed scaffold.
// Each attempt starts the search from the slots it had (a warm start).
void repairSplits(Arrangement& arrangement, Realization& realization, GrazeRepair& repair,
                  const SlotParams& params, double tolerance, const Deadline& deadline = {});

}  // namespace sliceform
