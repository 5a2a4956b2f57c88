// SPDX-License-Identifier: LGPL-2.1-or-later
// RoomGrid: a raster of a region that rules out, in microseconds, a box that cannot stand
// anywhere in a window. The labels ask a patch's paper tens of thousands of times where a
// box may stand near a slot, and most answers are "nowhere" (MODERN_Cooker_1: 36k of 53k
// questions, 29k of them on the bare paper): each costs Clipper a sweep of the bands of
// the nearby boundary (about 30 µs). The grid answers three in four of them from
// summed-area tables instead; BoxRoom asks it first and asks Clipper only where it cannot
// say.
#pragma once

#include <polyclipping/clipper.hpp>

#include <cstdint>
#include <vector>

namespace sliceform {

class RoomGrid {
 public:
  using cInt = ClipperLib::cInt;
  // The region's normalised paths (Region2d's invariant), in Clipper's units.
  explicit RoomGrid(const ClipperLib::Paths& paths);

  // False only where surely no centre in the window [x0, x1] x [y0, y1] holds a box of half
  // size (w, h) wholly inside the region, outside the interiors of the `avoid` boxes
  // (lo.X, lo.Y, hi.X, hi.Y each, `count` of them): what boxCentres would call empty, give
  // or take kSlack units at every border. True says nothing.
  bool mayHold(cInt w, cInt h, cInt x0, cInt y0, cInt x1, cInt y1, const cInt* avoid, size_t count) const;

  // Units every answer allows for: far more than the unit Clipper rounds to.
  static constexpr cInt kSlack = 100;  // 1 µm

 private:
  // The cells of one size: sums of the cells wholly outside, more than kSlack from the
  // region. Beyond the grid every cell is wholly outside.
  struct Level {
    cInt cell = 1;
    long nx = 0, ny = 0;
    std::vector<int32_t> summed;  // (nx + 1) x (ny + 1)
    void sum(const std::vector<uint8_t>& out);
    // Whether a box of half size (w, h) centred anywhere in cell (c, r) meets no cell wholly
    // outside. Wherever its centre is in the cell, the (closed) box meets every cell within
    // w / cell columns and h / cell rows of it, rounded down: the cell itself at least. A
    // box inside the region, give or take Clipper's unit, meets none.
    bool free(long c, long r, cInt w, cInt h) const;
  };
  // The cells of `level` about which a centre in the window may lie, within [c0, c1] x [r0, r1].
  struct Span {
    long c0, r0, c1, r1;
  };
  Span span(const Level& level, cInt x0, cInt y0, cInt x1, cInt y1) const;
  bool covered(const Level& level, long c, long r, const cInt* avoid, size_t count) const;

  static constexpr long kFactor = 4;  // fine cells per coarse cell's side
  cInt ox_ = 0, oy_ = 0;              // where both levels' cell (0, 0) begins, units
  Level fine_, coarse_;               // a coarse cell is wholly outside when its fine cells are
};

}  // namespace sliceform
