// SPDX-License-Identifier: LGPL-2.1-or-later
#include "verify/emitted.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include "frames/hinge_table.hpp"
#include "realization/interlock.hpp"
#include "support/parallel.hpp"

namespace sliceform {
namespace {

// The share of a hinge the two patches must cover between them to meet along it, as the
// independent checker asks.
constexpr double kMeetShare = 0.9;
// Overlaps along a common line count from this share of the design's size: half of what
// the independent checker allows, so a design we pass it passes too.
constexpr double kOverlapShare = 0.5e-3;

double length(const std::vector<Interval>& intervals) {
  double sum = 0;
  for (const Interval& i : intervals) sum += i.hi - i.lo;
  return sum;
}

bool boxesOverlap(const Box2& a, const Box2& b) {
  return !a.empty && !b.empty && a.min.x < b.max.x && b.min.x < a.max.x && a.min.y < b.max.y &&
         b.min.y < a.max.y;
}

}  // namespace

Emitted checkEmitted(const RealizationInput& input, const std::vector<Region2d>& outlines,
                     const SlotParams& params, const std::vector<int>* knownPieces) {
  Emitted e;
  const int n = static_cast<int>(outlines.size());
  const auto& ps = input.patches;
  std::vector<Box2> boxes(n);
  double extent = 0;
  for (int p = 0; p < n; ++p) {
    boxes[p] = outlines[p].bounds();
    if (!boxes[p].empty)
      extent = std::max({extent, boxes[p].max.x - boxes[p].min.x, boxes[p].max.y - boxes[p].min.y});
  }
  std::set<int> failing;

  // One piece each, by the slot search's own neck test against the unslotted shape, and
  // one outer loop each, whatever its size: the search drops crumbs below a slot's area
  // as cut-away waste, but a crumb written to the outline is a second outer loop to the
  // independent checker and a second piece to whoever cuts it (an exact face's sliver).
  std::vector<int>& pieces = e.pieces;
  pieces.assign(n, -1);
  std::vector<size_t> count;
  for (int p = 0; p < n; ++p)
    if (knownPieces && (*knownPieces)[p] >= 0)
      pieces[p] = (*knownPieces)[p];
    else
      count.push_back(static_cast<size_t>(p));
  parallelFor(count.size(), [&](size_t i) {
    const size_t p = count[i];
    pieces[p] = std::max(slottedPieces(ps[p].shape, outlines[p], params, input.tolerance),
                         static_cast<int>(outlines[p].components().size()));
  });
  for (int p = 0; p < n; ++p)
    if (pieces[p] != 1) {
      e.split.push_back(p);
      failing.insert(p);
    }
  e.splitPatches = static_cast<int>(e.split.size());

  // Where each patch lies on the line of every patch of the other family.
  const auto on = [&](int p, int q) {
    const double x = lineX(input.frames[ps[p].family], input.frames[ps[q].family], ps[q].position);
    if (boxes[p].empty || x < boxes[p].min.x || x > boxes[p].max.x) return std::vector<Interval>{};
    return outlines[p].intervalsOnLine({x, 0}, {0, 1});
  };
  std::vector<int> us, vs;
  for (int p = 0; p < n; ++p) (ps[p].family == Family::U ? us : vs).push_back(p);
  std::vector<double> overlap(us.size() * vs.size());
  std::vector<std::vector<Interval>> onU(us.size() * vs.size()), onV(us.size() * vs.size());
  parallelFor(us.size(), [&](size_t i) {
    for (size_t j = 0; j < vs.size(); ++j) {
      const size_t k = i * vs.size() + j;
      onU[k] = on(us[i], vs[j]);
      onV[k] = onU[k].empty() ? std::vector<Interval>{} : on(vs[j], us[i]);
      overlap[k] = length(intersectIntervals(onU[k], onV[k]));
    }
  });
  for (size_t i = 0; i < us.size(); ++i) {
    for (size_t j = 0; j < vs.size(); ++j) {
      const double o = overlap[i * vs.size() + j];
      if (o <= kOverlapShare * extent) continue;
      e.collisions.push_back({us[i], vs[j]});
      e.worstOverlap = std::max(e.worstOverlap, o);
      failing.insert(us[i]);
      failing.insert(vs[j]);
    }
  }
  std::vector<int> slot(n);  // index into us or vs
  for (size_t i = 0; i < us.size(); ++i) slot[us[i]] = static_cast<int>(i);
  for (size_t j = 0; j < vs.size(); ++j) slot[vs[j]] = static_cast<int>(j);
  for (const ScaffoldHinge& h : input.hinges) {
    const size_t k = slot[h.u] * vs.size() + slot[h.v];
    const double covered =
        length(intersectIntervals(onU[k], {h.w})) + length(intersectIntervals(onV[k], {h.w}));
    e.meets.push_back(covered >= kMeetShare * (h.w.hi - h.w.lo));
  }

  std::vector<HoleLoops> holes(n);
  for (int p = 0; p < n; ++p) holes[p] = holeLoops(outlines[p], ps[p].position);
  for (const int a : us) {
    for (const int b : vs) {
      const int count = interlockCount(holes[a], input.frames.u, holes[b], input.frames.v);
      if (count == 0) continue;
      e.interlocks += count;
      e.interlocked.push_back({a, b});
      failing.insert(a);
      failing.insert(b);
    }
  }

  // The closest stacked pair of one family; coplanar pieces of one slice lie side by side.
  // Holes filled: a patch seen through the other's hole still has its slots beside the
  // other's on a partner crossing both.
  std::vector<Region2d> cover(n);
  parallelFor(static_cast<size_t>(n), [&](size_t p) { cover[p] = outlines[p].withoutHoles(); });
  double closest = HUGE_VAL;
  for (int a = 0; a < n; ++a) {
    for (int b = a + 1; b < n; ++b) {
      const double d = std::fabs(ps[a].position - ps[b].position);
      if (ps[a].family != ps[b].family || d < 1e-9 || d >= closest || !boxesOverlap(boxes[a], boxes[b]))
        continue;
      if (cover[a].intersect(cover[b]).empty()) continue;
      closest = d;
      e.closest = {a, b};
    }
  }
  e.minPatchSpacing = std::isfinite(closest) ? closest : 0;
  e.failing.assign(failing.begin(), failing.end());
  return e;
}

bool tooClose(const Emitted& e, double spacing) {
  // Positions are slice centres in floating point: a hair under the rule is the rule.
  return e.closest.first >= 0 && e.minPatchSpacing < spacing - 1e-6;
}

std::vector<int> patchesToReplace(const Emitted& e, const std::vector<ScaffoldHinge>& hinges,
                                  const std::vector<bool>& searchMeets, const std::vector<char>& replaced) {
  std::set<int> out;
  const auto failing = [&](int k) { return std::binary_search(e.failing.begin(), e.failing.end(), k); };
  for (const int k : e.failing)
    if (!replaced[k]) out.insert(k);
  for (size_t h = 0; h < hinges.size(); ++h) {
    const int u = hinges[h].u, v = hinges[h].v;
    if (!hinges[h].holds || !searchMeets[h] || e.meets[h]) continue;
    if ((failing(u) && !replaced[u]) || (failing(v) && !replaced[v])) continue;
    for (const int k : {u, v})
      if (!replaced[k]) out.insert(k);
  }
  return {out.begin(), out.end()};
}

}  // namespace sliceform
