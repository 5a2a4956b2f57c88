// SPDX-License-Identifier: LGPL-2.1-or-later
#include "quality/quality.hpp"

#include <algorithm>
#include <map>

#include "support/parallel.hpp"
#include "support/per_family.hpp"

namespace sliceform {
namespace {

Region2d sliceUnion(const SliceSet& set) {
  std::vector<Region2d> all;
  for (const Slice& s : set.slices) all.push_back(s.region);
  return Region2d::uniteAll(all);
}

Region2d patchUnion(const Scaffold& s, Family f, const std::vector<Cylinder>& cylinders) {
  std::vector<Region2d> all;
  for (const ScaffoldPatch& p : s.patches)
    if (p.family == f) all.push_back(cylinders[p.cylinder].section);
  return Region2d::uniteAll(all);
}

// Strips in the (U, V) plane, expressed as (u, v): for a U slice at u, its material's
// v-extent, from u - ds/2 to u + ds/2. For a V slice, the mirror.
void addStrips(const SliceSet& set, const SliceSet& other, const Region2d& region, double position, bool isU,
               std::vector<Region2d::Loop>& out) {
  const double half = 0.5 * set.interval;
  const Box2 b = region.bounds();
  if (b.empty) return;
  // The frame's x axis is ±(other family's normal): map x back to the other coordinate.
  const double sign = dot(set.frame.xAxis, other.frame.normal) >= 0 ? 1 : -1;
  const double lo = std::min(sign * b.min.x, sign * b.max.x), hi = std::max(sign * b.min.x, sign * b.max.x);
  if (isU)
    out.push_back(
        {{position - half, lo}, {position + half, lo}, {position + half, hi}, {position - half, hi}});
  else
    out.push_back(
        {{lo, position - half}, {hi, position - half}, {hi, position + half}, {lo, position + half}});
}

// Volume IoU of one family: each slice stands for one interval of the model, so the volumes
// are sums over slices of the slice's material (S) against the union of the cylinders that
// span it (C). C does not always contain S: a small branch that Reeb simplification
// absorbed lives on only in its neighbour's end patch, and its own slices lie in no
// cylinder; the ratio of the total volumes, which assumed containment, then exceeded 1.
double volumeIou(const SliceSet& set, const std::vector<Cylinder>& cylinders) {
  const size_t n = set.slices.size();
  std::vector<std::vector<int>> spanning(n);
  for (size_t c = 0; c < cylinders.size(); ++c)
    for (int k = std::max(cylinders[c].firstSlice, 0); k <= cylinders[c].lastSlice && k < static_cast<int>(n);
         ++k)
      spanning[k].push_back(static_cast<int>(c));
  // Slices spanned by the same cylinders (most of a run) share their union: made once
  // (occ/Motor-c.brep: 2.5 % of its CPU, most in the direction search's estimates).
  std::map<std::vector<int>, size_t> setIndex;
  std::vector<size_t> setOf(n);
  std::vector<const std::vector<int>*> sets;
  for (size_t k = 0; k < n; ++k) {
    const auto [at, added] = setIndex.emplace(spanning[k], sets.size());
    if (added) sets.push_back(&at->first);
    setOf[k] = at->second;
  }
  std::vector<Region2d> unions(sets.size());
  parallelFor(sets.size(), [&](size_t i) {
    std::vector<Region2d> sections;
    for (const int c : *sets[i]) sections.push_back(cylinders[c].section);
    unions[i] = Region2d::uniteAll(sections);
  });
  std::vector<double> common(n), united(n);
  parallelFor(n, [&](size_t k) {
    const Region2d& s = set.slices[k].region;
    const Region2d& c = unions[setOf[k]];
    common[k] = s.intersect(c).area();
    united[k] = s.area() + c.area() - common[k];
  });
  double both = 0, either = 0;
  for (size_t k = 0; k < n; ++k) both += common[k], either += united[k];
  return either > 0 ? both / either : 0;
}

}  // namespace

double iou(const Region2d& a, const Region2d& b) {
  const double united = a.unite(b).area();
  return united > 0 ? a.intersect(b).area() / united : 0;
}

QualityBase qualityBase(const SliceSet& u, const SliceSet& v, const std::vector<Cylinder>& uCylinders,
                        const std::vector<Cylinder>& vCylinders) {
  QualityBase b;
  b.uSlices = sliceUnion(u);
  b.vSlices = sliceUnion(v);
  std::vector<Region2d::Loop> model;
  for (const Slice& s : u.slices) addStrips(u, v, s.region, s.position, true, model);
  b.footprint = Region2d::fromLoops(model, FillRule::NonZero);
  b.volumeIou = std::min(volumeIou(u, uCylinders), volumeIou(v, vCylinders));
  return b;
}

Quality measureQuality(const QualityBase& base, const SliceSet& u, const SliceSet& v,
                       const std::vector<Cylinder>& uCylinders, const std::vector<Cylinder>& vCylinders,
                       const Scaffold& scaffold) {
  Quality q;
  q.silhouetteIouU = iou(base.uSlices, patchUnion(scaffold, Family::U, uCylinders));
  q.silhouetteIouV = iou(base.vSlices, patchUnion(scaffold, Family::V, vCylinders));

  std::vector<Region2d::Loop> lattice;
  const PerFamily<const SliceSet&> sets{u, v};
  const PerFamily<const std::vector<Cylinder>&> cylinders{uCylinders, vCylinders};
  for (const ScaffoldPatch& p : scaffold.patches)
    addStrips(sets[p.family], sets[other(p.family)], cylinders[p.family][p.cylinder].section, p.position,
              p.family == Family::U, lattice);
  q.silhouetteIouW = iou(base.footprint, Region2d::fromLoops(lattice, FillRule::NonZero));
  q.volumeIou = base.volumeIou;
  return q;
}

}  // namespace sliceform
