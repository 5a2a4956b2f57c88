// SPDX-License-Identifier: LGPL-2.1-or-later
#include "quality/quality.hpp"

#include <algorithm>

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

double volumeRatio(const SliceSet& set, const std::vector<Cylinder>& cylinders) {
  double model = 0, swept = 0;
  for (const Slice& s : set.slices) model += s.region.area();
  for (const Cylinder& c : cylinders) swept += c.section.area() * (c.lastSlice - c.firstSlice + 1);
  return swept > 0 ? model / swept : 0;
}

}  // namespace

double iou(const Region2d& a, const Region2d& b) {
  const double united = a.unite(b).area();
  return united > 0 ? a.intersect(b).area() / united : 0;
}

Quality measureQuality(const SliceSet& u, const SliceSet& v, const std::vector<Cylinder>& uCylinders,
                       const std::vector<Cylinder>& vCylinders, const Scaffold& scaffold) {
  Quality q;
  q.silhouetteIouU = iou(sliceUnion(u), patchUnion(scaffold, Family::U, uCylinders));
  q.silhouetteIouV = iou(sliceUnion(v), patchUnion(scaffold, Family::V, vCylinders));

  std::vector<Region2d::Loop> model, lattice;
  for (const Slice& s : u.slices) addStrips(u, v, s.region, s.position, true, model);
  for (const ScaffoldPatch& p : scaffold.patches) {
    const SliceSet& set = p.family == Family::U ? u : v;
    const SliceSet& other = p.family == Family::U ? v : u;
    const auto& cylinders = p.family == Family::U ? uCylinders : vCylinders;
    addStrips(set, other, cylinders[p.cylinder].section, p.position, p.family == Family::U, lattice);
  }
  q.silhouetteIouW =
      iou(Region2d::fromLoops(model, FillRule::NonZero), Region2d::fromLoops(lattice, FillRule::NonZero));
  q.volumeIou = std::min(volumeRatio(u, uCylinders), volumeRatio(v, vCylinders));
  return q;
}

}  // namespace sliceform
