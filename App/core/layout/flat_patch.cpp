// SPDX-License-Identifier: LGPL-2.1-or-later
#include "layout/flat_patch.hpp"

#include <algorithm>
#include <cmath>
#include <set>

#include "layout/cut_paths.hpp"
#include "layout/labels.hpp"
#include "support/per_family.hpp"

namespace sliceform {
namespace {

constexpr double kTwoPi = 2 * M_PI;

// The partner of every hinge of `patch` that is still a hinge once slotted.
std::vector<LabelSpot> partnerSpots(const LayoutInput& d, int patch) {
  const Arrangement& a = d.arrangement;
  const Realization& r = d.realization;
  const Family family = a.scaffold.patches[patch].family;
  const SliceFrame& f = a.slices(family).frame;
  const SliceFrame& g = a.slices(other(family)).frame;
  std::vector<LabelSpot> spots;
  for (size_t h = 0; h < a.scaffold.hinges.size(); ++h) {
    const ScaffoldHinge& hinge = a.scaffold.hinges[h];
    if (hinge.patch(family) != patch || !d.meets[h]) continue;
    const int partner = hinge.patch(other(family));
    const Slot slot = familySlot(family, r.slots[h]);
    const Interval& at = hinge.holds ? hinge.grip : hinge.w;
    const double root = (at.lo + at.hi) / 2;
    // The slot's stretch of the hinge: above the root for an up slot, below for down; its
    // label beside the middle of that.
    const Interval cut = slot == Slot::Up        ? Interval{root, hinge.w.hi}
                         : slot == Slot::Down    ? Interval{hinge.w.lo, root}
                         : slot == Slot::Through ? hinge.w
                                                 : Interval{root, root};
    const double y = slot == Slot::Through ? root : (cut.lo + cut.hi) / 2;
    spots.push_back({patchId(a.scaffold, partner), lineX(f, g, a.scaffold.patches[partner].position), hinge.w,
                     y, r.params.width(), cut});
  }
  return spots;
}

}  // namespace

double sweepOf(const CutElement& e) {
  return std::fmod((e.ccw ? e.end - e.start : e.start - e.end) + 2 * kTwoPi, kTwoPi);
}

Vec2 pointAt(const CutElement& e, double t) {
  switch (e.kind) {
    case CutElement::Kind::Line:
      return {e.a.x + t * (e.b.x - e.a.x), e.a.y + t * (e.b.y - e.a.y)};
    case CutElement::Kind::Circle: {
      const double angle = t * kTwoPi;
      return {e.centre.x + e.radius * std::cos(angle), e.centre.y + e.radius * std::sin(angle)};
    }
    case CutElement::Kind::Arc: {
      const double angle = e.start + (e.ccw ? 1 : -1) * t * sweepOf(e);
      return {e.centre.x + e.radius * std::cos(angle), e.centre.y + e.radius * std::sin(angle)};
    }
  }
  return e.a;
}

std::vector<Vec2> sample(const CutElement& e, double deflection) {
  if (e.kind == CutElement::Kind::Line) return {e.a};
  // Chord error r (1 - cos(step / 2)) <= deflection.
  const double step = 2 * std::acos(std::max(-1.0, 1 - deflection / std::max(e.radius, 1e-9)));
  const double sweep = e.kind == CutElement::Kind::Arc ? sweepOf(e) : kTwoPi;
  const int n = std::max(2, static_cast<int>(std::ceil(sweep / step)));
  std::vector<Vec2> points;
  for (int i = 0; i < n; ++i) points.push_back(pointAt(e, static_cast<double>(i) / n));
  return points;
}

FlatPatch flattenPatch(const LayoutInput& d, int k) {
  const Arrangement& a = d.arrangement;
  FlatPatch flat;
  flat.patch = k;
  flat.id = patchId(a.scaffold, k);
  flat.family = a.scaffold.patches[k].family;
  flat.outline = d.patches[k].outline;
  flat.cut = cutPaths(d, k);
  const LabelPaper paper = labelPaper(flat.outline);
  const std::vector<int>& order = d.realization.assemblyOrder;
  const auto at = std::find(order.begin(), order.end(), k);
  flat.step = at == order.end() ? 0 : static_cast<int>(at - order.begin()) + 1;
  const std::vector<LabelSpot> spots = partnerSpots(d, k);
  PatchLabels labels = labelPatch(paper, flat.id, spots, flat.step);
  flat.name = std::move(labels.name);
  flat.stepLabel = std::move(labels.step);
  flat.partners = std::move(labels.partners);
  // The slots left without, by their partner's id, so the user knows where to write one.
  std::multiset<std::string> labelled;
  for (const Label& l : flat.partners) labelled.insert(l.text);
  for (const LabelSpot& s : spots) {
    const auto found = labelled.find(s.text);
    if (found == labelled.end())
      flat.unlabelled.push_back({s.text, {s.x, s.y}});
    else
      labelled.erase(found);
  }
  for (const Label& l : flat.partners) flat.partnersOnLeaders += !l.leader.empty();
  return flat;
}

}  // namespace sliceform
