// SPDX-License-Identifier: LGPL-2.1-or-later
#include "realization/realize.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <tuple>

#include "arrangement/arrange.hpp"
#include "frames/hinge_table.hpp"
#include "realization/interlock.hpp"
#include "realization/patch_states.hpp"
#include "support/parallel.hpp"
#include "support/per_family.hpp"

namespace sliceform {
namespace {

constexpr int kMaxCommonHinges = 8;  // 2^8 combinations of one pair's hinges at most

// What the search minimises, in this order.
struct Score {
  int broken = 0;  // split patches, and pairs whose holding hinges all lost their paper
  // Pieces beyond one, summed over the split patches: a move that takes a patch from five
  // pieces to four is progress, though it is still split.
  int extraPieces = 0;
  int interlocks = 0, cutThroughs = 0;
  bool operator<(const Score& o) const {
    return std::tie(broken, extraPieces, interlocks, cutThroughs) <
           std::tie(o.broken, o.extraPieces, o.interlocks, o.cutThroughs);
  }
};

using Move = SlotMove;

bool isUpDown(SlotPair s) {
  return s == SlotPair::UpDown || s == SlotPair::DownUp;
}
SlotPair flipped(SlotPair s) {
  return s == SlotPair::UpDown ? SlotPair::DownUp : SlotPair::UpDown;
}

double distanceToSegment(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 d{b.x - a.x, b.y - a.y};
  const double len2 = d.x * d.x + d.y * d.y;
  double t = len2 > 0 ? ((p.x - a.x) * d.x + (p.y - a.y) * d.y) / len2 : 0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(p.x - a.x - t * d.x, p.y - a.y - t * d.y);
}

double distanceToBoundary(const std::vector<Region2d::Loop>& loops, Vec2 p) {
  double best = std::numeric_limits<double>::infinity();
  for (const Region2d::Loop& loop : loops)
    for (size_t i = 0, n = loop.size(); i < n; ++i)
      best = std::min(best, distanceToSegment(p, loop[i], loop[(i + 1) % n]));
  return best;
}

}  // namespace

std::shared_ptr<RealizeMemo> makeRealizeMemo() {
  return std::make_shared<RealizeMemo>();
}

namespace {

class Search {
 public:
  Search(const RealizationInput& in, const SlotParams& params, const Deadline& deadline,
         const std::vector<SlotPair>& start, RealizeMemo* memo)
      : in_(in), params_(params), deadline_(deadline), n_(static_cast<int>(in.patches.size())) {
    hingesOf_.resize(n_);
    hingeIndex_.resize(in.hinges.size());
    for (int h = 0; h < static_cast<int>(in.hinges.size()); ++h) {
      hingeIndex_[h] = {hingesOf_[in.hinges[h].u].size(), hingesOf_[in.hinges[h].v].size()};
      hingesOf_[in.hinges[h].u].push_back(h);
      hingesOf_[in.hinges[h].v].push_back(h);
    }
    slots_ = start.size() == in.hinges.size()
                 ? start
                 : std::vector<SlotPair>(in.hinges.size(), params.uUp ? SlotPair::UpDown : SlotPair::DownUp);
    // Each patch's own tools and first state depend on nothing else: both cores at once.
    states_.emplace(in, params, memo, hingesOf_, slots_);
    locks_.assign(static_cast<size_t>(n_) * n_, 0);
    state_.resize(n_);
    std::vector<int> all(n_);
    for (int p = 0; p < n_; ++p) all[p] = p;
    const std::vector<std::shared_ptr<const PatchState>> first =
        states_->evaluate(all, std::vector<std::vector<SlotPair>>(1, slots_), true);
    for (int p = 0; p < n_; ++p) state_[p] = first[p];
    for (int p = 0; p < n_; ++p)
      if (in.patches[p].family == Family::U) refreshLocks(p);
    // The pairs with a holding hinge, in order, and how many of those meet: score() reads
    // the pairs left with none from the counts, not from the hinges at every move.
    pairOf_.assign(in.hinges.size(), -1);
    for (const ScaffoldHinge& hinge : in.hinges)
      if (hinge.holds) pairs_.emplace_back(hinge.u, hinge.v);
    std::sort(pairs_.begin(), pairs_.end());
    pairs_.erase(std::unique(pairs_.begin(), pairs_.end()), pairs_.end());
    for (size_t h = 0; h < in.hinges.size(); ++h)
      if (in.hinges[h].holds)
        pairOf_[h] = static_cast<int>(
            std::lower_bound(pairs_.begin(), pairs_.end(), std::pair{in.hinges[h].u, in.hinges[h].v}) -
            pairs_.begin());
    met_.assign(pairs_.size(), 0);
    lost_ = static_cast<int>(pairs_.size());
    meets_.assign(in.hinges.size(), 0);
    for (size_t h = 0; h < meets_.size(); ++h) setMeets(static_cast<int>(h), meets(static_cast<int>(h)));
  }

