// SPDX-License-Identifier: LGPL-2.1-or-later
#include "geometry/room_grid.hpp"

#include <algorithm>
#include <cmath>

namespace sliceform {
namespace {

using ClipperLib::IntPoint;
using ClipperLib::Path;

// Cells per side at most, and their smallest side in units (0.1 mm): a label's box is at
// least 1 mm high, so its half spans a cell or more on any patch up to 250 mm across, and
// the sums stay within about 1 MB however large the patch. 1024 cells a side ruled out a
// third more of MODERN_Cooker_1's questions, for grids that cost more than that saved.
constexpr long kMaxCells = 512;
constexpr ClipperLib::cInt kMinCell = 10000;

}  // namespace

RoomGrid::RoomGrid(const ClipperLib::Paths& paths) {
  cInt lx = 0, ly = 0, hx = 0, hy = 0;
  bool first = true;
  for (const Path& loop : paths)
    for (const IntPoint& p : loop) {
      if (first) lx = hx = p.X, ly = hy = p.Y, first = false;
      lx = std::min(lx, p.X), hx = std::max(hx, p.X), ly = std::min(ly, p.Y), hy = std::max(hy, p.Y);
    }
  const cInt cell = std::max(kMinCell, (std::max(hx - lx, hy - ly) + kMaxCells - 1) / kMaxCells);
  // One cell of margin on every side: the cells beyond the grid lie a cell or more from the
  // region, and so wholly outside it.
  ox_ = lx - cell, oy_ = ly - cell;
  const long nx = long((hx - lx) / cell) + 3, ny = long((hy - ly) / cell) + 3;
  std::vector<uint8_t> mixed(size_t(nx) * ny, 0);
  std::vector<std::vector<double>> crossings(ny);
  const double s = double(cell), e = double(kSlack);
  for (const Path& loop : paths)
    for (size_t i = 0, n = loop.size(); i < n; ++i) {
      const double ax = double(loop[i].X - ox_), ay = double(loop[i].Y - oy_);
      const double bx = double(loop[(i + 1) % n].X - ox_), by = double(loop[(i + 1) % n].Y - oy_);
      // Every cell within kSlack of the edge is mixed: row by row, the edge's part in the
      // row's band (grown by kSlack) spans these columns, grown by kSlack.
      const long r0 = std::max(0L, long(std::floor((std::min(ay, by) - e) / s)));
      const long r1 = std::min(ny - 1, long(std::floor((std::max(ay, by) + e) / s)));
      for (long r = r0; r <= r1; ++r) {
        double x0 = ax, x1 = bx;
        if (ay != by) {
          const double lo = r * s - e, hi = (r + 1) * s + e;
          const double t0 = std::clamp((lo - ay) / (by - ay), 0.0, 1.0);
          const double t1 = std::clamp((hi - ay) / (by - ay), 0.0, 1.0);
          x0 = ax + t0 * (bx - ax), x1 = ax + t1 * (bx - ax);
        }
        const long c0 = std::max(0L, long(std::floor((std::min(x0, x1) - e) / s)));
        const long c1 = std::min(nx - 1, long(std::floor((std::max(x0, x1) + e) / s)));
        std::fill(mixed.begin() + r * nx + c0, mixed.begin() + r * nx + c1 + 1, 1);
      }
      // Where the edge crosses the rows' middle lines, half-open so the crossings pair up.
      const long m0 = std::max(0L, long(std::floor(std::min(ay, by) / s - 0.5)));
      const long m1 = std::min(ny - 1, long(std::ceil(std::max(ay, by) / s - 0.5)));
      for (long r = m0; r <= m1; ++r) {
        const double y = (r + 0.5) * s;
        if ((ay > y) != (by > y)) crossings[r].push_back(ax + (y - ay) / (by - ay) * (bx - ax));
      }
    }
  // A cell no edge comes near lies wholly on the side its middle does. `mixed` becomes
  // "wholly outside" in place.
  std::vector<uint8_t>& out = mixed;
  for (long r = 0; r < ny; ++r) {
    std::vector<double>& xs = crossings[r];
    std::sort(xs.begin(), xs.end());
    size_t k = 0;
    for (long c = 0; c < nx; ++c) {
      while (k < xs.size() && xs[k] < (c + 0.5) * s) ++k;
      out[size_t(r) * nx + c] = !out[size_t(r) * nx + c] && k % 2 == 0;
    }
  }
  fine_ = {cell, nx, ny, {}};
  fine_.sum(out);
  // A coarse cell is wholly outside when every fine cell in it is (those beyond the fine
  // grid are).
  coarse_ = {cell * kFactor, (nx + kFactor - 1) / kFactor, (ny + kFactor - 1) / kFactor, {}};
  std::vector<uint8_t> coarseOut(size_t(coarse_.nx) * coarse_.ny);
  for (long r = 0; r < coarse_.ny; ++r)
    for (long c = 0; c < coarse_.nx; ++c) {
      const long fc = c * kFactor, fr = r * kFactor;
      const long inside = std::min(kFactor, nx - fc) * std::min(kFactor, ny - fr);
      const long outside =
          fine_.summed[size_t(std::min(ny, fr + kFactor)) * (nx + 1) + std::min(nx, fc + kFactor)] -
          fine_.summed[size_t(fr) * (nx + 1) + std::min(nx, fc + kFactor)] -
          fine_.summed[size_t(std::min(ny, fr + kFactor)) * (nx + 1) + fc] +
          fine_.summed[size_t(fr) * (nx + 1) + fc];
      coarseOut[size_t(r) * coarse_.nx + c] = outside == inside;
    }
  coarse_.sum(coarseOut);
}

void RoomGrid::Level::sum(const std::vector<uint8_t>& out) {
  summed.assign(size_t(nx + 1) * (ny + 1), 0);
  for (long r = 0; r < ny; ++r) {
    int32_t row = 0;
    for (long c = 0; c < nx; ++c) {
      row += out[size_t(r) * nx + c];
      summed[size_t(r + 1) * (nx + 1) + c + 1] = summed[size_t(r) * (nx + 1) + c + 1] + row;
    }
  }
}

bool RoomGrid::Level::free(long c, long r, cInt w, cInt h) const {
  const long kx = long(w / cell), ky = long(h / cell);
  if (c - kx < 0 || r - ky < 0 || c + kx >= nx || r + ky >= ny) return false;
  const auto at = [&](long cc, long rr) { return summed[size_t(rr) * (nx + 1) + cc]; };
  return at(c + kx + 1, r + ky + 1) - at(c - kx, r + ky + 1) - at(c + kx + 1, r - ky) + at(c - kx, r - ky) ==
         0;
}

RoomGrid::Span RoomGrid::span(const Level& level, cInt x0, cInt y0, cInt x1, cInt y1) const {
  const double s = double(level.cell);
  return {std::max(0L, long(std::floor(double(x0 - kSlack - ox_) / s))),
          std::max(0L, long(std::floor(double(y0 - kSlack - oy_) / s))),
          std::min(level.nx - 1, long(std::floor(double(x1 + kSlack - ox_) / s))),
          std::min(level.ny - 1, long(std::floor(double(y1 + kSlack - oy_) / s)))};
}

// Whether one box to avoid holds the whole cell, with kSlack to spare: no centre in it
// counts.
bool RoomGrid::covered(const Level& level, long c, long r, const cInt* avoid, size_t count) const {
  const cInt lx = ox_ + c * level.cell, ly = oy_ + r * level.cell, hx = lx + level.cell, hy = ly + level.cell;
  for (size_t i = 0; i < count; ++i) {
    const cInt* b = avoid + 4 * i;
    if (b[0] + kSlack < lx && b[1] + kSlack < ly && hx + kSlack < b[2] && hy + kSlack < b[3]) return true;
  }
  return false;
}

bool RoomGrid::mayHold(cInt w, cInt h, cInt x0, cInt y0, cInt x1, cInt y1, const cInt* avoid,
                       size_t count) const {
  // Each level's test holds for any centre in its cell: where a coarse cell cannot hold a
  // centre, none of its fine cells can, and they are not looked at.
  const Span coarse = span(coarse_, x0, y0, x1, y1), fine = span(fine_, x0, y0, x1, y1);
  for (long R = coarse.r0; R <= coarse.r1; ++R)
    for (long C = coarse.c0; C <= coarse.c1; ++C) {
      if (!coarse_.free(C, R, w, h) || covered(coarse_, C, R, avoid, count)) continue;
      const long r1 = std::min(fine.r1, (R + 1) * kFactor - 1), c1 = std::min(fine.c1, (C + 1) * kFactor - 1);
      for (long r = std::max(fine.r0, R * kFactor); r <= r1; ++r)
        for (long c = std::max(fine.c0, C * kFactor); c <= c1; ++c)
          if (fine_.free(c, r, w, h) && !covered(fine_, c, r, avoid, count)) return true;
    }
  return false;
}

}  // namespace sliceform
