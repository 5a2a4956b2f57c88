// SPDX-License-Identifier: LGPL-2.1-or-later
// The layout stage: every patch flattened and labelled, then nested onto sheets. What the
// sheet writers (PDF, SVG, PNG, DXF) and report.json read.
#pragma once

#include <vector>

#include "layout/flat_patch.hpp"
#include "layout/nesting.hpp"

namespace sliceform {

struct SheetLayout {
  SheetSpec sheet;
  double kerf = 0;                 // the kerf the cut paths are drawn for (half of it off the paper)
  std::vector<FlatPatch> patches;  // in patch order
  Packing packing;                 // libnest2d
  Packing shelf;                   // the paper's shelf layout, for comparison only
};

SheetLayout layOut(const LayoutInput& input, const SheetSpec& sheet);
// `laid` (layOut of the same input, but for the kerf) laid out on `sheet`, as layOut would:
// a patch's flattening and labels read nothing of the sheet, and the kerf moves only the cut
// paths (nesting and labels read the paper). So a sheet, margin, spacing or turning edit
// only nests again, and a kerf edit only draws the cut paths again.
SheetLayout laidOutAgain(const LayoutInput& input, const SheetLayout& laid, const SheetSpec& sheet);

// Everything drawn on one sheet, in sheet coordinates (mm, origin bottom-left, y up).
struct SheetDrawing {
  std::vector<CutLoop> cut;
  std::vector<Stroke> engrave;
};
std::vector<SheetDrawing> sheetDrawings(const SheetLayout& layout);
// One patch as it is drawn on its sheet (labels upright): the part of sheetDrawings() it adds.
SheetDrawing placedDrawing(const FlatPatch& patch, const Placement& at);

}  // namespace sliceform
