// SPDX-License-Identifier: LGPL-2.1-or-later
// Partner ids at the slots. Every slot should get its partner's id, and whoever assembles
// must read it as that slot's: so a label goes beside its slot (across or turned along
// it) or on the slot's own hinge line beyond it, never across another hinge's line, and
// never beside another slot unless nearer its own. Where slots crowd, sizes shrink to the
// legible minimum and the packing is tried again in another order.
#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>

#include "layout/label_room.hpp"
#include "layout/labels.hpp"

namespace sliceform {
namespace {

constexpr double kMaxPartnerHeight = 3.5;  // mm: a partner id is a note beside its slot

// Where a partner label may go, in the order tried: beside the slot reading across it (as
// the patch id reads), beside it turned to read along it (a box as wide as the text is
// high fits between slots closer than the text is long), or on the hinge line itself
// beyond the slot's root, turned along it: there the paper is whole where slots crowd.
enum class Way { Across, Along, OnLine };

// Cap heights a label tries, largest first: the patch's own scale down by fifths, then the
// legible minimum.
std::vector<double> heightsFrom(double maxHeight) {
  std::vector<double> heights;
  for (double h = std::min(maxHeight, kMaxPartnerHeight); h > kMinLabelHeight + 1e-9; h *= 0.8)
    heights.push_back(h);
  heights.push_back(kMinLabelHeight);
  return heights;
}

bool otherLine(const LabelSpot& o, const LabelSpot& s) {
  return std::abs(o.x - s.x) >= 1e-6;
}

// The other hinges' segments reaching `y`: where their partners stand once assembled. A
// label never lies across one, beyond its slot either: it would read as that hinge's.
std::vector<Box2> otherHinges(const std::vector<LabelSpot>& spots, const LabelSpot& s, Interval y) {
  std::vector<Box2> lines;
  for (const LabelSpot& o : spots)
    if (otherLine(o, s) && o.w.hi >= y.lo && o.w.lo <= y.hi)
      lines.push_back({{o.x, o.w.lo}, {o.x, o.w.hi}, false});
  return lines;
}

// A label between two slots reads as the nearer one's. Beside its own slot (its box
// reaching the slot's stretch of the line) it must be nearer its own line than any other
// slot beside it; beyond its slot, nearer its own line than any other hinge's there.
bool readsAsOwn(const std::vector<LabelSpot>& spots, const LabelSpot& s, Vec2 c, Vec2 half) {
  const auto beside = [&](const Interval& y) { return y.lo < c.y + half.y && y.hi > c.y - half.y; };
  const bool besideOwnSlot = beside(s.slot);
  for (const LabelSpot& o : spots)
    if (otherLine(o, s) && beside(besideOwnSlot ? o.slot : o.w) && std::abs(c.x - o.x) <= std::abs(c.x - s.x))
      return false;
  return true;
}

// How far the nearest other hinge line is, along the spot's hinge.
double pitchAt(const std::vector<LabelSpot>& spots, const LabelSpot& s) {
  double d = HUGE_VAL;
  for (const LabelSpot& o : spots)
    if (otherLine(o, s) && o.w.hi >= s.w.lo && o.w.lo <= s.w.hi) d = std::min(d, std::abs(o.x - s.x));
  return d;
}

// The stretch of x nearer the line of `s` than any other line whose hinge reaches `y`.
Interval nearerOwn(const std::vector<LabelSpot>& spots, const LabelSpot& s, Interval y) {
  Interval x{-HUGE_VAL, HUGE_VAL};
  for (const LabelSpot& o : spots) {
    if (!otherLine(o, s) || o.w.lo >= y.hi || o.w.hi <= y.lo) continue;
    const double mid = (o.x + s.x) / 2;
    if (o.x > s.x)
      x.hi = std::min(x.hi, mid - 1e-3);
    else
      x.lo = std::max(x.lo, mid + 1e-3);
  }
  return x;
}

// Where the centre of `s`'s label set `way` at cap height `height` is sought: x in [lo, hi]
// and y in `y`; `side` is how far beside the slot's line the nearest centre lies.
struct Window {
  double lo, hi, side;
  Interval y;
};
Window windowOf(const LabelSpot& s, Way way, double height) {
  const Vec2 half = halfSize(s.text, height, way != Way::Across);
  const double reach = half.y + 2 * height;
  if (way == Way::OnLine)  // on the line, to Clipper's micrometre
    return {s.x - 1e-3, s.x + 1e-3, 0, {s.w.lo - reach - 2 * half.y, s.w.hi + reach + 2 * half.y}};
  const double side = s.slotWidth / 2 + kGap + half.x;
  return {s.x - side - half.x - kGap, s.x + side + half.x + kGap, side, {s.w.lo - reach, s.w.hi + reach}};
}

// The label of `s` set `way` at cap height `height` where its box has room nearest the
// slot's middle and reads as this slot's; none when there is none. Beside the slot the box
// reaches the hinge's stretch, or comes within two cap heights of its ends (a short hinge
// has little paper beside it); on the line it may lie two label lengths beyond them.
std::optional<Label> placeAt(const BoxRoom& inner, const std::vector<Label>& taken,
                             const std::vector<LabelSpot>& spots, const LabelSpot& s, Way way,
                             double height) {
  const bool vertical = way != Way::Across;
  const Vec2 half = halfSize(s.text, height, vertical);
  // Plain copies, not a structured binding: the lambda below captures them (C++17).
  const Window w = windowOf(s, way, height);
  double lo = w.lo, hi = w.hi;
  const double side = w.side;
  const Interval y = w.y;
  const std::vector<Box2> lines = otherHinges(spots, s, {y.lo - half.y, y.hi + half.y});
  // The room between `lo` and `hi` nearest either side of the slot, the nearer first, if
  // it reads as this slot's (on its line a label continues its slot).
  bool none = false;
  const auto nearest = [&]() -> std::optional<Label> {
    if (lo >= hi) return std::nullopt;
    const Region2d room = freeFor(inner, taken, half, {{lo, y.lo}, {hi, y.hi}, false}, lines);
    if ((none = room.empty())) return std::nullopt;
    Vec2 at[] = {nearestPoint(room, {s.x + side, s.y}), nearestPoint(room, {s.x - side, s.y})};
    if (std::hypot(at[1].x - s.x + side, at[1].y - s.y) <
        std::hypot(at[0].x - s.x - side, at[0].y - s.y) - 1e-9)
      std::swap(at[0], at[1]);
    for (const Vec2& c : at)
      if (way == Way::OnLine || readsAsOwn(spots, s, c, half)) return setLabel(s.text, c, height, vertical);
    return std::nullopt;
  };
  if (std::optional<Label> label = nearest(); label || none || way == Way::OnLine) return label;
  // The nearest room may read as a neighbour's where nearer room, further along, would not:
  // then the room nearer this line than any other hinge's along the window.
  const Interval own = nearerOwn(spots, s, {y.lo - half.y, y.hi + half.y});
  lo = std::max(lo, own.lo), hi = std::min(hi, own.hi);
  return nearest();
}

// The label of `s` clear of `taken`: the first way it fits, at the largest size that fits
// that way; none when it has no room.
std::optional<Label> partnerLabel(const BoxRoom& inner, const std::vector<LabelSpot>& spots,
                                  const LabelSpot& s, const std::vector<Label>& taken, double maxHeight) {
  // Where the next line is nearer than the text is long at the smallest size, a label
  // across lies over a neighbour's line, where that neighbour's label would stand turned:
  // there labels turn first.
  const double pitch = pitchAt(spots, s);
  static constexpr Way kAcrossFirst[] = {Way::Across, Way::Along, Way::OnLine};
  static constexpr Way kTurnedFirst[] = {Way::Along, Way::OnLine, Way::Across};
  for (const Way way : pitch < labelWidth(s.text, kMinLabelHeight) ? kTurnedFirst : kAcrossFirst) {
    // Turned labels side by side along close slots: no higher than the slots are apart,
    // less the gap, or the first one set pushes its neighbours' off.
    const std::vector<double> heights =
        heightsFrom(way == Way::Across ? maxHeight : std::min(maxHeight, pitch - kGap));
    const auto at = [&](double height) { return placeAt(inner, taken, spots, s, way, height); };
    // Most labels fit at the first size; where the smallest does not fit this way no other
    // does (a bigger box only loses room), so two tries rule a way out.
    if (std::optional<Label> label = at(heights.front())) return label;
    if (heights.size() == 1) continue;
    const std::optional<Label> smallest = at(heights.back());
    if (!smallest) continue;
    for (size_t h = 1; h + 1 < heights.size(); ++h)
      if (std::optional<Label> label = at(heights[h])) return label;
    return smallest;
  }
  return std::nullopt;
}

// The labels of `spots` set in `order`, each clear of those before it and of `taken`.
std::vector<std::optional<Label>> partnerLabels(const BoxRoom& inner, const std::vector<LabelSpot>& spots,
                                                const std::vector<size_t>& order,
                                                const std::vector<Label>& taken, double maxHeight) {
  std::vector<std::optional<Label>> labels(spots.size());
  std::vector<Label> all = taken;
  for (const size_t i : order) {
    labels[i] = partnerLabel(inner, spots, spots[i], all, maxHeight);
    if (labels[i]) all.push_back(*labels[i]);
  }
  return labels;
}

// The labels set, in spot order; `missing` counts the spots without one.
std::vector<Label> present(const std::vector<std::optional<Label>>& labels, int& missing) {
  std::vector<Label> out;
  for (const std::optional<Label>& l : labels) {
    if (l)
      out.push_back(*l);
    else
      ++missing;
  }
  return out;
}

// Whether `label` lies within `r` of the hinge of a spot in `order` left without a label.
bool nearMissing(const std::vector<LabelSpot>& spots, const std::vector<size_t>& order,
                 const std::vector<std::optional<Label>>& labels, const Label& label, double r) {
  const Vec2 h = halfSize(label.text, label.height, label.vertical), c = label.at;
  for (const size_t j : order) {
    const LabelSpot& m = spots[j];
    if (!labels[j] && c.x + h.x > m.x - r && c.x - h.x < m.x + r && c.y + h.y > m.w.lo - r &&
        c.y - h.y < m.w.hi + r)
      return true;
  }
  return false;
}

std::vector<size_t> inOrder(size_t n) {
  std::vector<size_t> order(n);
  for (size_t i = 0; i < n; ++i) order[i] = i;
  return order;
}

// Whether a kMinLabelHeight box has room over `paper`, clear of `taken`, with its centre in
// the windows of every way, across and then turned, at cap height `windowHeight` (placeAt's
// own windows, which only grow with the height), no other hinge's line kept off.
bool boxMayFit(const BoxRoom& paper, const LabelSpot& s, const std::vector<Label>& taken,
               double windowHeight) {
  for (const bool vertical : {false, true}) {
    Box2 window{{HUGE_VAL, HUGE_VAL}, {-HUGE_VAL, -HUGE_VAL}, false};
    for (const Way way : {Way::Across, Way::Along, Way::OnLine}) {
      if ((way != Way::Across) != vertical) continue;
      const Window w = windowOf(s, way, windowHeight);
      window.min = {std::min(window.min.x, w.lo), std::min(window.min.y, w.y.lo)};
      window.max = {std::max(window.max.x, w.hi), std::max(window.max.y, w.y.hi)};
    }
    if (!freeFor(paper, taken, halfSize(s.text, kMinLabelHeight, vertical), window).empty()) return true;
  }
  return false;
}

}  // namespace

bool besideMayFit(const BoxRoom& paper, const LabelSpot& s, const std::vector<Label>& taken) {
  return boxMayFit(paper, s, taken, kMinLabelHeight);
}

// A label set at a cap height h from 1 mm to kMaxPartnerHeight has its centre in the windows
// of its way at h, which lie inside those at kMaxPartnerHeight, and a 1 mm box at that
// centre lies within its box: so that small box has room on the leaders' paper (the inner
// paper less eroded), nothing else on it. Leaders' labels are what leaderMayFit asks.
bool mayEverFit(const LabelPaper& paper, const LabelSpot& s) {
  const BoxRoom& leaderRoom = leaderPaper(paper);
  return boxMayFit(leaderRoom, s, {}, kMaxPartnerHeight) || leaderMayFit(paper.inner, leaderRoom, s, {});
}

std::vector<Label> placePartners(const LabelPaper& paper, const std::vector<LabelSpot>& spots,
                                 const std::vector<Label>& taken, double maxHeight, int& missing) {
  return present(partnerLabels(paper.inner, spots, inOrder(spots.size()), taken, maxHeight), missing);
}

namespace {

// A patch's labels with its id at most `nameHeight` high; `left`, when given, gets the spots
// left without one. A try that must leave fewer than `toBeat` slots without a label to be
// kept stops where it surely cannot, before its leaders.
PatchLabels labelPartners(const LabelPaper& paper, const std::string& id, const std::vector<LabelSpot>& spots,
                          double nameHeight, int toBeat, std::vector<size_t>* left = nullptr) {
  PatchLabels out;
  out.name = placeName(paper, id, {}, nameHeight);
  // Partner ids scale with the patch id, which says how much room the patch has.
  const double height = std::max(out.name.height * 0.6, kMinLabelHeight);
  std::vector<size_t> order = inOrder(spots.size());
  std::vector<std::optional<Label>> partners = partnerLabels(paper.inner, spots, order, {out.name}, height);
  out.partners = present(partners, out.missing);
  std::vector<std::optional<Label>> best = partners;  // out's partners, in spot order
  const auto noteLeft = [&] {
    if (!left) return;
    left->clear();
    for (size_t i = 0; i < spots.size(); ++i)
      if (!best[i]) left->push_back(i);
  };
  // A slot left without a label that has no room even on the bare patch has none whatever
  // the order: it is left out of the tries below.
  int hopeless = 0;
  order.erase(std::remove_if(order.begin(), order.end(),
                             [&](size_t i) {
                               const bool none =
                                   !partners[i] && !partnerLabel(paper.inner, spots, spots[i], {}, height);
                               hopeless += none;
                               return none;
                             }),
              order.end());
  // Where a slot is left without, first come, first served gave its room away. So again
  // around it: the labels within a label's length of its hinge are lifted and set again,
  // the slots left out first (they have least room), with the patch id last (set first at
  // the deepest spot, it may sit where slots' labels need to be; it finds room after);
  // twice, then at the smallest size (small labels pack closer). The try that labels most
  // slots stands.
  for (int attempt = 0; attempt < 3 && out.missing > hopeless; ++attempt) {
    std::stable_partition(order.begin(), order.end(), [&](size_t i) { return !partners[i]; });
    std::vector<size_t> again;
    std::vector<Label> kept;
    for (const size_t i : order) {
      if (!partners[i] ||
          nearMissing(spots, order, partners, *partners[i], labelWidth(spots[i].text, height)))
        again.push_back(i);
      else
        kept.push_back(*partners[i]);
    }
    const std::vector<std::optional<Label>> set =
        partnerLabels(paper.inner, spots, again, kept, attempt == 2 ? kMinLabelHeight : height);
    for (const size_t i : again) partners[i] = set[i];
    PatchLabels next;
    next.partners = present(partners, next.missing);
    if (next.missing >= out.missing) continue;
    next.name = placeName(paper, id, next.partners, nameHeight);
    if (next.name.height > 0) out = std::move(next), best = partners;  // the patch id comes first
  }
  if (out.missing == 0) {
    noteLeft();
    return out;
  }
  // What is left gets a label that stands off with a leader to its slot, set last so that
  // every label that reads as its slot's on its own keeps its room.
  const BoxRoom& leaderRoom = leaderPaper(paper);
  std::vector<Label> taken = out.partners;
  taken.push_back(out.name);
  // Only the slots with room for a leader's label or a last-resort one, now, can be labelled
  // below: labels set meanwhile only take room away. A retry that cannot then beat the try
  // before it ends here, the leaders (the costly part) not sought: of MODERN_Cooker_1's 166
  // retries (of 228 tries), 30 labelled more slots and 96 end here.
  if (int mayFit = 0, spare = out.missing - toBeat; spare >= 0) {
    for (size_t i = 0; i < spots.size() && mayFit <= spare; ++i)
      if (!best[i] && (besideMayFit(leaderRoom, spots[i], taken) ||
                       leaderMayFit(paper.inner, leaderRoom, spots[i], taken)))
        ++mayFit;
    if (mayFit <= spare) {
      noteLeft();
      return out;
    }
  }
  std::vector<double> sizes{std::min(height, kMaxPartnerHeight)};
  if (sizes.front() > kMinLabelHeight) sizes.push_back(kMinLabelHeight);
  for (size_t i = 0; i < spots.size(); ++i) {
    if (best[i]) continue;
    best[i] = leaderLabel(paper.inner, leaderRoom, spots[i], taken, sizes);
    if (best[i]) taken.push_back(*best[i]);
  }
  // Last, a 1 mm label beside its slot whose box keeps only the leaders' margin off the
  // cuts: in a finger 1.6 to 2.2 mm wide whose room lies beyond a leader's reach.
  for (size_t i = 0; i < spots.size(); ++i) {
    if (best[i]) continue;
    best[i] = partnerLabel(leaderRoom, spots, spots[i], taken, kMinLabelHeight);
    if (best[i]) taken.push_back(*best[i]);
  }
  out.missing = 0;
  out.partners = present(best, out.missing);
  noteLeft();
  return out;
}

}  // namespace

PatchLabels labelPatch(const LabelPaper& paper, const std::string& id, const std::vector<LabelSpot>& spots,
                       int step) {
  std::vector<size_t> left;
  PatchLabels out =
      labelPartners(paper, id, spots, nameHeights().front(), std::numeric_limits<int>::max(), &left);
  // A small patch whose id, set large at its deepest spot, took the room its slots' labels
  // need: the id (and with it the partner ids) a size smaller, up to three sizes, while that
  // labels more slots. A slot with no room for any label on the bare patch is left without
  // by every try, so it is among those the first left: once no more are left than such
  // slots, no smaller id labels more (MODERN_Cooker_1: 4 of the 59 patches with slots left,
  // whose 12 smaller tries took 90 ms). They are counted only as far as that question needs.
  size_t counted = 0;
  int never = 0;  // of left[0, counted)
  const auto onlyNeverLeft = [&] {
    while (never < out.missing && left.size() - counted >= static_cast<size_t>(out.missing - never))
      never += !mayEverFit(paper, spots[left[counted++]]);
    return never >= out.missing;
  };
  const std::vector<double>& sizes = nameHeights();
  auto smaller = std::upper_bound(sizes.begin(), sizes.end(), out.name.height, std::greater<double>());
  for (int tries = 0; tries < 3 && smaller != sizes.end() && !onlyNeverLeft(); ++tries, ++smaller) {
    PatchLabels next = labelPartners(paper, id, spots, *smaller, out.missing);
    if (next.missing < out.missing && next.name.height > 0) out = std::move(next);
  }
  if (step > 0) out.step = placeStep(paper, "#" + std::to_string(step), out.name, out.partners);
  return out;
}

}  // namespace sliceform