  void run() {
    found_ = score().interlocks;
    // Violations no move improves, with the version of their neighbourhood then: one is
    // tried again once a move changed a patch its moves touch (a move changes what other
    // moves can do), and not before (the Menger sponge: 180 patch states a try).
    Given given;
    const int maxSteps = 4 * static_cast<int>(in_.hinges.size()) + 16;
    for (int step = 0; step < maxSteps; ++step) {
      if (deadline_.passed()) {
        timedOut_ = true;
        break;
      }
      std::pair<int, int> v = nextViolation(given);
      if (v.first < 0) break;
      if (!improve(v)) given[v] = neighbourhoodVersion(v);
    }
  }

  Realization result() const {
    Realization r;
    r.params = params_;
    r.slots = slots_;
    for (const auto& st : state_) r.cuts.push_back(st->cuts);
    r.slotted.resize(n_);
    parallelFor(static_cast<size_t>(n_),
                [&](size_t p) { r.slotted[p] = states_->paperOf(static_cast<int>(p), *state_[p]); });
    const Score s = score();
    r.interlocks = {found_, std::max(0, found_ - s.interlocks), s.interlocks, s.cutThroughs};
    for (int p = 0; p < n_; ++p)
      if (state_[p]->pieces > 1) r.split.push_back(p);
    r.splitPatches = static_cast<int>(r.split.size());
    r.meets.assign(meets_.begin(), meets_.end());
    r.lostPins = static_cast<int>(lostPins().size());
    r.timedOut = timedOut_;
    measure(r);
    order(r);
    return r;
  }

 private:
  int lockAt(int a, int b) const { return locks_[static_cast<size_t>(a) * n_ + b]; }

  void refreshLocks(int p) {
    const bool isU = in_.patches[p].family == Family::U;
    for (int q = 0; q < n_; ++q) {
      if (in_.patches[q].family == in_.patches[p].family) continue;
      const int a = isU ? p : q, b = isU ? q : p;
      int& lock = locks_[static_cast<size_t>(a) * n_ + b];
      const int now = interlockCount(state_[a]->holes, in_.frames.u, state_[b]->holes, in_.frames.v);
      lockTotal_ += now - lock;
      lock = now;
    }
  }

  // meets_[h] = m, the counts of meeting holding hinges per pair kept with it.
  void setMeets(int h, bool m) {
    if (meets_[h] == m) return;
    meets_[h] = m;
    const int pair = pairOf_[h];
    if (pair < 0) return;
    const int before = met_[pair];
    met_[pair] += m ? 1 : -1;
    if (before == 0) --lost_;
    if (met_[pair] == 0) ++lost_;
  }

  // Whether the slotted patches of hinge h still meet along it: with both slots pointing the
  // same way at two hinges on one line (the paper's rule ends a slot at the next hinge's
  // root), one patch keeps no paper along the second hinge, which is then no hinge.
  bool meets(int h) const {
    const ScaffoldHinge& hinge = in_.hinges[h];
    double covered = 0;
    for (const double length : state_[hinge.u]->onHinge[hingeIndex_[h].first]) covered += length;
    for (const double length : state_[hinge.v]->onHinge[hingeIndex_[h].second]) covered += length;
    return covered >= 0.9 * (hinge.w.hi - hinge.w.lo);
  }

