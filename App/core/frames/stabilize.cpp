// SPDX-License-Identifier: LGPL-2.1-or-later
#include "frames/stabilize.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <set>
#include <sstream>

#include "support/error.hpp"
#include "support/per_family.hpp"

namespace sliceform {
namespace {

// Positions are slice centres computed in floating point; a gap of exactly the spacing
// rule must not fail it by a rounding error.
constexpr double kSpacingSlack = 1e-6;

struct Candidate {
  Family family = Family::U;
  int cylinder = 0;
  int slice = 0;
};

class Builder {
 public:
  Builder(const SliceSet& u, const SliceSet& v, const std::vector<Cylinder>& cu,
          const std::vector<Cylinder>& cv, const HingeTable& table, double minSpacing)
      : sets_{u, v},
        cylinders_{cu, cv},
        table_(table),
        minSpacing_(minSpacing),
        pitch_{slicesApart(minSpacing, u.interval), slicesApart(minSpacing, v.interval)} {}

  Scaffold scaffold;

  const std::vector<Cylinder>& cylinders(Family f) const { return cylinders_[f]; }
  double volume(Family f, int c) const {
    const Cylinder& cyl = cylinders(f)[c];
    return cyl.section.area() * (cyl.lastSlice - cyl.firstSlice + 1);
  }

  // The slices of a cylinder, those on the family's grid first (every pitch_-th slice,
  // pitch_ slices being the spacing rule), then middle first: the middle patch shows the
  // cylinder best, and patches on the grid never stand in each other's way (on one slice
  // they lie side by side, else a pitch apart). Measured on man.off: silhouette IoU
  // 0.815/0.880 middle first, 0.934/0.915 grid first.
  std::vector<int> slicesMiddleOut(Family f, int c) const {
    const Cylinder& cyl = cylinders(f)[c];
    std::vector<int> out;
    for (int k = cyl.firstSlice; k <= cyl.lastSlice; ++k) out.push_back(k);
    const double middle = 0.5 * (cyl.firstSlice + cyl.lastSlice);
    const int pitch = pitch_[f];
    std::stable_sort(out.begin(), out.end(), [&](int a, int b) {
      const bool ga = a % pitch == 0, gb = b % pitch == 0;
      if (ga != gb) return ga;
      return std::fabs(a - middle) < std::fabs(b - middle);
    });
    return out;
  }

  bool holds(const Candidate& p, const ScaffoldPatch& q) const {
    if (p.family == q.family) return false;
    return p.family == Family::U ? table_.holds(p.cylinder, p.slice, q.cylinder, q.slice)
                                 : table_.holds(q.cylinder, q.slice, p.cylinder, p.slice);
  }

  // Placed patches of the other family that hold `c`, counted by distinct position.
  int pins(const Candidate& c) const {
    std::set<int> slices;
    for (const ScaffoldPatch& q : scaffold.patches)
      if (holds(c, q)) slices.insert(q.slice);
    return static_cast<int>(slices.size());
  }

  bool placed(const Candidate& c) const {
    return std::any_of(scaffold.patches.begin(), scaffold.patches.end(), [&](const ScaffoldPatch& p) {
      return p.family == c.family && p.cylinder == c.cylinder && p.slice == c.slice;
    });
  }
  bool covered(Family f, int c) const {
    return std::any_of(scaffold.patches.begin(), scaffold.patches.end(),
                       [&](const ScaffoldPatch& p) { return p.family == f && p.cylinder == c; });
  }

  double pos(const Candidate& c) const { return sets_[c.family].slices[c.slice].position; }

  // The spacing rule: no placed patch of c's family closer than minSpacing whose outline,
  // seen along the normal, overlaps c's. Patches of one slice lie side by side, not stacked.
  bool spaced(const Candidate& c) const {
    for (const ScaffoldPatch& q : scaffold.patches) {
      if (q.family != c.family || q.slice == c.slice) continue;
      if (std::fabs(q.position - pos(c)) < minSpacing_ + kSpacingSlack &&
          stacked(c.family, c.cylinder, q.cylinder))
        return false;
    }
    return true;
  }
  bool allowed(const Candidate& c) const { return !placed(c) && spaced(c); }

  void place(const Candidate& c) {
    const SliceSet& set = sets_[c.family];
    scaffold.patches.push_back({c.family, c.cylinder, c.slice, set.slices[c.slice].position});
  }

