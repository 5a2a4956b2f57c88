// SPDX-License-Identifier: LGPL-2.1-or-later
// The neck test of a slotted patch (SlotCutter): its pieces once opened by `neck` (eroded,
// then grown back), so that a bridge of paper narrower than two necks counts as cut. Pieces
// smaller than `crumb` mm² fall out and are not counted.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <utility>
#include <vector>

#include "geometry/region2d.hpp"

namespace sliceform {

// Pieces of at least `crumb` mm² left when the region is opened by `neck` mm: a bridge
// narrower than 2 neck is cut. openedPieceCountFull grows the whole region back;
// openedPieceCount only the eroded pieces that come close to another (the same count, as
// the tests check).
int openedPieceCount(const Region2d& region, double neck, double crumb);
int openedPieceCountFull(const Region2d& region, double neck, double crumb);

// openedPieceCount of the region whose erosion by `neck` is `eroded`. Opened pieces smaller
// than `small` mm² go to `smallPieces` when it is given.
int openedPiecesOfEroded(const Region2d& eroded, double neck, double crumb, double small = 0,
                         std::vector<Region2d>* smallPieces = nullptr);

// openedPiecesOfEroded of `eroded` less `grown`: the eroded patch less its grown slots, in one
// Boolean of the whole.
int openedPiecesLess(const Region2d& eroded, const Region2d& grown, double neck, double crumb, double small,
                     std::vector<Region2d>* smallPieces);

struct OpenedPart;  // one connected piece of an eroded region (opened_pieces.cpp)

// The same count for an eroded patch less slots grown by the neck, made column by column.
// A slot stands on a hinge line x = c, so its grown strip lies within a narrow column
// around that line, and the patch outside every column is the same for every slot choice.
// The patch is cut once along the columns' sides: the pieces between columns are kept, and
// so is the patch within each column. A choice then costs a Boolean of one column's paper
// with that column's slots, kept too (two choices differ in a slot or two), where one
// Boolean of the whole patch with every slot was 79 % of the neck test (occ/Top.brep).
// Pieces that share a stretch of a column's side are one piece of paper; the rest is the
// neck test as before, which links the pieces closer than two necks anyway. So the count
// is the one of the patch less the slots, but for rounding to Clipper's units where an
// edge meets a column's side (a bridge within microns of the neck may count either way, as
// it may in the test of the whole). Shared by the threads that cut one patch.
class ErodedColumns {
 public:
  // `eroded` must outlive this. Slots wider than `widest` mm, grown, are not put in columns.
  // `reach`: how far mm a slot's grown strip may stand beyond the slot's own x range (the
  // neck, and how far the grown corners' chords may lie beyond their arcs).
  // `lines`: where slots are expected (the patch's hinge lines), `halfWidth` mm either side
  // of them before the neck: their columns are made with the first count's, not one by one
  // as their slots come (occ/Top.brep: 991 layouts for 523 patches' cutters).
  ErodedColumns(const Region2d& eroded, double neck, double crumb, double widest, double reach,
                const std::vector<double>& lines = {}, double halfWidth = 0);
  ~ErodedColumns();

  // The slots each grown by the neck, alone (SlotCutter::grownSlots).
  using Grow = std::function<std::vector<Region2d>(const Region2d& slots)>;
  // openedPiecesOfEroded(eroded less `slots` grown by `grow`, ...), or nothing where the
  // slots have a hole or one is wider than `widest` grown: the caller then counts on the
  // whole. `slots`: one loop a slot (or a round end), overlaid (slotStrips). A column's
  // slots are grown only when the column has not had them before.
  std::optional<int> less(const Region2d& slots, const Grow& grow, double small,
                          std::vector<Region2d>* smallPieces) const;

 private:
  struct Layout;
  using Parts = std::vector<OpenedPart>;
  using Range = std::pair<double, double>;  // x from, to, mm
  // The layout whose columns hold `ranges`, made when needed.
  std::shared_ptr<const Layout> layoutFor(const std::vector<Range>& ranges) const;
  // The column's paper less `slots` grown, or null where they grow out of the column.
  std::shared_ptr<const Parts> columnLess(const Layout& layout, size_t column,
                                          const std::vector<Region2d::Loop>& slots, const Grow& grow) const;

  const Region2d* eroded_;
  double neck_, crumb_, widest_;
  double reach_;                 // `reach` and a unit of Region2d's grid
  std::vector<Range> expected_;  // the columns of `lines`, for the first layout
  mutable std::mutex mutex_;
  mutable std::shared_ptr<const Layout> layout_;
  // A column's paper less its slots, by the column and the slots' points.
  mutable std::map<std::vector<double>, std::shared_ptr<const Parts>> columns_;
};

}  // namespace sliceform