  // Pairs that had a holding hinge and have none left whose patches meet.
  std::set<std::pair<int, int>> lostPins() const {
    std::set<std::pair<int, int>> lost;
    for (size_t k = 0; k < pairs_.size(); ++k)
      if (met_[k] == 0) lost.insert(lost.end(), pairs_[k]);
    return lost;
  }

  Score score() const {
    Score s;
    for (int p = 0; p < n_; ++p) {
      s.broken += state_[p]->pieces > 1 ? 1 : 0;
      s.extraPieces += std::max(0, state_[p]->pieces - 1);
    }
    s.broken += lost_;
    s.interlocks = lockTotal_;
    for (const SlotPair x : slots_) s.cutThroughs += isUpDown(x) ? 0 : 1;
    return s;
  }

  using Given = std::map<std::pair<int, int>, long>;

  // How often the patches a violation's moves touch (its patches and their partners) have
  // changed in accepted moves.
  long neighbourhoodVersion(std::pair<int, int> v) const {
    long sum = 0;
    for (const int p : {v.first, v.second}) {
      if (p < 0) continue;
      sum += version_[p];
      for (const int h : hingesOf_[p])
        sum += version_[in_.hinges[h].u == p ? in_.hinges[h].v : in_.hinges[h].u];
    }
    return sum;
  }
  bool givenUp(const Given& given, std::pair<int, int> v) const {
    const auto it = given.find(v);
    return it != given.end() && it->second == neighbourhoodVersion(v);
  }

  // A split patch (p, -1), or an interlocked pair (U-patch, V-patch); (-1, -1) when none.
  std::pair<int, int> nextViolation(const Given& given) const {
    for (int p = 0; p < n_; ++p)
      if (state_[p]->pieces > 1 && !givenUp(given, {p, -1})) return {p, -1};
    for (const auto& pair : lostPins())
      if (!givenUp(given, pair)) return pair;
    for (int a = 0; a < n_; ++a)
      for (int b = 0; b < n_; ++b)
        if (lockAt(a, b) > 0 && !givenUp(given, {a, b})) return {a, b};
    return {-1, -1};
  }

  // Applies a move and returns the score; undo() puts the old state back.
  Score apply(const Move& move) {
    saved_.clear();
    savedLocks_ = locks_;
    savedLockTotal_ = lockTotal_;
    savedMeets_ = meets_;
    savedMet_ = met_;
    savedLost_ = lost_;
    std::set<int> touched;
    for (const auto& [h, pair] : move) {
      saved_.push_back({h, slots_[h]});
      slots_[h] = pair;
      touched.insert(in_.hinges[h].u);
      touched.insert(in_.hinges[h].v);
    }
    savedPatches_.clear();
    for (const int p : touched) {
      savedPatches_.push_back({p, state_[p]});
      state_[p] = states_->of(p, slots_);
    }
    for (const int p : touched) {
      refreshLocks(p);
      for (const int h : hingesOf_[p]) setMeets(h, meets(h));  // only these can change
    }
    return score();
  }

  void undo() {
    for (const auto& [h, pair] : saved_) slots_[h] = pair;
    for (auto& s : savedPatches_) state_[s.patch] = std::move(s.state);
    locks_ = savedLocks_;
    lockTotal_ = savedLockTotal_;
    meets_ = savedMeets_;
    met_ = savedMet_;
    lost_ = savedLost_;
  }

  // Whether hinge h may be cut through: not the last holding up/down hinge of its pair.
  bool mayCutThrough(int h) const {
    const ScaffoldHinge& hinge = in_.hinges[h];
    if (!hinge.holds) return true;
    for (const int o : hingesOf_[hinge.u])
      if (o != h && in_.hinges[o].v == hinge.v && in_.hinges[o].holds && isUpDown(slots_[o])) return true;
    return false;
  }

