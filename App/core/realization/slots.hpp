// SPDX-License-Identifier: LGPL-2.1-or-later
// Slots (§5): what is cut from a patch at each of its hinges so that it slides onto its
// partner. A slot is a strip of width thickness + clearance centred on the hinge line; the
// type says which part of the line it clears:
//   up / down  from the hinge's root upwards / downwards (+W / -W), to the patch boundary
//              or to the root of the next hinge on that line, whichever comes first;
//   through    the whole hinge and the paper around it up to the neighbouring hinges or
//              the boundary, which breaks a loop of paper (Alg. 3's last resort);
//   none       nothing: the partner is cut through instead.
// Coordinates are the patch's frame: x across the hinge lines, y along W.
#pragma once

#include <map>
#include <memory>
#include <mutex>
#include <vector>

#include "geometry/region2d.hpp"
#include "geometry/vec.hpp"
#include "realization/opened_pieces.hpp"
#include "slicing/slice_set.hpp"

namespace sliceform {

enum class Slot { Up, Down, Through, None };
const char* slotName(Slot slot);  // "up", "down", "through", "none"

// The four valid combinations at one hinge, (slot of the U-patch, slot of the V-patch).
enum class SlotPair { UpDown, DownUp, ThroughNone, NoneThrough };
Slot uSlot(SlotPair pair);
Slot vSlot(SlotPair pair);
// The one a patch of family f gets: uSlot or vSlot.
Slot familySlot(Family f, SlotPair pair);

enum class SlotEnd { Square, Round };

struct SlotParams {
  double thickness = 0.3;  // mm of material (0.3 mm card)
  double clearance = 0.2;  // mm added so the partner slides in
  double kerf = 0;         // mm the cutter removes; outputs compensate half of it per side
  SlotEnd end = SlotEnd::Square;
  bool uUp = true;  // the first try: U-patches slotted up (+W), V-patches down
  double width() const { return thickness + clearance; }
};

// Throws BadParameter for a thickness <= 0, negative clearance or kerf, or a kerf as wide as
// the slot.
void checkSlotParams(const SlotParams& params);

// One hinge as a patch sees it.
struct PatchHinge {
  double x = 0;     // the hinge line
  Interval w;       // the hinge segment along the line
  double root = 0;  // where up/down slots start: middle of the grip, or of the segment
  Slot slot = Slot::None;
};

// The strip cleared at one hinge: x in [x - width/2, x + width/2], y in [y.lo, y.hi]. An
// open end runs out of the paper (past the boundary); a closed end is inside the paper
// and gets a round end when asked.
struct SlotCut {
  double x = 0;
  Interval y;
  bool openLo = false, openHi = false;
};

// Where a shape lies on vertical lines x = c (Region2d::intervalsOnLine along +y), kept for
// the lines given up front: planning a patch's slots asks for the same few lines, those of
// its hinges and both walls of their slots, for every slot choice the search tries. Other
// lines are computed when asked. Keeps a pointer to `shape`, which must outlive it.
class VerticalLines {
 public:
  VerticalLines(const Region2d& shape, const std::vector<double>& xs);
  std::vector<Interval> at(double x) const;
  // The lines planSlots asks for, given the hinges (whatever their slots).
  static std::vector<double> slotLines(const std::vector<PatchHinge>& hinges, const SlotParams& params);

 private:
  const Region2d* shape_;
  std::map<double, std::vector<Interval>> lines_;
};

// How far an up or down slot starts past its root, mm: the partner's slot ends there too,
// and two slot ends on one point leave the interlock parity to rounding (planSlots). The
// two papers overlap by twice this at the root.
constexpr double kRootGap = 1e-3;

// The strips to cut for the hinges of one patch (one per hinge that is not `none`).
std::vector<SlotCut> planSlots(const Region2d& shape, const std::vector<PatchHinge>& hinges,
                               const SlotParams& params);
std::vector<SlotCut> planSlots(const VerticalLines& shape, const std::vector<PatchHinge>& hinges,
                               const SlotParams& params);

// The strips as plain shapes (rectangles, and discs for round closed ends), for the
// polygon search and the exact faces alike.
struct Disc {
  Vec2 centre;
  double radius = 0;
};
struct SlotShapes {
  std::vector<Box2> rectangles;
  std::vector<Disc> discs;
};
SlotShapes slotShapes(const std::vector<SlotCut>& cuts, const SlotParams& params);

// The region the strips clear.
Region2d slotRegion(const std::vector<SlotCut>& cuts, const SlotParams& params);
// The same strips (and round ends) overlaid, not united: for the searches' cuts
// (SlotCutter::tryCut, opened, inPieces), whose Booleans read overlapping loops as one.
// The union was 15 % of the slot search's states (occ/Top.brep).
Region2d slotStrips(const std::vector<SlotCut>& cuts, const SlotParams& params);

// The search's tests for a slotted patch: pieces smaller than `slotCrumb` mm² fall out when
// cut, and a bridge narrower than 2 `slotNeck` mm counts as cut (see SlotCutter).
double slotCrumb(const SlotParams& params);
double slotNeck(const SlotParams& params, double tolerance);
// Pieces of `slotted` (cut from `shape`) by those tests: what SlotCutter::cut reports.
int slottedPieces(const Region2d& shape, const Region2d& slotted, const SlotParams& params, double tolerance);

// The slotted patch: shape minus its slots. Crumbs (pieces smaller than a slot-wide square
// or 0.5 mm², whichever is larger) fall out when cut and are dropped. `pieces` is set to the
// number of pieces that remain, which must be 1; a bridge narrower than the material
// thickness (at least 0.2 mm) plus twice `tolerance` (how far the polygons may stray from
// the true shape) counts as cut, unless the shape had it before the slots. Slivers (pieces
// of under kSliverCrumbs crumbs that only such a bridge holds) are cut away with it.
class SlotCutter {
 public:
  // `lines`: the patch's hinge lines, where its slots will be (ErodedColumns), if known.
  SlotCutter(const Region2d& shape, const SlotParams& params, double tolerance,
             const std::vector<double>& lines = {});

