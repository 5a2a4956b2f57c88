// SPDX-License-Identifier: LGPL-2.1-or-later
#include "realization/patch_states.hpp"

#include <algorithm>
#include <set>

#include "frames/hinge_table.hpp"
#include "support/parallel.hpp"
#include "support/per_family.hpp"

namespace sliceform {

PatchStates::PatchStates(const RealizationInput& in, const SlotParams& params, RealizeMemo* memo,
                         const std::vector<std::vector<int>>& hingesOf, const std::vector<SlotPair>& first)
    : in_(in), params_(params), memo_(memo), hingesOf_(hingesOf) {
  // Each patch's own tools depend on nothing else: both cores at once.
  const size_t n = in.patches.size();
  lines_.resize(n);
  cutters_ = patchCutters(in, params, memo_ ? &memo_->cutters : nullptr);
  parallelFor(n, [&](size_t p) {
    lines_[p] = std::make_unique<VerticalLines>(
        in.patches[p].shape, VerticalLines::slotLines(patchHinges(in_, first, static_cast<int>(p)), params));
  });
}

PatchStates::Key PatchStates::key(int p, const std::vector<SlotPair>& slots) const {
  Key key{p, {}};
  for (const int h : hingesOf_[p]) key.second.push_back(familySlot(in_.patches[p].family, slots[h]));
  return key;
}

// Patch p slotted as `slots` says. A pure function of p and p's own slots (key()), so it may
// run on any thread and its result may be reused. `opened`: the cutter's neck test of these
// slots, when prepareBounds made it already.
std::shared_ptr<const PatchState> PatchStates::evaluatePatch(int p, const std::vector<SlotPair>& slots,
                                                             const SlotCutter::Opened* opened) const {
  const PatchShape& ps = in_.patches[p];
  auto st = std::make_shared<PatchState>();
  st->cuts = planSlots(*lines_[p], patchHinges(in_, slots, p), params_);
  SlotCutter::Trial trial = cutters_[p]->tryCut(slotStrips(st->cuts, params_), opened);
  st->slotted = std::move(trial.paper);
  st->pieces = trial.pieces;
  st->trimmed = trial.trimmed;
  st->holes = holeLoops(st->slotted, ps.position);
  std::vector<double> xs;
  for (const int h : hingesOf_[p])
    xs.push_back(lineX(in_.frames[ps.family], in_.frames[other(ps.family)],
                       in_.patches[in_.hinges[h].patch(other(ps.family))].position));
  const std::vector<std::vector<Interval>> onLines = st->slotted.intervalsOnVerticalLines(xs);
  for (size_t k = 0; k < xs.size(); ++k) {
    std::vector<double> lengths;
    for (const Interval& i : intersectIntervals(onLines[k], {in_.hinges[hingesOf_[p][k]].w}))
      lengths.push_back(i.hi - i.lo);
    st->onHinge.push_back(std::move(lengths));
  }
  st->bytes = sizeof(PatchState) + st->cuts.size() * sizeof(SlotCut) + st->onHinge.size() * 32;
  st->bytes += st->slotted.bytes();
  for (const Region2d::Loop& loop : st->holes.holes) st->bytes += loop.size() * sizeof(Vec2) + 32;
  st->bytes += st->holes.boxes.size() * sizeof(Box2);
  return st;
}

const Region2d& PatchStates::paperOf(int p, const PatchState& st) const {
  if (!st.united)
    st.united =
        std::make_shared<const Region2d>(cutters_[p]->paperOf(slotRegion(st.cuts, params_), st.trimmed));
  return *st.united;
}

MemoKey PatchStates::memoKey(int p, const std::vector<SlotPair>& slots) const {
  const PatchShape& ps = in_.patches[p];
  MemoKey key{familyIndex(ps.family), ps.cylinder, ps.position, {}};
  for (const PatchHinge& h : patchHinges(in_, slots, p))
    std::get<3>(key).emplace_back(h.x, h.w.lo, h.w.hi, h.root, static_cast<int>(h.slot));
  return key;
}

std::vector<std::shared_ptr<const PatchState>> PatchStates::evaluate(
    const std::vector<int>& patches, const std::vector<std::vector<SlotPair>>& slots, bool same) {
  const auto slotsFor = [&](size_t i) -> const std::vector<SlotPair>& { return same ? slots[0] : slots[i]; };
  std::vector<std::shared_ptr<const PatchState>> out(patches.size());
  std::vector<MemoKey> keys(patches.size());
  std::vector<size_t> missing;
  std::vector<std::shared_ptr<const SlotCutter::Opened>> opened(patches.size());
  for (size_t i = 0; i < patches.size(); ++i) {
    if (memo_ && in_.patches[patches[i]].cylinder >= 0) {
      keys[i] = memoKey(patches[i], slotsFor(i));
      if ((out[i] = memo_->states.find(keys[i]))) continue;
    }
    missing.push_back(i);
    opened[i] = opened_.find(key(patches[i], slotsFor(i)));
  }
  parallelFor(missing.size(), [&](size_t m) {
    const size_t i = missing[m];
    out[i] = evaluatePatch(patches[i], slotsFor(i), opened[i].get());
  });
  if (memo_)
    for (const size_t i : missing)
      if (in_.patches[patches[i]].cylinder >= 0) memo_->states.put(std::move(keys[i]), out[i], out[i]->bytes);
  return out;
}

// The keys and slots of the states the moves (each from `from`) need that `have` has not
// (of the patches in `only`, when given), each once, in the moves' order.
template <class Have>
void PatchStates::needed(const std::vector<SlotMove>& moves, const std::vector<SlotPair>& from,
                         const std::vector<int>& only, Have&& have, std::vector<Key>& keys,
                         std::vector<std::vector<SlotPair>>& slotsOf) const {
  std::set<Key> queued;
  std::vector<SlotPair> slots = from;
  for (const SlotMove& m : moves) {
    for (const auto& [h, pair] : m) slots[h] = pair;
    for (const auto& [h, pair] : m)
      for (const int p : {in_.hinges[h].u, in_.hinges[h].v}) {
        if (!only.empty() && std::find(only.begin(), only.end(), p) == only.end()) continue;
        Key k = key(p, slots);
        if (have(k) || !queued.insert(k).second) continue;
        keys.push_back(std::move(k));
        slotsOf.push_back(slots);
      }
    for (const auto& [h, pair] : m) slots[h] = from[h];
  }
}

void PatchStates::prepare(const std::vector<SlotMove>& moves, const std::vector<SlotPair>& slots) {
  std::vector<Key> keys;
  std::vector<std::vector<SlotPair>> slotsOf;
  needed(
      moves, slots, {}, [&](const Key& k) { return cache_.contains(k); }, keys, slotsOf);
  std::vector<int> patches;
  for (const Key& k : keys) patches.push_back(k.first);
  std::vector<std::shared_ptr<const PatchState>> states = evaluate(patches, slotsOf, false);
  for (size_t i = 0; i < keys.size(); ++i) cache_.put(std::move(keys[i]), states[i], states[i]->bytes);
}

void PatchStates::prepareBounds(const std::vector<SlotMove>& moves, const std::vector<int>& own,
                                const std::vector<SlotPair>& slots) {
  std::vector<Key> keys;
  std::vector<std::vector<SlotPair>> slotsOf;
  needed(
      moves, slots, own, [&](const Key& k) { return cache_.contains(k) || opened_.contains(k); }, keys,
      slotsOf);
  std::vector<size_t> missing;
  std::vector<MemoKey> memoKeys(keys.size());
  std::vector<std::shared_ptr<const SlotCutter::Opened>> opened(keys.size());
  for (size_t i = 0; i < keys.size(); ++i) {
    const int p = keys[i].first;
    if (memo_ && in_.patches[p].cylinder >= 0) {
      memoKeys[i] = memoKey(p, slotsOf[i]);
      if (std::shared_ptr<const PatchState> st = memo_->states.find(memoKeys[i])) {
        cache_.put(std::move(keys[i]), st, st->bytes);
        continue;
      }
      opened[i] = memo_->opened.find(memoKeys[i]);
    }
    missing.push_back(i);
  }
  parallelFor(missing.size(), [&](size_t m) {
    const size_t i = missing[m];
    if (opened[i]) return;
    const int p = keys[i].first;
    const std::vector<SlotCut> cuts = planSlots(*lines_[p], patchHinges(in_, slotsOf[i], p), params_);
    opened[i] = std::make_shared<SlotCutter::Opened>(cutters_[p]->opened(slotStrips(cuts, params_)));
  });
  for (const size_t i : missing) {
    // The key too: an entry is small, and the cache holds many (Top: 25,565 tests).
    size_t bytes = sizeof(SlotCutter::Opened) + sizeof(Key) + keys[i].second.size() * sizeof(Slot) + 64;
    for (const Region2d& sliver : opened[i]->slivers) bytes += sliver.bytes();
    if (memo_ && in_.patches[keys[i].first].cylinder >= 0) {
      // Its key's hinges too, counted before the key is moved into the memo.
      const size_t keyBytes =
          std::get<3>(memoKeys[i]).size() * sizeof(std::tuple_element_t<3, MemoKey>::value_type);
      memo_->opened.put(std::move(memoKeys[i]), opened[i], bytes + keyBytes);
    }
    opened_.put(std::move(keys[i]), opened[i], bytes);
  }
}

int PatchStates::piecesAtLeast(const Key& k) {
  if (std::shared_ptr<const PatchState> st = cache_.find(k)) return st->pieces;
  const std::shared_ptr<const SlotCutter::Opened> o = opened_.find(k);
  return o->slivers.empty() ? o->pieces : std::min(1, o->pieces);
}

std::shared_ptr<const PatchState> PatchStates::of(int p, const std::vector<SlotPair>& slots) {
  Key k = key(p, slots);
  if (auto st = cache_.find(k)) return st;
  auto st = evaluate({p}, {slots}, true).front();
  cache_.put(std::move(k), st, st->bytes);
  return st;
}

void PatchStates::age() {
  cache_.age();
  opened_.age();
  if (memo_) {
    memo_->states.age();
    memo_->opened.age();
  }
}

}  // namespace sliceform
