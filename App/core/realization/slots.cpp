// SPDX-License-Identifier: LGPL-2.1-or-later
#include "realization/slots.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "support/error.hpp"

namespace sliceform {
namespace {

constexpr double kSameLine = 1e-6;  // mm: hinges closer than this share a line
constexpr double kOvershoot = 1.0;  // mm an open slot runs past the boundary it leaves by
constexpr double kPi = 3.14159265358979323846;

// The material interval of `intervals` containing y, or the nearest one.
Interval containing(const std::vector<Interval>& intervals, double y) {
  Interval best{y, y};
  double bestGap = std::numeric_limits<double>::infinity();
  for (const Interval& i : intervals) {
    const double gap = y < i.lo ? i.lo - y : (y > i.hi ? y - i.hi : 0);
    if (gap < bestGap) bestGap = gap, best = i;
  }
  return best;
}

// How far an open end at `end` (going in direction dir = +1 up, -1 down) must run so that the
// whole strip leaves the paper: the strip's side lines may meet paper that reaches further
// than the centre line does (a slot at the bottom of a valley). Never into paper beyond a gap.
double openEnd(const VerticalLines& shape, double x, double halfWidth, double end, int dir) {
  double reach = end, wall = std::numeric_limits<double>::infinity();
  for (const double xs : {x - halfWidth, x, x + halfWidth}) {
    const double inside = end - dir * 1e-3;
    for (const Interval& i : shape.at(xs)) {
      if (inside >= i.lo && inside <= i.hi) reach = dir > 0 ? std::max(reach, i.hi) : std::min(reach, i.lo);
      const double start = dir > 0 ? i.lo : -i.hi;  // paper met going outwards
      if (start > dir * end + 1e-9) wall = std::min(wall, start - dir * end);
    }
  }
  const double run = std::min(std::fabs(reach - end) + kOvershoot, wall / 2);
  return end + dir * run;
}

Region2d::Loop disc(double cx, double cy, double r) {
  Region2d::Loop out;
  const int n = 48;
  for (int k = 0; k < n; ++k) {
    const double t = 2 * kPi * k / n;
    out.push_back({cx + r * std::cos(t), cy + r * std::sin(t)});
  }
  return out;
}

}  // namespace

void checkSlotParams(const SlotParams& p) {
  if (!(p.thickness > 0 && p.thickness < 100) || !(p.clearance >= 0 && p.clearance < 100) ||
      !(p.kerf >= 0 && p.kerf < p.width()))
    throw Error(ErrorKind::BadParameter,
                "the thickness must be > 0, the clearance and kerf >= 0 (all below 100 mm), and the kerf "
                "narrower than the slot (thickness + clearance)");
}

const char* slotName(Slot slot) {
  switch (slot) {
    case Slot::Up:
      return "up";
    case Slot::Down:
      return "down";
    case Slot::Through:
      return "through";
    case Slot::None:
      return "none";
  }
  return "none";
}

Slot uSlot(SlotPair pair) {
  switch (pair) {
    case SlotPair::UpDown:
      return Slot::Up;
    case SlotPair::DownUp:
      return Slot::Down;
    case SlotPair::ThroughNone:
      return Slot::Through;
    case SlotPair::NoneThrough:
      return Slot::None;
  }
  return Slot::None;
}

Slot vSlot(SlotPair pair) {
  switch (pair) {
    case SlotPair::UpDown:
      return Slot::Down;
    case SlotPair::DownUp:
      return Slot::Up;
    case SlotPair::ThroughNone:
      return Slot::None;
    case SlotPair::NoneThrough:
      return Slot::Through;
  }
  return Slot::None;
}

Slot familySlot(Family f, SlotPair pair) {
  return f == Family::U ? uSlot(pair) : vSlot(pair);
}

VerticalLines::VerticalLines(const Region2d& shape, const std::vector<double>& xs) : shape_(&shape) {
  const std::vector<std::vector<Interval>> on = shape.intervalsOnVerticalLines(xs);
  for (size_t k = 0; k < xs.size(); ++k) lines_.emplace(xs[k], on[k]);
}

std::vector<Interval> VerticalLines::at(double x) const {
  const auto it = lines_.find(x);
  return it != lines_.end() ? it->second : shape_->intervalsOnLine({x, 0}, {0, 1});
}

std::vector<double> VerticalLines::slotLines(const std::vector<PatchHinge>& hinges,
                                             const SlotParams& params) {
  std::vector<double> xs;
  const double halfWidth = params.width() / 2;
  for (const PatchHinge& h : hinges) xs.insert(xs.end(), {h.x - halfWidth, h.x, h.x + halfWidth});
  return xs;
}

std::vector<SlotCut> planSlots(const Region2d& shape, const std::vector<PatchHinge>& hinges,
                               const SlotParams& params) {
  return planSlots(VerticalLines(shape, {}), hinges, params);
}

std::vector<SlotCut> planSlots(const VerticalLines& shape, const std::vector<PatchHinge>& hinges,
                               const SlotParams& params) {
  std::vector<SlotCut> cuts;
  const double halfWidth = params.width() / 2;
  for (const PatchHinge& h : hinges) {
    if (h.slot == Slot::None) continue;
    const Interval paper = containing(shape.at(h.x), (h.w.lo + h.w.hi) / 2);
    // Neighbours on the same line and the same stretch of paper bound the cut.
    double above = paper.hi, below = paper.lo;  // for through: segment ends of neighbours
    double rootAbove = paper.hi, rootBelow = paper.lo;
    bool closedAbove = false, closedBelow = false, throughAbove = false, throughBelow = false;
    for (const PatchHinge& o : hinges) {
      if (&o == &h || std::fabs(o.x - h.x) > kSameLine) continue;
      if (o.w.lo >= h.w.hi - 1e-9 && o.w.lo < paper.hi) {
        if (o.root < rootAbove) rootAbove = o.root, closedAbove = true;
        if (o.w.lo < above) above = o.w.lo, throughAbove = true;
      }
      if (o.w.hi <= h.w.lo + 1e-9 && o.w.hi > paper.lo) {
        if (o.root > rootBelow) rootBelow = o.root, closedBelow = true;
        if (o.w.hi > below) below = o.w.hi, throughBelow = true;
      }
    }
    SlotCut cut{h.x, {h.root, h.root}, false, false};
    if (h.slot == Slot::Up) {
      cut.y.hi = closedAbove ? rootAbove + kRootGap : rootAbove;
      cut.openHi = !closedAbove;
    } else if (h.slot == Slot::Down) {
      cut.y.lo = closedBelow ? rootBelow - kRootGap : rootBelow;
      cut.openLo = !closedBelow;
    } else {
      cut.y = {below, above};
      cut.openLo = !throughBelow;
      cut.openHi = !throughAbove;
    }
    if (cut.openHi) cut.y.hi = openEnd(shape, h.x, halfWidth, cut.y.hi, +1);
    if (cut.openLo) cut.y.lo = openEnd(shape, h.x, halfWidth, cut.y.lo, -1);
    // An up or down slot starts kRootGap past its root: the partner's slot ends on the
    // root too, and two slot ends on one point make the interlock test read that point as
    // inside the other's hole or not by rounding alone (the independent checker read 5
    // interlocks on a Menger sponge that has none). The two papers overlap by 2 µm there,
    // which paper of any thickness does. An end bound by a neighbour's root goes kRootGap
    // past it, so it still meets the patch's own slot there, which starts past that root.
    if (h.slot == Slot::Up) cut.y.lo += kRootGap;
    if (h.slot == Slot::Down) cut.y.hi -= kRootGap;
    if (cut.y.hi > cut.y.lo) cuts.push_back(cut);
  }
  return cuts;
}

SlotShapes slotShapes(const std::vector<SlotCut>& cuts, const SlotParams& params) {
  SlotShapes out;
  const double r = params.width() / 2;
  const bool round = params.end == SlotEnd::Round;
  for (const SlotCut& c : cuts) {
    double lo = c.y.lo, hi = c.y.hi;
    if (round && !c.openLo && hi - lo > 2 * r) {
      lo += r;
      out.discs.push_back({{c.x, lo}, r});
    }
    if (round && !c.openHi && hi - lo > 2 * r) {
      hi -= r;
      out.discs.push_back({{c.x, hi}, r});
    }
    out.rectangles.push_back({{c.x - r, lo}, {c.x + r, hi}, false});
  }
  return out;
}

namespace {

std::vector<Region2d::Loop> slotLoops(const std::vector<SlotCut>& cuts, const SlotParams& params) {
  const SlotShapes shapes = slotShapes(cuts, params);
  std::vector<Region2d::Loop> loops;
  for (const Box2& b : shapes.rectangles)
    loops.push_back(Region2d::rectangle(b.min.x, b.min.y, b.max.x, b.max.y));
  for (const Disc& d : shapes.discs) loops.push_back(disc(d.centre.x, d.centre.y, d.radius));
  return loops;
}

}  // namespace

Region2d slotRegion(const std::vector<SlotCut>& cuts, const SlotParams& params) {
  return Region2d::fromLoops(slotLoops(cuts, params), FillRule::NonZero);
}

Region2d slotStrips(const std::vector<SlotCut>& cuts, const SlotParams& params) {
  return Region2d::overlaidLoops(slotLoops(cuts, params));
}

// A bridge of paper narrower than the neck is no bridge: a slot wall that grazes a hole
// leaves 0.3 mm on the polygons, and nothing at all on the exact faces (occ/Ball.brep):
// the polygons may stray `tolerance` from the true shape. The slotted region's opened
// pieces are counted against the shape's own, counted once here.
double slotCrumb(const SlotParams& params) {
  return std::max(0.5, params.width() * params.width());
}

double slotNeck(const SlotParams& params, double tolerance) {
  return std::max(0.1, params.thickness / 2) + tolerance;
}

int slottedPieces(const Region2d& shape, const Region2d& slotted, const SlotParams& params,
                  double tolerance) {
  const double crumb = slotCrumb(params), neck = slotNeck(params, tolerance);
  int kept = 0;
  for (const Region2d& piece : slotted.components()) kept += piece.area() >= crumb ? 1 : 0;
  const int opened = openedPieceCount(slotted, neck, crumb) - openedPieceCount(shape, neck, crumb) + 1;
  return std::max(kept, opened);
}

SlotCutter::SlotCutter(const Region2d& shape, const SlotParams& params, double tolerance,
                       const std::vector<double>& lines)
    : shape_(shape),
      crumb_(slotCrumb(params)),
      neck_(slotNeck(params, tolerance)),
      erodedShape_(shape.offset(-neck_)),
      // The erosion openedPieceCount(shape) would make again (erodedShape_ is declared, so
      // made, first).
      shapePieces_(openedPiecesOfEroded(erodedShape_, neck_, crumb_)),
      // A grown slot is a slot and two necks wide: wider, it is slots on lines closer than
      // that grown into one, or paper cleared beside them (cutAs), counted on the whole.
      columns_(std::make_unique<ErodedColumns>(erodedShape_, neck_, crumb_, 2 * (params.width() + 2 * neck_),
                                               neck_ + kNeckArcTolerance, lines, params.width() / 2)) {}

Region2d SlotCutter::keep(const Region2d& cleared, int* kept, bool united) const {
  std::vector<Region2d> pieces;
  for (Region2d& piece : united ? shape_.subtractComponents(cleared) : shape_.subtractComponentsRaw(cleared))
    if (piece.area() >= crumb_) pieces.push_back(std::move(piece));
  *kept = static_cast<int>(pieces.size());
  // Pieces of one difference are apart already: laid side by side, not united again (a
  // search tries many split choices; Motor-c: a tenth of its cuts' time).
  return pieces.size() == 1 ? pieces.front() : Region2d::overlaid(pieces);
}

SlotCutter::Opened SlotCutter::opened(const Region2d& slots) const {
  Opened o;
  o.pieces = openedPieces(slots, &o.slivers);
  return o;
}

SlotCutter::Trial SlotCutter::cutAs(const Region2d& slots, const Opened* known, bool united) const {
  Trial t;
  int kept = 0;
  t.paper = keep(slots, &kept, united);
  Opened made;
  const Opened& o = known ? *known : (made = opened(slots));
  t.pieces = std::max(kept, o.pieces);
  // Slivers: a strip of paper between a slot and the outline, thinner than the neck where
  // it joins the rest, tears off like a crumb falls out. Cut away with their thread, and
  // kept so when that leaves fewer pieces (rocker-arm: 0.6 mm² beside a slot leaving
  // the paper 0.3 mm from its edge).
  if (t.pieces == 1 || o.slivers.empty()) return t;
  const Region2d cleared = slots.unite(Region2d::uniteAll(o.slivers).offset(neck_));
  int trimmedKept = 0;
  Region2d trimmed = keep(cleared, &trimmedKept, united);
  const int trimmedPieces = std::max(trimmedKept, openedPieces(cleared, nullptr));
  if (trimmedPieces >= t.pieces) return t;
  t.pieces = trimmedPieces;
  t.paper = std::move(trimmed);
  t.trimmed = true;
  return t;
}

Region2d SlotCutter::cut(const Region2d& slots, int* pieces, const Opened* known) const {
  if (!pieces) {
    int kept = 0;
    return keep(slots, &kept, true);
  }
  Trial t = cutAs(slots, known, true);
  *pieces = t.pieces;
  return std::move(t.paper);
}

SlotCutter::Trial SlotCutter::tryCut(const Region2d& slots, const Opened* known) const {
  return cutAs(slots, known, false);
}

bool SlotCutter::inPieces(const Region2d& slots) const {
  const Opened o = opened(slots);
  if (o.slivers.empty() && o.pieces > 1) return true;
  return cutAs(slots, &o, false).pieces > 1;
}

Region2d SlotCutter::paperOf(const Region2d& slots, bool trimmed) const {
  int pieces = 0;
  // Untrimmed, cut()'s paper is the shape less the slots; trimmed (rare), cut() decides again.
  return trimmed ? cut(slots, &pieces) : cut(slots, nullptr);
}

int SlotCutter::openedPieces(const Region2d& slots, std::vector<Region2d>* slivers) const {
  // The slotted shape eroded is the shape eroded less the slots grown by the same amount
  // (a disc fits the paper left when it fits the shape and misses every slot), and the
  // shape is eroded once: one Boolean instead of eroding the whole outline again. The two
  // differ only in how round corners are cut into chords (1 µm), so the count could differ
  // from eroding the slotted shape only on a bridge within microns of the neck.
  const double small = kSliverCrumbs * crumb_;
  std::vector<Region2d> found;
  std::optional<int> n = columns_->less(
      slots, [this](const Region2d& s) { return grownSlots(s); }, small, slivers ? &found : nullptr);
  // Slivers are cut away, and their outlines reach the files: made from the whole patch, as
  // before, not from pieces joined at the columns' sides (ChineseDragon-10kv: an outline
  // 1e-5 mm off where a column's side crossed a sliver). Few choices leave any.
  if (!found.empty()) n.reset();
  if (!n)
    n = openedPiecesLess(erodedShape_, Region2d::overlaid(grownSlots(slots)), neck_, crumb_, small, slivers);
  return *n - shapePieces_ + 1;
}

std::vector<Region2d> SlotCutter::grownSlots(const Region2d& slots) const {
  // Slots enclose no paper of their own; a hole among them would not grow alone.
  if (slots.holeCount() > 0) return {slots.offset(neck_)};
  // Bounds the slots kept (about 1 kB each): a repair's searches move patches, and with
  // them their slots. Top.brep's busiest patch kept 350.
  constexpr size_t kMaxGrown = 1024;
  std::vector<Region2d> grown = slots.loopsApart();
  for (Region2d& slot : grown) {
    std::vector<double> key;
    for (const Region2d::Loop& loop : slot.loops())
      for (const Vec2& v : loop) key.insert(key.end(), {v.x, v.y});
    {
      std::lock_guard<std::mutex> lock(grownMutex_);
      const auto it = grown_.find(key);
      if (it != grown_.end()) {
        slot = it->second;
        continue;
      }
    }
    slot = slot.grownSquareOff(neck_, erodedShape_, kNeckArcTolerance);
    std::lock_guard<std::mutex> lock(grownMutex_);
    if (grown_.size() >= kMaxGrown) grown_.clear();
    grown_.emplace(std::move(key), slot);
  }
  return grown;
}

}  // namespace sliceform
