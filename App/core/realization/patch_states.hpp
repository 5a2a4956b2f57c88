// SPDX-License-Identifier: LGPL-2.1-or-later
// The slot search's patch states: one patch slotted with one choice of slots, cut on both
// cores and kept for later moves (and, through RealizeMemo, for the split repair's later
// searches). realize.cpp moves slots about; this file says what a patch becomes with them.
#pragma once

#include <memory>
#include <tuple>
#include <utility>
#include <vector>

#include "realization/interlock.hpp"
#include "realization/realize.hpp"
#include "realization/slots.hpp"
#include "support/bounded_cache.hpp"

namespace sliceform {

// Patch states kept for later steps, per generation of a cache (two are kept).
constexpr size_t kPatchStateCacheBytes = size_t{48} << 20;

// One patch slotted with one choice of slots: what the search needs to know of it.
struct PatchState {
  std::vector<SlotCut> cuts;
  // As SlotCutter::tryCut leaves it: paperOf() gives what the files get.
  Region2d slotted;
  int pieces = 1;
  bool trimmed = false;  // slivers cut away
  // The paper as the files get it (PatchStates::paperOf), made when first asked: a split
  // repair's searches end on states they share but a few (occ/Top.brep: 24 searches).
  mutable std::shared_ptr<const Region2d> united;
  HoleLoops holes;
  // Per hinge of the patch (in PatchStates' hinge order): the lengths of the hinge segment
  // the slotted patch still covers, for the search's meets(); read off once here, not at
  // every move.
  std::vector<std::vector<double>> onHinge;
  size_t bytes = 0;  // about what it holds, for the caches
};

// A patch state by all it depends on: family, cylinder, position, and its hinges as
// planSlots sees them (line, segment, root, slot).
using MemoKey = std::tuple<int, int, double, std::vector<std::tuple<double, double, double, double, int>>>;

class RealizeMemo {
 public:
  CutterCache cutters;
  // Bounded as the search's own cache, and aged at the same steps: the repairs' 24 searches
  // put every state they cut here (occ/Top.brep: 384 MB at the peak, 165 MB before).
  BoundedCache<MemoKey, PatchState> states{kPatchStateCacheBytes};
  // The neck tests of states never cut (PatchStates::prepareBounds), likewise: a repair's
  // search asks again for those of every patch it did not move (occ/Top.brep's file axes:
  // 24 searches, all with the same 11 patches in pieces).
  BoundedCache<MemoKey, SlotCutter::Opened> opened{kPatchStateCacheBytes};
};

// A move of the search: hinges given new slot pairs.
using SlotMove = std::vector<std::pair<int, SlotPair>>;  // (hinge, new combination)

class PatchStates {
 public:
  // What patch p's state depends on: the slot p gets at each of its hinges.
  using Key = std::pair<int, std::vector<Slot>>;

  // `hingesOf`: per patch, its hinges in order; `first`: the slots the search starts from,
  // which place each patch's hinge lines. Each patch's cutter and lines are made here, on
  // both cores.
  PatchStates(const RealizationInput& in, const SlotParams& params, RealizeMemo* memo,
              const std::vector<std::vector<int>>& hingesOf, const std::vector<SlotPair>& first);

  Key key(int p, const std::vector<SlotPair>& slots) const;

  // Patch p's paper as the files get it, for its state `st`: the state's own, united (once;
  // kept in `st`, so no two threads may ask for one state at once).
  const Region2d& paperOf(int p, const PatchState& st) const;

  // Patch patches[i] with slots[i] (or slots[0] for all when `same`), on both cores, through
  // the memo when there is one.
  std::vector<std::shared_ptr<const PatchState>> evaluate(const std::vector<int>& patches,
                                                          const std::vector<std::vector<SlotPair>>& slots,
                                                          bool same);
  // Every state the moves (each from `slots`) need that is not cached yet, cut on both
  // cores. Which states are cut does not depend on timing, and each is a pure function, so
  // the search stays deterministic.
  void prepare(const std::vector<SlotMove>& moves, const std::vector<SlotPair>& slots);
  // What the search's bound needs of the states of the patches in `own` the moves make:
  // their pieces from the cutter's neck test alone where no state is cached or in the memo
  // (most moves of a split patch leave it split, and then the slotted shape itself is never
  // wanted).
  void prepareBounds(const std::vector<SlotMove>& moves, const std::vector<int>& own,
                     const std::vector<SlotPair>& slots);
  // At least how many pieces the state of `key` has (after prepare or prepareBounds): exact
  // from a cached state, else from the neck test. cut() may trim slivers off and count fewer
  // than that test: where it found slivers, nothing beyond one piece is sure.
  int piecesAtLeast(const Key& key);
  // The state of patch p for `slots`, cut now when no move asked for it yet.
  std::shared_ptr<const PatchState> of(int p, const std::vector<SlotPair>& slots);
  // A new step of the search: what was not asked for lately may go.
  void age();

 private:
  std::shared_ptr<const PatchState> evaluatePatch(int p, const std::vector<SlotPair>& slots,
                                                  const SlotCutter::Opened* opened) const;
  MemoKey memoKey(int p, const std::vector<SlotPair>& slots) const;
  template <class Have>
  void needed(const std::vector<SlotMove>& moves, const std::vector<SlotPair>& from,
              const std::vector<int>& only, Have&& have, std::vector<Key>& keys,
              std::vector<std::vector<SlotPair>>& slotsOf) const;

  const RealizationInput& in_;
  SlotParams params_;
  RealizeMemo* memo_;
  const std::vector<std::vector<int>>& hingesOf_;
  std::vector<std::unique_ptr<VerticalLines>> lines_;       // per patch: its shape on its hinge lines
  std::vector<std::shared_ptr<const SlotCutter>> cutters_;  // per patch
  // The states moves asked for. Kept across steps: a violation no move improved is tried
  // again whenever its neighbourhood changed, and asks for the same states but the few a
  // move since changed (occ/Top.brep: three split patches, 870 states a try, tried again
  // after every accepted move; the search ran out of its 60 s with 38 patches in pieces).
  BoundedCache<Key, PatchState> cache_{kPatchStateCacheBytes};
  // The neck tests prepareBounds made, by the same keys and aged with them: piecesAtLeast
  // reads them, and evaluatePatch finishes a state from one instead of testing again.
  BoundedCache<Key, SlotCutter::Opened> opened_{kPatchStateCacheBytes};
};

}  // namespace sliceform
