// SPDX-License-Identifier: LGPL-2.1-or-later
// Nesting flat patches onto sheets. `nestOnSheets` uses libnest2d (no-fit-polygon placer,
// first-fit selection, rotations by quarter turns when allowed); `shelfPack` is the paper's
// left-to-right layout (bounding boxes in rows), kept to compare against.
//
// A placement maps a point p of the patch plane to the sheet: R(rotation) p + offset, in mm,
// with the sheet's origin at its bottom-left corner and y up.
#pragma once

#include <string>
#include <vector>

#include "geometry/region2d.hpp"

namespace sliceform {

struct SheetSpec {
  std::string name = "A4";
  double width = 210, height = 297;  // mm
  double margin = 10;                // mm left clear along every edge
  double spacing = 3;                // mm between patches
  bool rotate = true;                // patches may turn by 90°, 180°, 270°
};

// "A4", "A3", "Letter" (portrait), or "WxH" in mm such as "600x400". Throws BadParameter.
SheetSpec sheetSpec(const std::string& name, double margin, double spacing);

struct Placement {
  int sheet = 0;
  Vec2 offset;
  double rotation = 0;  // degrees, counter-clockwise
  Vec2 apply(Vec2 p) const;
};

struct Packing {
  int sheets = 0;
  std::vector<Placement> placements;  // one per outline, in input order
  double utilisation = 0;             // paper area / (sheets x sheet area)
};

// Throws BadParameter naming the first outline that fits no sheet. `askEverySheet`: with
// libnest2d's own first-fit selection, which asks every sheet's placer for every patch
// (the same placements, slower: for tests); else a sheet where the patch has no room is
// not asked (layout/first_fit.hpp).
Packing nestOnSheets(const std::vector<Region2d>& outlines, const std::vector<std::string>& names,
                     const SheetSpec& sheet, bool askEverySheet = false);
Packing shelfPack(const std::vector<Region2d>& outlines, const std::vector<std::string>& names,
                  const SheetSpec& sheet);

}  // namespace sliceform
