// SPDX-License-Identifier: LGPL-2.1-or-later
// Paper realization (§5, Alg. 3): a slot combination for every hinge such that no two
// patches interlock and no patch falls apart, then the slotted patch shapes and an order to
// put them together in.
//
// Decision (deviation from Alg. 3, in docs/decisions.md): Alg. 3 treats one pair of patches
// at a time, but a slot chosen for one pair changes the loops another pair sees. We search
// globally instead. Start with every U-patch slotted up (V down), then while a pair
// interlocks or a patch is split, try in this order and keep the first tier that lowers
// (split patches, interlocks, cut-throughs):
//   1. every up/down combination of the pair's common hinges (the paper's table T),
//   2. flipping any one other hinge of either patch,
//   3. a cut-through at one hinge of either patch, never at the last holding hinge between
//      two patches, so every pin of the certificate keeps an up/down slot.
// A violation that no move improves is left and counted as remaining. Besides interlocks
// and split patches, a violation is a pair of patches whose holding hinges all stop
// meeting once slotted (two slots the same way on one line clear a whole hinge), which
// would take a pin from the certificate.
#pragma once

#include <map>
#include <memory>
#include <utility>
#include <vector>

#include "frames/scaffold.hpp"
#include "realization/slots.hpp"
#include "slicing/slice_set.hpp"
#include "support/deadline.hpp"
#include "support/per_family.hpp"

namespace sliceform {

struct Arrangement;

struct PatchShape {
  Family family = Family::U;
  double position = 0;  // along the family's normal, mm
  Region2d shape;       // in the family's frame, before slots
  int cylinder = -1;    // whose section `shape` is, for RealizeMemo (-1: not known)
};

struct RealizationInput {
  PerFamily<SliceFrame> frames;
  std::vector<PatchShape> patches;
  std::vector<ScaffoldHinge> hinges;
  double tolerance = 0;  // mm the polygon shapes may stray from the true ones
};
// `tolerance`: the model's mesh deflection (the polygons come from its triangulation).
RealizationInput realizationInput(const Arrangement& arrangement, double tolerance);
// The same for another scaffold of the arrangement's cylinders (a patch moved on trial).
RealizationInput realizationInput(const Arrangement& arrangement, const Scaffold& scaffold, double tolerance);

struct InterlockStats {
  int found = 0;     // interlocked hole pairs with the default slots
  int repaired = 0;  // found - remaining
  int remaining = 0;
  int cutThroughs = 0;  // hinges cut through to break a loop
};

struct Realization {
  SlotParams params;
  std::vector<SlotPair> slots;             // per hinge
  std::vector<std::vector<SlotCut>> cuts;  // per patch, in its frame
  std::vector<Region2d> slotted;           // per patch: shape minus slots, crumbs dropped
  InterlockStats interlocks;
  int splitPatches = 0;            // patches in more than one piece (must be 0)
  std::vector<int> split;          // which they are
  std::vector<bool> meets;         // per hinge: the slotted patches still meet along it
  int lostPins = 0;                // pairs whose every holding hinge stopped meeting
  double minSlotEdgeDistance = 0;  // mm of paper left around slot roots of holding hinges
  double shortestHinge = 0;        // mm, over holding hinges
  std::vector<int> assemblyOrder;  // patch indices
  bool assemblyChecked = false;    // each patch added is free of the ones placed
  bool timedOut = false;           // the deadline passed before the search ended
};

// Slot cutters by (family, cylinder): a cutter depends on the patch's shape alone, and the
// graze tests and repeated searches of one design ask for the same ones again and again.
using CutterCache = std::map<std::pair<int, int>, std::shared_ptr<const SlotCutter>>;
// The cutter of each patch `needed` says (every patch when it is empty; null for the
// others), from `cache` when it has it, else made (both cores at once) and kept there.
std::vector<std::shared_ptr<const SlotCutter>> patchCutters(const RealizationInput& input,
                                                            const SlotParams& params, CutterCache* cache,
                                                            const std::vector<char>& needed = {});

// What searches of one design share when it is searched again after a patch moved: each
// cylinder's slot cutter, and each patch state by everything it depends on (cylinder,
// position, and its hinges with their slots), so only the moved patch and its partners are
// slotted anew. Only for the same slot parameters and tolerance.
class RealizeMemo;
std::shared_ptr<RealizeMemo> makeRealizeMemo();

// `start`: a slot pair per hinge to begin from (a warm start after a patch moved), or empty
// for every U-patch slotted as params.uUp says. The search stops when `deadline` passes,
// with the best slots it has (Realization::timedOut).
Realization realize(const RealizationInput& input, const SlotParams& params, const Deadline& deadline = {},
                    const std::vector<SlotPair>& start = {}, RealizeMemo* memo = nullptr);

// The hinges of one patch as planSlots sees them, with the given slot choices.
std::vector<PatchHinge> patchHinges(const RealizationInput& input, const std::vector<SlotPair>& slots,
                                    int patch);

}  // namespace sliceform
