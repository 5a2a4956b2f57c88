// SPDX-License-Identifier: LGPL-2.1-or-later
// A fit test coupon: a small sheet of slotted strips to cut from the same material, on the
// same cutter, before the design's sheets. Pairs of strips at clearances around the chosen
// one, each engraved with its clearance: the pair that slides together snugly names the
// --clearance to design with. One strip with a slot at the chosen slot-edge distance from
// its end (E), and one with two slots the spacing rule apart (F, the paper between them):
// if either tears, the rules are too tight for the material. Fit and kerf do not carry over
// between cutters and materials; a coupon costs a few strips instead of a sheet.
#pragma once

#include <string>
#include <vector>

#include "layout/layout.hpp"
#include "realization/slots.hpp"

namespace sliceform {

struct CouponStrip {
  std::string text;  // what is engraved on it: a clearance, or E / F and its distance
  Box2 box;          // the strip's paper on the sheet, mm
  // Every slot's paper opening on the sheet, x from the left edge of the opening, as cut
  // (the cut path runs half the kerf inside it).
  std::vector<Interval> slots;
  Interval slotDepth;  // y of a slot's bottom and of the strip's edge it opens on
};

struct Coupon {
  SheetSpec sheet;  // sized to the strips, name "coupon"
  SheetDrawing drawing;
  std::vector<CouponStrip> strips;
};

// `edgeDistance` and `spacing` are the design's minimum slot-edge distance and patch spacing.
Coupon makeCoupon(const SlotParams& slots, double edgeDistance, double spacing);

// coupon.pdf, coupon.svg, coupon.dxf, coupon.png and coupon.json (the strips: text, box,
// slot openings) into `folder`, which must exist.
void writeCoupon(const Coupon& coupon, const std::string& folder);

}  // namespace sliceform