  std::vector<std::vector<Move>> tiers(std::pair<int, int> v) const {
    std::vector<int> common, others;
    const int a = v.first, b = v.second;
    for (const int p : {a, b}) {
      if (p < 0) continue;
      for (const int h : hingesOf_[p]) {
        const bool pair = b >= 0 && ((in_.hinges[h].u == a && in_.hinges[h].v == b));
        if (pair && isUpDown(slots_[h])) {
          if (std::find(common.begin(), common.end(), h) == common.end()) common.push_back(h);
        } else if (std::find(others.begin(), others.end(), h) == others.end()) {
          others.push_back(h);
        }
      }
    }
    std::vector<std::vector<Move>> out(3);
    if (!common.empty() && common.size() <= kMaxCommonHinges) {
      for (unsigned mask = 1; mask < (1u << common.size()); ++mask) {
        Move m;
        for (size_t k = 0; k < common.size(); ++k)
          if (mask & (1u << k)) m.push_back({common[k], flipped(slots_[common[k]])});
        out[0].push_back(m);
      }
    } else {
      for (const int h : common) out[0].push_back({{h, flipped(slots_[h])}});
    }
    for (const int h : others) {
      if (isUpDown(slots_[h]))
        out[1].push_back({{h, flipped(slots_[h])}});
      else
        out[1].push_back({{h, SlotPair::UpDown}});  // undo an earlier cut-through
    }
    std::vector<int> all = common;
    all.insert(all.end(), others.begin(), others.end());
    for (const int h : all) {
      if (!isUpDown(slots_[h]) || !mayCutThrough(h)) continue;
      out[2].push_back({{h, SlotPair::ThroughNone}});
      out[2].push_back({{h, SlotPair::NoneThrough}});
    }
    return out;
  }

  // A lower bound on the score after move m, knowing the new states of the patches in `known`
  // (cached) and of no other patch the move touches: those are taken whole, free of
  // interlocks, and every pin they lost as restored. `now` is score() and `lost` lostPins().
  Score bound(const Move& m, const std::vector<int>& known, const Score& now,
              const std::set<std::pair<int, int>>& lost) {
    std::set<int> touched;
    for (const auto& [h, pair] : m) touched.insert({in_.hinges[h].u, in_.hinges[h].v});
    Score s = now;
    Move before;  // the move undone
    for (const auto& [h, pair] : m) {
      s.cutThroughs += (isUpDown(pair) ? 0 : 1) - (isUpDown(slots_[h]) ? 0 : 1);
      before.push_back({h, slots_[h]});
      slots_[h] = pair;
    }
    for (const int p : touched) {
      s.broken -= state_[p]->pieces > 1 ? 1 : 0;
      s.extraPieces -= std::max(0, state_[p]->pieces - 1);
      if (std::find(known.begin(), known.end(), p) == known.end()) continue;
      const int pieces = states_->piecesAtLeast(states_->key(p, slots_));
      s.broken += pieces > 1 ? 1 : 0;
      s.extraPieces += std::max(0, pieces - 1);
    }
    for (const auto& [h, pair] : before) slots_[h] = pair;
    for (const auto& [a, b] : lost) s.broken -= touched.count(a) || touched.count(b) ? 1 : 0;
    for (const int p : touched)
      for (int q = 0; q < n_; ++q) {
        if (in_.patches[q].family == in_.patches[p].family || (touched.count(q) && q < p)) continue;
        s.interlocks -= in_.patches[p].family == Family::U ? lockAt(p, q) : lockAt(q, p);
      }
    return s;
  }

  // The moves of a tier that may improve on `now`, by bound() from the states of the
  // violation's own patches, tested first (PatchStates::prepareBounds). The others are no
  // better than now whatever their partners' states, so those are not cut: the search takes
  // the same steps with fewer cuts (occ/Top.brep: a split patch's flips mostly leave it
  // split, and each would cut a partner of some 40 hinges). A bound from fewer pieces than a
  // state has (piecesAtLeast) lets more moves through, never a better one: improve() takes
  // only a move whose score, of the whole states, beats `now`.
  std::vector<Move> mayImprove(const std::vector<Move>& tier, std::pair<int, int> v, const Score& now) {
    std::vector<int> own;
    for (const int p : {v.first, v.second})
      if (p >= 0) own.push_back(p);
    states_->prepareBounds(tier, own, slots_);
    const std::set<std::pair<int, int>> lost = lostPins();
    std::vector<Move> out;
    for (const Move& m : tier)
      if (bound(m, own, now, lost) < now) out.push_back(m);
    return out;
  }