  // Every (cylinder, slice) of a family, big cylinders and middle slices first.
  std::vector<Candidate> candidates(Family f) const {
    std::vector<int> order(cylinders(f).size());
    for (size_t c = 0; c < order.size(); ++c) order[c] = static_cast<int>(c);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return volume(f, a) > volume(f, b); });
    std::vector<Candidate> out;
    for (int c : order)
      for (int k : slicesMiddleOut(f, c)) out.push_back({f, c, k});
    return out;
  }

  // A 2x2 grid: two U-patches and two V-patches at distinct positions, all four hinges
  // holding (Claims 1 and 2). Tries big cylinders and middle slices first.
  bool seed() {
    const std::vector<Candidate> us = candidates(Family::U), vs = candidates(Family::V);
    const size_t words = (us.size() + 63) / 64;
    std::vector<std::vector<uint64_t>> holding(vs.size(), std::vector<uint64_t>(words, 0));
    for (size_t q = 0; q < vs.size(); ++q) {
      for (size_t p = 0; p < us.size(); ++p) {
        if (table_.holds(us[p].cylinder, us[p].slice, vs[q].cylinder, vs[q].slice))
          holding[q][p / 64] |= uint64_t{1} << (p % 64);
      }
    }
    // Among all grids, the one whose patches are farthest apart (as a share of the model's
    // extent, up to a quarter of it): close patches make a flimsy grid, and patches a
    // slice apart are no use on paper. Ties go to the earlier, bigger and more central ones.
    const double extentU = sets_.u.slices.back().position - sets_.u.slices.front().position;
    const double extentV = sets_.v.slices.back().position - sets_.v.slices.front().position;
    double bestScore = -1;
    Candidate best[4];
    for (size_t q1 = 0; q1 < vs.size(); ++q1) {
      for (size_t q2 = q1 + 1; q2 < vs.size(); ++q2) {
        if (vs[q1].slice == vs[q2].slice || !apart(vs[q1], vs[q2])) continue;
        const double sepV = std::fabs(pos(vs[q1]) - pos(vs[q2])) / std::max(extentV, 1e-9);
        if (std::min(sepV, 0.25) <= bestScore) continue;
        int first = -1, far = -1;  // a held U-patch, and the held one farthest from it
        int low = -1, high = -1;   // the held U-patches lowest and highest along U
        for (size_t w = 0; w < words; ++w) {
          for (uint64_t bits = holding[q1][w] & holding[q2][w]; bits; bits &= bits - 1) {
            const int p = static_cast<int>(64 * w + __builtin_ctzll(bits));
            if (low < 0 || pos(us[p]) < pos(us[low])) low = p;
            if (high < 0 || pos(us[p]) > pos(us[high])) high = p;
            if (first < 0)
              first = p;
            else if (!apart(us[p], us[first]))
              continue;
            else if (far < 0 ||
                     std::fabs(pos(us[p]) - pos(us[first])) > std::fabs(pos(us[far]) - pos(us[first])))
              far = p;
          }
        }
        // None far enough from the first (the spacing rule): the two held farthest apart.
        if (far < 0 && low >= 0 && us[low].slice != us[high].slice && apart(us[low], us[high]))
          first = low, far = high;
        if (far < 0 || us[far].slice == us[first].slice) continue;
        const double sepU = std::fabs(pos(us[far]) - pos(us[first])) / std::max(extentU, 1e-9);
        const double score = std::min({sepU, sepV, 0.25});
        if (score > bestScore) {
          bestScore = score;
          best[0] = us[first], best[1] = us[far], best[2] = vs[q1], best[3] = vs[q2];
        }
      }
    }
    if (bestScore < 0) return false;
    for (const Candidate& c : best) place(c);
    return true;
  }

  // A patch for cylinder c where it is held by two placed patches; false if nowhere.
  bool attach(Family f, int c) {
    for (int k : slicesMiddleOut(f, c)) {
      const Candidate cand{f, c, k};
      if (allowed(cand) && pins(cand) >= 2) {
        place(cand);
        return true;
      }
    }
    return false;
  }

