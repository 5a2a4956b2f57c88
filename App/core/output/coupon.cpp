// SPDX-License-Identifier: LGPL-2.1-or-later
#include "output/coupon.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "layout/labels.hpp"
#include "output/report_json.hpp"
#include "output/sheet_dxf.hpp"
#include "output/sheets_cairo.hpp"

namespace sliceform {
namespace {

// Clearances tried: the chosen one and these steps about it, none below zero (the design
// refuses a negative clearance). −0.15 … +0.30 mm: card swells or crushes by about that.
constexpr double kSteps[] = {-0.15, -0.10, -0.05, 0, 0.05, 0.10, 0.15, 0.20, 0.25, 0.30};
constexpr double kStripLength = 40;  // mm
constexpr int kPerRow = 3;
constexpr double kGap = 4;      // mm between strips
constexpr double kMargin = 10;  // mm, as the design's sheets

std::string number(double mm, int decimals = 2) {
  char text[32];
  std::snprintf(text, sizeof text, "%.*f", decimals, mm);
  return text;
}

Vec2 at(double x, double y) {
  return {x, y};
}

// The cut path of a strip: its paper [x0, x0 + L] x [y0, y0 + H] with slots opening on the
// top edge down to `bottom`, moved out of the paper by half the kerf everywhere.
CutLoop stripPath(const CouponStrip& s, double kerf) {
  const double h = kerf / 2, x0 = s.box.min.x - h, x1 = s.box.max.x + h, y0 = s.box.min.y - h,
               top = s.box.max.y + h, bottom = s.slotDepth.lo + h;
  std::vector<Vec2> p = {at(x0, y0), at(x1, y0), at(x1, top)};
  std::vector<Interval> slots = s.slots;
  std::sort(slots.begin(), slots.end(), [](const Interval& a, const Interval& b) { return a.lo > b.lo; });
  for (const Interval& o : slots) {
    p.push_back(at(o.hi - h, top));
    p.push_back(at(o.hi - h, bottom));
    p.push_back(at(o.lo + h, bottom));
    p.push_back(at(o.lo + h, top));
  }
  p.push_back(at(x0, top));
  CutLoop loop;
  for (size_t i = 0; i < p.size(); ++i) {
    CutElement e;
    e.a = p[i], e.b = p[(i + 1) % p.size()];
    loop.push_back(e);
  }
  return loop;
}

}  // namespace

Coupon makeCoupon(const SlotParams& slots, double edgeDistance, double spacing) {
  checkSlotParams(slots);
  const double t = slots.thickness, height = std::max(20.0, 8 * t), depth = height / 2;
  const auto width = [&](double clearance) { return t + clearance; };
  // The strips in reading order: (text, slot openings relative to the strip's left end).
  std::vector<std::pair<std::string, std::vector<Interval>>> strips;
  for (const double step : kSteps) {
    const double c = slots.clearance + step;
    if (c < -1e-9 || width(c) <= slots.kerf + 0.05) continue;
    const double w = width(std::max(0.0, c)), mid = kStripLength / 2;
    for (int copy = 0; copy < 2; ++copy)
      strips.push_back({number(std::max(0.0, c)), {{mid - w / 2, mid + w / 2}}});
  }
  const double w = slots.width(), mid = kStripLength / 2;
  // E: the slot's paper edge `edgeDistance` from the strip's right end.
  strips.push_back(
      {"E" + number(edgeDistance, 1), {{kStripLength - edgeDistance - w, kStripLength - edgeDistance}}});
  // F: two slots `spacing` apart, centre to centre: the finger between them.
  strips.push_back({"F" + number(spacing - w, 1),
                    {{mid - spacing / 2 - w / 2, mid - spacing / 2 + w / 2},
                     {mid + spacing / 2 - w / 2, mid + spacing / 2 + w / 2}}});

  Coupon c;
  const int rows = static_cast<int>((strips.size() + kPerRow - 1) / kPerRow);
  c.sheet.name = "coupon";
  c.sheet.margin = kMargin, c.sheet.spacing = kGap, c.sheet.rotate = false;
  c.sheet.width = 2 * kMargin + kPerRow * kStripLength + (kPerRow - 1) * kGap;
  c.sheet.height = 2 * kMargin + rows * height + (rows - 1) * kGap;
  const double labelHeight = std::min(4.0, height / 4);
  for (size_t k = 0; k < strips.size(); ++k) {
    const int row = static_cast<int>(k) / kPerRow, col = static_cast<int>(k) % kPerRow;
    const double x0 = kMargin + col * (kStripLength + kGap);
    const double y0 = c.sheet.height - kMargin - height - row * (height + kGap);  // top row first
    CouponStrip s;
    s.text = strips[k].first;
    s.box = {{x0, y0}, {x0 + kStripLength, y0 + height}, false};
    for (const Interval& o : strips[k].second) s.slots.push_back({x0 + o.lo, x0 + o.hi});
    s.slotDepth = {y0 + height - depth, y0 + height};
    c.drawing.cut.push_back(stripPath(s, slots.kerf));
    // The mark on the left of the strip's lower half, clear of every slot.
    const Label l =
        setLabel(s.text, {x0 + 2 + labelWidth(s.text, labelHeight) / 2, y0 + height / 4}, labelHeight, false);
    for (const Stroke& stroke : l.strokes) c.drawing.engrave.push_back(stroke);
    c.strips.push_back(s);
  }
  return c;
}

void writeCoupon(const Coupon& c, const std::string& folder) {
  const std::string base = folder + "/coupon";
  writeSheetsPdf({c.drawing}, c.sheet, base + ".pdf");
  writeSheetSvg(c.drawing, c.sheet, base + ".svg");
  writeSheetDxf(c.drawing, c.sheet, base + ".dxf");
  writeSheetsPng({c.drawing}, c.sheet, base + ".png", 4);
  nlohmann::json strips = nlohmann::json::array();
  for (const CouponStrip& s : c.strips) {
    nlohmann::json slots = nlohmann::json::array();
    for (const Interval& o : s.slots) slots.push_back({o.lo, o.hi});
    strips.push_back({{"text", s.text},
                      {"box", {{s.box.min.x, s.box.min.y}, {s.box.max.x, s.box.max.y}}},
                      {"slots", slots},
                      {"slot_bottom_mm", s.slotDepth.lo}});
  }
  writeJson(
      {{"format", "sliceform-coupon"}, {"sheet_mm", {c.sheet.width, c.sheet.height}}, {"strips", strips}},
      base + ".json");
}

}  // namespace sliceform