  bool improve(std::pair<int, int> v) {
    const Score now = score();
    states_->age();
    for (const std::vector<Move>& all : tiers(v)) {
      if (deadline_.passed()) return false;
      const std::vector<Move> tier = mayImprove(all, v, now);
      states_->prepare(tier, slots_);
      const Move* best = nullptr;
      Score bestScore = now;
      for (const Move& m : tier) {
        const Score s = apply(m);
        undo();
        if (s < bestScore) bestScore = s, best = &m;
      }
      if (best) {
        apply(*best);
        for (const auto& saved : savedPatches_) ++version_[saved.patch];
        return true;
      }
    }
    return false;
  }

  void measure(Realization& r) const {
    double minEdge = std::numeric_limits<double>::infinity();
    double shortest = std::numeric_limits<double>::infinity();
    std::vector<std::vector<Region2d::Loop>> outlines(n_);
    for (int p = 0; p < n_; ++p) outlines[p] = in_.patches[p].shape.loops();
    for (size_t h = 0; h < in_.hinges.size(); ++h) {
      const ScaffoldHinge& hinge = in_.hinges[h];
      if (!hinge.holds) continue;
      shortest = std::min(shortest, hinge.w.hi - hinge.w.lo);
      const double root = (hinge.grip.lo + hinge.grip.hi) / 2;
      for (const int p : {hinge.u, hinge.v}) {
        const Slot s = p == hinge.u ? uSlot(slots_[h]) : vSlot(slots_[h]);
        if (s != Slot::Up && s != Slot::Down) continue;
        const int other = p == hinge.u ? hinge.v : hinge.u;
        const SliceFrame& f = in_.frames[in_.patches[p].family];
        const SliceFrame& g = in_.frames[in_.patches[other].family];
        const Vec2 at{lineX(f, g, in_.patches[other].position), root};
        minEdge = std::min(minEdge, distanceToBoundary(outlines[p], at) - params_.width() / 2);
      }
    }
    r.minSlotEdgeDistance = std::isfinite(minEdge) ? minEdge : 0;
    r.shortestHinge = std::isfinite(shortest) ? shortest : 0;
  }

  // Greedy: start from the first U-patch, then always the patch hinged to most placed
  // ones (ties: U before V, then by position, the paper's order along the slicing
  // direction). Each patch is checked against every placed one: no interlock.
  void order(Realization& r) const {
    std::vector<bool> placed(n_, false);
    std::vector<int> links(n_, 0);
    r.assemblyChecked = true;
    for (int step = 0; step < n_; ++step) {
      int pick = -1;
      for (int p = 0; p < n_; ++p) {
        if (placed[p]) continue;
        const auto key = [&](int q) {
          return std::make_tuple(-links[q], familyIndex(in_.patches[q].family), in_.patches[q].position);
        };
        if (pick < 0 || key(p) < key(pick)) pick = p;
      }
      for (const int q : r.assemblyOrder) {
        const bool pu = in_.patches[pick].family == Family::U;
        if (in_.patches[q].family == in_.patches[pick].family) continue;
        if ((pu ? lockAt(pick, q) : lockAt(q, pick)) > 0) r.assemblyChecked = false;
      }
      placed[pick] = true;
      r.assemblyOrder.push_back(pick);
      for (const int h : hingesOf_[pick]) {
        const int other = in_.hinges[h].u == pick ? in_.hinges[h].v : in_.hinges[h].u;
        ++links[other];
      }
    }
  }

  struct SavedPatch {
    int patch;
    std::shared_ptr<const PatchState> state;
  };