  // A support patch: held by two placed patches, and reaching as many uncovered cylinders
  // as possible, so they can be attached next.
  bool support(const std::vector<std::pair<Family, int>>& uncovered) {
    Candidate best;
    int bestScore = 0;
    for (Family f : {Family::U, Family::V}) {
      for (const Candidate& cand : candidates(f)) {
        if (!allowed(cand) || pins(cand) < 2) continue;
        int score = 0;
        for (const auto& [g, c] : uncovered) {
          if (g == f) continue;
          for (int k : slicesMiddleOut(g, c)) {
            if (holds(cand, {g, c, k, 0})) {
              ++score;
              break;
            }
          }
        }
        if (score > bestScore) {
          bestScore = score;
          best = cand;
        }
      }
    }
    if (bestScore == 0) return false;
    place(best);
    return true;
  }

  // Fig. 16b: extra patches in long cylinders, each held by two patches of the other family.
  void densify(double maxSpacing) {
    for (Family f : {Family::U, Family::V}) {
      const SliceSet& set = sets_[f];
      for (int c = 0; c < static_cast<int>(cylinders(f).size()); ++c) {
        if (!covered(f, c)) continue;
        while (true) {
          // The slice farthest from this cylinder's patches that can be held.
          int bestSlice = -1;
          double bestGap = maxSpacing;
          for (int k : slicesMiddleOut(f, c)) {
            double gap = HUGE_VAL;
            for (const ScaffoldPatch& p : scaffold.patches)
              if (p.family == f && p.cylinder == c)
                gap = std::min(gap, std::fabs(p.position - set.slices[k].position));
            if (gap > bestGap && allowed({f, c, k}) && pins({f, c, k}) >= 2) {
              bestGap = gap;
              bestSlice = k;
            }
          }
          if (bestSlice < 0) break;
          place({f, c, bestSlice});
        }
      }
    }
  }

 private:
  PerFamily<const SliceSet&> sets_;
  PerFamily<const std::vector<Cylinder>&> cylinders_;
  const HingeTable& table_;
  double minSpacing_;
  PerFamily<int> pitch_;  // slices that far apart are the rule apart
  // Whether two cylinders' outlines (holes filled) overlap seen along their family's
  // normal, by pair; filled because a patch seen through another's hole still has its
  // slots beside the other's on every partner that crosses both.
  mutable std::map<std::tuple<Family, int, int>, bool> stacked_;

  bool stacked(Family f, int a, int b) const {
    if (a > b) std::swap(a, b);
    const auto key = std::make_tuple(f, a, b);
    const auto it = stacked_.find(key);
    if (it != stacked_.end()) return it->second;
    const bool overlap = stackedSections(cylinders(f)[a].section, cylinders(f)[b].section);
    stacked_.emplace(key, overlap);
    return overlap;
  }

  // Two candidates of one family that may both be placed under the spacing rule.
  bool apart(const Candidate& a, const Candidate& b) const {
    return a.slice == b.slice || std::fabs(pos(a) - pos(b)) >= minSpacing_ + kSpacingSlack ||
           !stacked(a.family, a.cylinder, b.cylinder);
  }

  bool holds(const Candidate& p, const Candidate& q) const {
    return holds(p, ScaffoldPatch{q.family, q.cylinder, q.slice, 0});
  }
};

}  // namespace

bool stackedSections(const Region2d& a, const Region2d& b) {
  const Box2 ba = a.bounds(), bb = b.bounds();
  if (ba.empty || bb.empty || ba.min.x >= bb.max.x || bb.min.x >= ba.max.x || ba.min.y >= bb.max.y ||
      bb.min.y >= ba.max.y)
    return false;
  return !a.withoutHoles().intersect(b.withoutHoles()).empty();
}

bool movePatch(Scaffold& s, const SliceSet& u, const SliceSet& v, const std::vector<Cylinder>& uCylinders,
               const std::vector<Cylinder>& vCylinders, const HingeTable& table, double minSpacing, int k,
               int slice) {
  ScaffoldPatch& p = s.patches[k];
  const PerFamily<const SliceSet&> sets{u, v};
  const PerFamily<const std::vector<Cylinder>&> cylindersOf{uCylinders, vCylinders};
  const std::vector<Cylinder>& cylinders = cylindersOf[p.family];
  const Cylinder& c = cylinders[p.cylinder];
  if (slice < c.firstSlice || slice > c.lastSlice) return false;
  const double position = sets[p.family].slices[slice].position;
  for (int q = 0; q < static_cast<int>(s.patches.size()); ++q) {
    const ScaffoldPatch& o = s.patches[q];
    if (q == k || o.family != p.family) continue;
    if (o.slice == slice) {
      if (o.cylinder == p.cylinder) return false;  // that patch is there already
      continue;                                    // side by side on one slice
    }
    if (std::fabs(o.position - position) < minSpacing + kSpacingSlack &&
        stackedSections(c.section, cylinders[o.cylinder].section))
      return false;
  }
  p.slice = slice;
  p.position = position;
  findHinges(s, table);
  return true;
}

