// SPDX-License-Identifier: LGPL-2.1-or-later
#include "realization/grazes.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <set>
#include <tuple>

#include "frames/stabilize.hpp"
#include "support/parallel.hpp"

namespace sliceform {
namespace {

// Where a patch may move off a graze or a split, in slices, nearest first. One or two
// slices removed every graze measured on man, bones and the dragon; further moves change
// the design more than they help.
constexpr int kMoves[] = {1, -1, 2, -2};
// Searches of the whole design repairSplits may run.
constexpr int kMaxAttempts = 24;

// A hinge by what it joins, to follow it when the scaffold's hinge list is rebuilt.
using HingeKey = std::tuple<int, int, long long>;
HingeKey keyOf(const ScaffoldHinge& h) {
  return {h.u, h.v, std::llround(h.w.lo * 1e4)};
}

}  // namespace

std::vector<int> grazingHinges(const RealizationInput& in, const SlotParams& params,
                               const std::vector<int>& which, CutterCache* cache) {
  std::vector<int> hinges = which;
  if (hinges.empty())
    for (int h = 0; h < static_cast<int>(in.hinges.size()); ++h) hinges.push_back(h);
  // Each patch's hinges as planSlots sees them, all without a slot, and its cutter.
  const int n = static_cast<int>(in.patches.size());
  std::vector<char> needed(n, 0);
  for (const int h : hinges) needed[in.hinges[h].u] = needed[in.hinges[h].v] = 1;
  // A patch whole with every slot the search starts from is whole with any one of them
  // (one slot cuts less, and bounds its end where all do): where both patches of a hinge
  // are, its first slot pair passes, and most hinges need no test of their own.
  const std::vector<SlotPair> first(in.hinges.size(), params.uUp ? SlotPair::UpDown : SlotPair::DownUp);
  std::vector<std::vector<PatchHinge>> base(n);
  const std::vector<std::shared_ptr<const SlotCutter>> cutters = patchCutters(in, params, cache, needed);
  std::vector<char> whole(n, 0);
  parallelFor(static_cast<size_t>(n), [&](size_t p) {
    if (!needed[p]) return;
    base[p] = patchHinges(in, first, static_cast<int>(p));
    whole[p] = !cutters[p]->inPieces(slotStrips(planSlots(in.patches[p].shape, base[p], params), params));
    for (PatchHinge& h : base[p]) h.slot = Slot::None;
  });
  // The position of hinge h in its patch's list (patchHinges keeps the hinges' order).
  std::vector<int> indexIn(2 * in.hinges.size(), -1);
  std::vector<int> count(n, 0);
  for (size_t h = 0; h < in.hinges.size(); ++h) {
    indexIn[2 * h] = count[in.hinges[h].u]++;
    indexIn[2 * h + 1] = count[in.hinges[h].v]++;
  }
  const auto splits = [&](int p, int index, Slot slot) {
    std::vector<PatchHinge> hs = base[p];
    hs[index].slot = slot;
    return cutters[p]->inPieces(slotStrips(planSlots(in.patches[p].shape, hs, params), params));
  };
  std::vector<char> grazing(hinges.size(), 0);
  parallelFor(hinges.size(), [&](size_t i) {
    const int h = hinges[i];
    const ScaffoldHinge& hinge = in.hinges[h];
    if (whole[hinge.u] && whole[hinge.v]) return;
    const int iu = indexIn[2 * h], iv = indexIn[2 * h + 1];
    const bool upDown = !splits(hinge.u, iu, Slot::Up) && !splits(hinge.v, iv, Slot::Down);
    const bool downUp = !upDown && !splits(hinge.u, iu, Slot::Down) && !splits(hinge.v, iv, Slot::Up);
    // A hinge that holds keeps an up/down slot (the search never cuts its last one through).
    const bool through = !upDown && !downUp && !hinge.holds &&
                         (!splits(hinge.u, iu, Slot::Through) || !splits(hinge.v, iv, Slot::Through));
    grazing[i] = !(upDown || downUp || through);
  });
  std::vector<int> out;
  for (size_t i = 0; i < hinges.size(); ++i)
    if (grazing[i]) out.push_back(hinges[i]);
  return out;
}

GrazeRepair avoidGrazes(Arrangement& a, const SlotParams& params, double tolerance,
                        const Deadline& deadline) {
  GrazeRepair g;
  const auto inputOf = [&](const Scaffold& s) { return realizationInput(a, s, tolerance); };
  CutterCache cutters;
  std::vector<int> found = grazingHinges(inputOf(a.scaffold), params, {}, &cutters);
  g.found = static_cast<int>(found.size());
  std::set<HingeKey> bad;
  for (const int h : found) bad.insert(keyOf(a.scaffold.hinges[h]));
  std::set<HingeKey> givenUp;
  const auto hingesOf = [](const Scaffold& s, int k) {
    std::vector<int> out;
    for (int h = 0; h < static_cast<int>(s.hinges.size()); ++h)
      if (s.hinges[h].u == k || s.hinges[h].v == k) out.push_back(h);
    return out;
  };
  const auto badOf = [&](int k) {
    int n = 0;
    for (const HingeKey& key : bad) n += std::get<0>(key) == k || std::get<1>(key) == k ? 1 : 0;
    return n;
  };
  while (true) {
    if (deadline.passed()) {
      g.timedOut = true;
      break;
    }
    auto next = std::find_if(bad.begin(), bad.end(), [&](const HingeKey& k) { return !givenUp.count(k); });
    if (next == bad.end()) break;
    const HingeKey hinge = *next;
    bool moved = false;
    // The V-patch first, then the U-patch; nearest slices first.
    for (const int k : {std::get<1>(hinge), std::get<0>(hinge)}) {
      const int before = badOf(k);
      for (const int delta : kMoves) {
        Scaffold trial = a.scaffold;
        if (!movePatch(trial, a.u, a.v, a.uCylinders, a.vCylinders, *a.table, a.minSpacing, k,
                       trial.patches[k].slice + delta))
          continue;
        if (!certifyScaffold(trial).stable) continue;
        const std::vector<int> now = grazingHinges(inputOf(trial), params, hingesOf(trial, k), &cutters);
        if (static_cast<int>(now.size()) >= before) continue;
        // Hinges of k are new; the others keep their keys (the patch indices stay).
        for (auto it = bad.begin(); it != bad.end();)
          it = std::get<0>(*it) == k || std::get<1>(*it) == k ? bad.erase(it) : std::next(it);
        for (const int h : now) bad.insert(keyOf(trial.hinges[h]));
        a.scaffold = std::move(trial);
        ++g.moved;
        moved = true;
        break;
      }
      if (moved) break;
    }
    if (moved) continue;
    // No slice near works: take out the smaller of the two patches where the scaffold
    // stays certified without it (the slot search could only fail on it, at length, and
    // the split repair would take it out after).
    std::vector<int> which{std::get<0>(hinge), std::get<1>(hinge)};
    const auto areaOf = [&](int k) {
      const ScaffoldPatch& p = a.scaffold.patches[k];
      return a.cylinders(p.family)[p.cylinder].section.area();
    };
    if (areaOf(which[1]) < areaOf(which[0])) std::swap(which[0], which[1]);
    for (const int k : which) {
      Scaffold trial = a.scaffold;
      dropPatch(trial, *a.table, k);
      if (!certifyScaffold(trial).stable) continue;
      a.scaffold = std::move(trial);
      const auto renumber = [&](const std::set<HingeKey>& keys) {
        std::set<HingeKey> out;
        for (auto [u, v, w] : keys) {
          if (u == k || v == k) continue;
          out.insert({u > k ? u - 1 : u, v > k ? v - 1 : v, w});
        }
        return out;
      };
      bad = renumber(bad);
      givenUp = renumber(givenUp);
      ++g.dropped;
      moved = true;
      break;
    }
    if (!moved) givenUp.insert(hinge);
  }
  g.remaining = static_cast<int>(bad.size());
  if (g.moved + g.dropped > 0) remeasure(a);
  return g;
}

void repairSplits(Arrangement& a, Realization& r, GrazeRepair& g, const SlotParams& params, double tolerance,
                  const Deadline& deadline) {
  const auto broken = [](const Realization& x) { return x.splitPatches + x.lostPins; };
  const auto better = [&](const Realization& x) {
    return std::make_pair(broken(x), x.interlocks.remaining) <
           std::make_pair(broken(r), r.interlocks.remaining);
  };
  // Tries a changed scaffold: kept, with its search, when fewer patches are broken.
  // Each attempt searches the whole design again; kMaxAttempts bounds the cost where
  // nothing helps (man.off: 0.3 s a search).
  int attempts = 0;
  const std::shared_ptr<RealizeMemo> memo = makeRealizeMemo();
  // `renumber` maps the patch indices of the current scaffold to the trial's (-1: gone).
  const auto attempt = [&](Scaffold trial, const std::vector<int>& renumber) {
    if (attempts >= kMaxAttempts || deadline.passed() || !certifyScaffold(trial).stable) return false;
    ++attempts;
    // The slots every hinge had that is still there, by what it joins.
    std::map<HingeKey, SlotPair> had;
    for (size_t h = 0; h < a.scaffold.hinges.size(); ++h) {
      ScaffoldHinge moved = a.scaffold.hinges[h];
      moved.u = renumber[moved.u];
      moved.v = renumber[moved.v];
      if (moved.u >= 0 && moved.v >= 0) had[keyOf(moved)] = r.slots[h];
    }
    std::vector<SlotPair> start(trial.hinges.size(), params.uUp ? SlotPair::UpDown : SlotPair::DownUp);
    for (size_t h = 0; h < trial.hinges.size(); ++h) {
      const auto it = had.find(keyOf(trial.hinges[h]));
      if (it != had.end()) start[h] = it->second;
    }
    std::swap(a.scaffold, trial);
    Realization next = realize(realizationInput(a, tolerance), params, deadline, start, memo.get());
    if (better(next)) {
      r = std::move(next);
      return true;
    }
    std::swap(a.scaffold, trial);
    return false;
  };
  const auto identity = [&] {
    std::vector<int> same(a.scaffold.patches.size());
    for (size_t k = 0; k < same.size(); ++k) same[k] = static_cast<int>(k);
    return same;
  };
  const auto move = [&](int k) {
    for (const int delta : kMoves) {
      Scaffold trial = a.scaffold;
      if (movePatch(trial, a.u, a.v, a.uCylinders, a.vCylinders, *a.table, a.minSpacing, k,
                    trial.patches[k].slice + delta) &&
          attempt(std::move(trial), identity()))
        return true;
    }
    return false;
  };
  const auto drop = [&](int k) {
    Scaffold trial = a.scaffold;
    dropPatch(trial, *a.table, k);
    std::vector<int> renumber = identity();
    for (int& i : renumber) i = i == k ? -1 : i > k ? i - 1 : i;
    return attempt(std::move(trial), renumber);
  };
  // Each round changes one patch and keeps the change only when it helps, so the count of
  // broken patches falls every round. Order: move a split patch; move the partner across a
  // graze of it (the other side of a hinge no slot can cut); take the partner out; take the
  // split patch out. Taking out leaves a cylinder without a patch, but the design buildable.
  for (int rounds = broken(r); rounds > 0 && broken(r) > 0; --rounds) {
    const std::vector<int> culprits = r.split;
    if (culprits.empty()) break;  // lost pins only: moving a patch is no answer to those
    // Partners across a graze of a split patch first, then its other partners.
    std::vector<int> partners;
    {
      const RealizationInput in = realizationInput(a, tolerance);
      std::vector<int> theirs;
      for (int h = 0; h < static_cast<int>(in.hinges.size()); ++h)
        for (const int k : culprits)
          if (in.hinges[h].u == k || in.hinges[h].v == k) theirs.push_back(h);
      const auto add = [&](int h) {
        for (const int k : {in.hinges[h].u, in.hinges[h].v})
          if (std::find(culprits.begin(), culprits.end(), k) == culprits.end() &&
              std::find(partners.begin(), partners.end(), k) == partners.end())
            partners.push_back(k);
      };
      for (const int h : grazingHinges(in, params, theirs)) add(h);
      for (const int h : theirs) add(h);
    }
    bool changed = false;
    for (const int k : culprits)
      if (!changed && move(k)) ++g.splitMoved, changed = true;
    for (const int k : partners)
      if (!changed && move(k)) ++g.splitMoved, changed = true;
    for (const int k : partners)
      if (!changed && drop(k)) ++g.splitDropped, changed = true;
    for (const int k : culprits)
      if (!changed && drop(k)) ++g.splitDropped, changed = true;
    if (!changed) break;
  }
  g.splitTimedOut = deadline.passed();
  if (g.splitMoved + g.splitDropped > 0) remeasure(a);
}

}  // namespace sliceform
