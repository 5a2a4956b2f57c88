// SPDX-License-Identifier: LGPL-2.1-or-later
// Region2d: a planar region with holes, the currency of every search stage (slices,
// cylinder cross-sections, hinge tests). Stored as Clipper integer polygons so unions,
// intersections and offsets are exact and robust; coordinates are in millimetres at the
// interface and in units of 1/kUnitsPerMm mm inside.
//
// Invariant: the paths are normalised (no overlaps, no self-intersections), outer loops
// counter-clockwise (positive area, y up), holes clockwise.
//
// This is the one place that uses Clipper for regions: whatever else needs its integer
// polygons asks Region2d, so units, rounding and fill rules are decided here alone (the
// nesting hands libnest2d hulls in libnest2d's own Clipper paths and units; RoomGrid reads
// Region2d's paths for BoxRoom alone).
#pragma once

#include <polyclipping/clipper.hpp>

#include <map>
#include <optional>
#include <utility>
#include <vector>

#include "geometry/room_grid.hpp"
#include "geometry/vec.hpp"

namespace sliceform {

enum class FillRule { EvenOdd, NonZero };

struct Box2 {
  Vec2 min, max;
  bool empty = true;
};

// Whether boxes a and b are more than `gap` mm apart along x or y (an empty box is apart
// from any): with gap 0, regions in them share no area.
inline bool apart(const Box2& a, const Box2& b, double gap) {
  return a.empty || b.empty || b.min.x - a.max.x > gap || a.min.x - b.max.x > gap ||
         b.min.y - a.max.y > gap || a.min.y - b.max.y > gap;
}

// The lines x = xs[k] in ascending order (`xs`) and each one's index in the given list
// (`index`): what the queries on many vertical lines sweep each edge over.
struct SortedLines {
  std::vector<double> xs;
  std::vector<size_t> index;
};
SortedLines sortedLines(const std::vector<double>& xs);

class Region2d {
 public:
  // 10 nm: far below any cutting tolerance, and keeps models up to ~10 m inside Clipper's
  // fast 32-bit-product range (coordinates below 2^30 units).
  static constexpr double kUnitsPerMm = 1e5;
  using Loop = std::vector<Vec2>;

  Region2d() = default;
  // Loops in mm with any orientation; `rule` decides what is inside.
  static Region2d fromLoops(const std::vector<Loop>& loops, FillRule rule = FillRule::EvenOdd);
  static Region2d uniteAll(const std::vector<Region2d>& regions);
  // The union of all of them in one sweep over every loop: for a few regions that barely
  // touch (uniteAll pairs them up, which pays for many similar ones).
  static Region2d uniteAtOnce(const std::vector<Region2d>& regions);
  // The regions' loops together, not united: where they overlap, the Booleans (which fill
  // by the non-zero rule) read them as one. For loops that seldom overlap, a union first
  // would cost a sweep over all of them for nothing.
  static Region2d overlaid(const std::vector<Region2d>& regions);
  // Loops in mm, counterclockwise, as they are: overlaid, not united.
  static Region2d overlaidLoops(const std::vector<Loop>& loops);
  // The axis-aligned rectangle [x0, x1] x [y0, y1] as a counterclockwise loop.
  static Loop rectangle(double x0, double y0, double x1, double y1) {
    return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
  }
  // Each loop alone, as it is, a region of its own: a region without holes in its pieces.
  std::vector<Region2d> loopsApart() const;

  // The integer polygons themselves, for tests that compare results bit for bit.
  const ClipperLib::Paths& paths() const { return paths_; }
  // Loops in mm: outer loops counter-clockwise, holes clockwise.
  std::vector<Loop> loops() const;
  bool empty() const { return paths_.empty(); }
  double area() const;  // mm²
  Box2 bounds() const;
  int holeCount() const;
  size_t bytes() const;  // about what its polygons take in memory

  // The region with its holes filled: what it covers seen from the side, as an outline.
  Region2d withoutHoles() const;

  // Connected pieces, each one outer loop with its holes.
  std::vector<Region2d> components() const;
  // subtract(other).components() in one sweep: the pieces come straight from the
  // difference's tree instead of a second union over its result.
  std::vector<Region2d> subtractComponents(const Region2d& other) const;
  // The same pieces as the tree gives them, outer loop first, not normalised again (no
  // second union, no cleaning): enough to count and measure them, at a fraction of the
  // time. A piece whose outer loop has under three points is left out. Swept turned a
  // quarter (see the .cpp): the pieces may come in another order than subtractComponents'.
  std::vector<Region2d> subtractComponentsRaw(const Region2d& other) const;