void dropPatch(Scaffold& s, const HingeTable& table, int k) {
  const ScaffoldPatch gone = s.patches[k];
  s.patches.erase(s.patches.begin() + k);
  const bool covered = std::any_of(s.patches.begin(), s.patches.end(), [&](const ScaffoldPatch& p) {
    return p.family == gone.family && p.cylinder == gone.cylinder;
  });
  if (!covered) s.uncovered(gone.family).push_back(gone.cylinder);
  findHinges(s, table);
}

int slicesApart(double spacing, double interval) {
  return std::max(1, static_cast<int>(std::ceil(spacing / interval - 1e-9)));
}

double minPatchSpacing(const StabilizeOptions& options, const HingeRules& rules) {
  const double least = rules.slotWidth + rules.minSlotEdgeDistance;
  if (options.minSpacing == 0) return least;
  if (!(options.minSpacing >= least) || !std::isfinite(options.minSpacing)) {
    std::ostringstream out;
    out << "the minimum patch spacing must be at least the slot width plus the paper kept beside a slot ("
        << least << " mm here), so that paper is left between two neighbouring slots; lower "
        << "--min-slot-edge-distance to allow closer patches";
    throw Error(ErrorKind::BadParameter, out.str());
  }
  return options.minSpacing;
}

std::string patchId(const Scaffold& scaffold, int patch) {
  const Family f = scaffold.patches[patch].family;
  int number = 0;
  for (int k = 0; k < patch; ++k) number += scaffold.patches[k].family == f ? 1 : 0;
  return familyName(f) + std::to_string(number);
}

Scaffold stabilize(const SliceSet& u, const SliceSet& v, const std::vector<Cylinder>& uCylinders,
                   const std::vector<Cylinder>& vCylinders, const HingeTable& table,
                   const StabilizeOptions& options) {
  Builder b(u, v, uCylinders, vCylinders, table, minPatchSpacing(options, table.rules()));
  std::vector<std::pair<Family, int>> required;
  for (Family f : {Family::U, Family::V}) {
    const bool needed =
        options.scheme == Scheme::Both || (f == Family::U) == (options.scheme == Scheme::DominantU);
    if (!needed) continue;
    std::vector<int> order(b.cylinders(f).size());
    for (size_t c = 0; c < order.size(); ++c) order[c] = static_cast<int>(c);
    std::stable_sort(order.begin(), order.end(),
                     [&](int x, int y) { return b.volume(f, x) > b.volume(f, y); });
    for (int c : order) required.push_back({f, c});
  }
  if (b.seed()) {
    while (true) {
      std::vector<std::pair<Family, int>> uncovered;
      for (const auto& [f, c] : required)
        if (!b.covered(f, c)) uncovered.push_back({f, c});
      if (uncovered.empty()) break;
      bool progress = false;
      for (const auto& [f, c] : uncovered) progress = b.attach(f, c) || progress;
      if (!progress && !b.support(uncovered)) break;
    }
    if (options.maxSpacing > 0) b.densify(options.maxSpacing);
  }
  for (const auto& [f, c] : required)
    if (!b.covered(f, c)) b.scaffold.uncovered(f).push_back(c);
  Scaffold s = std::move(b.scaffold);
  findHinges(s, table);
  return s;
}

void findHinges(Scaffold& scaffold, const HingeTable& table) {
  scaffold.hinges.clear();
  const auto& ps = scaffold.patches;
  for (int a = 0; a < static_cast<int>(ps.size()); ++a) {
    if (ps[a].family != Family::U) continue;
    for (int b = 0; b < static_cast<int>(ps.size()); ++b) {
      if (ps[b].family != Family::V) continue;
      for (const Interval& w : table.segments(ps[a].cylinder, ps[a].slice, ps[b].cylinder, ps[b].slice)) {
        const Interval grip = table.grip(ps[a].cylinder, ps[a].slice, ps[b].cylinder, ps[b].slice, w);
        scaffold.hinges.push_back({a, b, w, grip.hi > grip.lo, grip});
      }
    }
  }
}

}  // namespace sliceform