  const RealizationInput& in_;
  SlotParams params_;
  const Deadline& deadline_;
  bool timedOut_ = false;
  int n_;
  std::vector<std::vector<int>> hingesOf_;
  std::vector<std::pair<size_t, size_t>> hingeIndex_;  // per hinge: its index in hingesOf_ of u, of v
  std::vector<SlotPair> slots_;
  std::optional<PatchStates> states_;                     // each patch with any slots, cut and kept
  std::vector<std::shared_ptr<const PatchState>> state_;  // per patch, for slots_
  std::vector<int> locks_;                                // interlocked hole pairs, [U-patch * n + V-patch]
  int lockTotal_ = 0, savedLockTotal_ = 0;                // their sum
  int found_ = 0;
  std::vector<std::pair<int, SlotPair>> saved_;
  std::vector<SavedPatch> savedPatches_;
  std::vector<int> savedLocks_;
  std::vector<char> meets_, savedMeets_;    // per hinge: meets(h), kept up to date by apply() (setMeets)
  std::vector<std::pair<int, int>> pairs_;  // the (U, V) pairs with a holding hinge, sorted
  std::vector<int> pairOf_;                 // per hinge: its pair in pairs_, -1 if it does not hold
  std::vector<int> met_, savedMet_;         // per pair: its holding hinges that meet
  int lost_ = 0, savedLost_ = 0;            // pairs with none (lostPins().size())
  std::vector<long> version_ = std::vector<long>(n_, 0);  // per patch: accepted moves that changed it
};

}  // namespace

std::vector<PatchHinge> patchHinges(const RealizationInput& input, const std::vector<SlotPair>& slots,
                                    int patch) {
  std::vector<PatchHinge> out;
  const PatchShape& p = input.patches[patch];
  const SliceFrame& f = input.frames[p.family];
  const SliceFrame& g = input.frames[other(p.family)];
  for (size_t h = 0; h < input.hinges.size(); ++h) {
    const ScaffoldHinge& hinge = input.hinges[h];
    if (hinge.patch(p.family) != patch) continue;
    const double x = lineX(f, g, input.patches[hinge.patch(other(p.family))].position);
    const Interval& at = hinge.holds ? hinge.grip : hinge.w;
    out.push_back({x, hinge.w, (at.lo + at.hi) / 2, familySlot(p.family, slots[h])});
  }
  return out;
}

std::vector<std::shared_ptr<const SlotCutter>> patchCutters(const RealizationInput& in,
                                                            const SlotParams& params, CutterCache* cache,
                                                            const std::vector<char>& needed) {
  const size_t n = in.patches.size();
  const auto wanted = [&](size_t p) { return needed.empty() || needed[p]; };
  const auto key = [&](size_t p) {
    return std::make_pair(familyIndex(in.patches[p].family), in.patches[p].cylinder);
  };
  const auto cached = [&](size_t p) { return cache && in.patches[p].cylinder >= 0; };
  std::vector<std::shared_ptr<const SlotCutter>> out(n);
  for (size_t p = 0; p < n; ++p) {
    if (!wanted(p) || !cached(p)) continue;
    const auto it = cache->find(key(p));
    if (it != cache->end()) out[p] = it->second;
  }
  parallelFor(n, [&](size_t p) {
    if (!wanted(p) || out[p]) return;
    std::vector<double> lines;
    for (const PatchHinge& h : patchHinges(in, std::vector<SlotPair>(in.hinges.size()), static_cast<int>(p)))
      lines.push_back(h.x);
    out[p] = std::make_shared<SlotCutter>(in.patches[p].shape, params, in.tolerance, lines);
  });
  for (size_t p = 0; p < n; ++p)
    if (wanted(p) && cached(p)) cache->emplace(key(p), out[p]);
  return out;
}

RealizationInput realizationInput(const Arrangement& a, double tolerance) {
  return realizationInput(a, a.scaffold, tolerance);
}

RealizationInput realizationInput(const Arrangement& a, const Scaffold& scaffold, double tolerance) {
  RealizationInput in;
  in.frames = {a.u.frame, a.v.frame};
  for (const ScaffoldPatch& p : scaffold.patches)
    in.patches.push_back({p.family, p.position, a.cylinders(p.family)[p.cylinder].section, p.cylinder});
  in.hinges = scaffold.hinges;
  in.tolerance = tolerance;
  return in;
}

Realization realize(const RealizationInput& input, const SlotParams& params, const Deadline& deadline,
                    const std::vector<SlotPair>& start, RealizeMemo* memo) {
  checkSlotParams(params);
  Search search(input, params, deadline, start, memo);
  search.run();
  return search.result();
}

}  // namespace sliceform