  Region2d unite(const Region2d& other) const;
  Region2d intersect(const Region2d& other) const;
  Region2d subtract(const Region2d& other) const;
  // Grows (delta > 0) or erodes (delta < 0) by |delta| mm, with round corners: chords whose
  // ends lie on the true arcs, within `arcToleranceMm` of them (1 µm: round at any print
  // size).
  static constexpr double kArcToleranceMm = 0.001;
  Region2d offset(double deltaMm, double arcToleranceMm = kArcToleranceMm) const;
  // Grown by deltaMm > 0 with mitred corners: a corner's two sides go on to where they meet
  // while that is at most `mitreLimit` times deltaMm from the corner, and are cut square
  // (tangent to the round corner) where it is further.
  Region2d mitredOffset(double deltaMm, double mitreLimit) const;
  // A region of one axis-aligned rectangle (a slot) grown by deltaMm: square corners
  // wherever the square a corner then adds misses `other` (the two differ only outside
  // `other`, so `other` less either is the same region, and a square corner is one vertex
  // where a round one is several); round ones elsewhere, as chords tangent to the true arc
  // whose corners lie at most `arcToleranceMm` (and a unit) beyond it, so the grown slot
  // covers every point within deltaMm of the slot. Any other region is offset as it is.
  Region2d grownSquareOff(double deltaMm, const Region2d& other,
                          double arcToleranceMm = kArcToleranceMm) const;
  // offset with round corners cut as chords up to `toleranceMm` inside the true arcs (far
  // fewer vertices than offset's 1 µm), then normalised as fromLoops normalises.
  Region2d coarseOffset(double deltaMm, double toleranceMm) const;
  // With vertices closer than `toleranceMm` merged: fewer, longer edges.
  Region2d simplified(double toleranceMm) const;

  // Whether p lies inside, to Clipper's units (a point on the boundary is inside).
  bool contains(Vec2 p) const;
  // Whether the segment a-b runs inside all along, to Clipper's units: no piece of it
  // outside is longer than `slackMm` (rounding leaves specks at its ends).
  bool containsSegment(Vec2 a, Vec2 b, double slackMm) const;
  // Where the centre of an axis-aligned box of half size `half` (mm) may stand within
  // `window` so that the whole box lies inside the region and the centre inside none of
  // `avoid` (boxes of centres ruled out already), to Clipper's units.
  Region2d boxCentres(Vec2 half, const Box2& window, const std::vector<Box2>& avoid) const;

  // Where the line point + t * dir (dir a unit vector) runs inside the region, as sorted
  // intervals of t in mm. For a slice frame whose y axis is W and the vertical line
  // x = c, this gives the W-intervals a hinge at c can use.
  std::vector<Interval> intervalsOnLine(Vec2 point, Vec2 dir) const;
  // intervalsOnLine({x, 0}, {0, 1}) for every x, to the bit, in one pass over the edges.
  std::vector<std::vector<Interval>> intervalsOnVerticalLines(const std::vector<double>& xs) const;
  // The stretches of the boundary that lie on the lines x = xs[k] (to Clipper's units, as
  // a Boolean with a rectangle whose side is such a line leaves them): each one's line x and
  // its y interval. `xs` sorted.
  struct Stretch {
    double x;
    Interval y;
  };
  std::vector<Stretch> stretchesOn(const std::vector<double>& xs) const;

  // Shoelace area of one loop, mm²: positive for an outer loop, negative for a hole.
  static double signedArea(const Loop& loop);
  // Length of one loop's boundary, mm.
  static double perimeter(const Loop& loop);
  static ClipperLib::cInt toUnits(double mm);
  static double toMm(ClipperLib::cInt units) { return static_cast<double>(units) / kUnitsPerMm; }

 private:
  friend class BoxRoom;
  static Region2d fromPaths(const ClipperLib::Paths& paths, FillRule rule);
  // What decides boxCentres's answer, in Clipper's units: the half size, the window, and
  // the boxes to avoid that reach the window, in the order given.
  static std::vector<ClipperLib::cInt> boxQuery(Vec2 half, const Box2& window,
                                                const std::vector<Box2>& avoid);
  Region2d boxCentres(const std::vector<ClipperLib::cInt>& query) const;

  ClipperLib::Paths paths_;
};

// A region that keeps boxCentres's answers: asked again with the same box, window and boxes
// to avoid near the window (to Clipper's units), it answers from memory. The labels ask a
// patch's paper the same question again and again, placing them again in other orders and
// at other sizes (MODERN_Cooker_1: 41 % of 80k questions). A question its grid says has no
// room is not asked of Clipper. The memo and the grid are unguarded: one thread's at a time.
class BoxRoom {
 public:
  BoxRoom() = default;
  explicit BoxRoom(Region2d region) : region_(std::move(region)) {}
  const Region2d& region() const { return region_; }
  const Region2d& boxCentres(Vec2 half, const Box2& window, const std::vector<Box2>& avoid) const;

 private:
  Region2d region_;
  mutable std::map<std::vector<ClipperLib::cInt>, Region2d> answers_;
  // Questions it answers with Clipper before it makes its grid, which takes as long as
  // 10-20 of them: fandisk's papers are asked few, and grids from the 8th question cost
  // 8 ms there to save 4 ms of Clipper.
  static constexpr size_t kGridAfter = 16;
  mutable size_t asked_ = 0;
  mutable std::optional<RoomGrid> grid_;
};

}  // namespace sliceform