  // What the neck test alone says of the shape less `slots`: its opened pieces beyond those
  // the shape had, plus one, and the slivers among them. cut() counts at least as many
  // pieces unless it trims slivers off, which it tries only when there are some and the
  // patch is in pieces: elsewhere `pieces` is a lower bound of cut()'s count, without the
  // slotted shape itself (a third of a cut's work on occ/Top.brep).
  struct Opened {
    int pieces = 1;
    std::vector<Region2d> slivers;
  };
  Opened opened(const Region2d& slots) const;

  // `known`: opened(slots), when the caller has it already.
  Region2d cut(const Region2d& slots, int* pieces, const Opened* known = nullptr) const;

  // What cut() counts and keeps, for the searches, which read the count and the paper's
  // shape but never its vertices' order: the pieces as Clipper's difference leaves them,
  // not united again one by one (their loops may start at another vertex, and keep one
  // within 1.4e-5 mm of its neighbours' line). The union was half of every cut's work
  // (occ/Top.brep). `trimmed`: whether slivers were cut away.
  struct Trial {
    Region2d paper;
    int pieces = 1;
    bool trimmed = false;
  };
  Trial tryCut(const Region2d& slots, const Opened* known = nullptr) const;
  // Whether cut() leaves the patch in pieces. The neck test alone says so where it counts
  // pieces and finds no slivers (cut() counts at least as many); the cut is made only
  // otherwise (the graze tests: most of their tries are of patches in pieces).
  bool inPieces(const Region2d& slots) const;
  // cut()'s paper, for the slots a trial cut (`trimmed`: the trial's): only what reaches
  // the files is united.
  Region2d paperOf(const Region2d& slots, bool trimmed) const;

  // Opened pieces smaller than this many crumbs, once slots are cut, are slivers (cut()).
  static constexpr double kSliverCrumbs = 4;

  // The grown slots' round corners (Region2d::grownSquareOff): chords tangent to the true
  // arcs, their corners at most 10 µm beyond them. So the grown slot covers every point
  // within a neck of the slot, and no bridge narrower than two necks passes (offset's 1 µm
  // chords, used before, cut up to 2.3 µm inside the arcs). A round corner is then 3 vertices,
  // not 8 (a 0.17 mm neck), a grown slot about 8, not 18, and the Boolean of every slot
  // choice the search tries that much smaller (the realization stage, median of 3:
  // occ/Top.brep 1.76 -> 1.32 s, MODERN_Cooker_1 1.16 -> 0.89 s). Every design (occt-misc,
  // the meshes) is the same.
  static constexpr double kNeckArcTolerance = 0.01;  // mm

 private:
  // The shape less `cleared`, crumbs dropped; `kept` is set to the pieces left. Each piece
  // united again (Region2d::subtractComponents) when `united`, else as the difference left
  // it (subtractComponentsRaw).
  Region2d keep(const Region2d& cleared, int* kept, bool united) const;
  Trial cutAs(const Region2d& slots, const Opened* known, bool united) const;
  // Opened pieces of the shape less `slots` beyond the shape's own, plus one (the neck
  // test); those smaller than kSliverCrumbs crumbs go to `slivers` when it is given.
  int openedPieces(const Region2d& slots, std::vector<Region2d>* slivers) const;
  // The slots grown by neck_, slot by slot (see grown_), each alone. A corner beyond the
  // eroded shape stays square (Region2d::grownSquareOff): the difference is the same, and
  // an open end's two corners, half a slot's, come to two points (occ/Top.brep: 52 % of
  // 80,724 corners; its slot searches 17 % faster).
  std::vector<Region2d> grownSlots(const Region2d& slots) const;

  Region2d shape_;
  double crumb_, neck_;
  Region2d erodedShape_;  // shape_ eroded by neck_
  int shapePieces_;       // of the opened shape, before any slot
  // erodedShape_ cut along the slots' columns, for the neck test of any slot choice.
  std::unique_ptr<const ErodedColumns> columns_;
  // Each slot's outline grown by neck_, by its corners: a search tries many slot choices
  // of one patch, and any two share all slots but one or two. Grown alone and not united,
  // a slot costs its rounded corners once (MODERN_Cooker_1: 51 slots, 2460 points grown),
  // not at every choice. Shared by the threads that cut this patch.
  mutable std::mutex grownMutex_;
  mutable std::map<std::vector<double>, Region2d> grown_;
};

}  // namespace sliceform
