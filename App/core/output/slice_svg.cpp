// SPDX-License-Identifier: LGPL-2.1-or-later
#include "output/slice_svg.hpp"

#include <cairo-svg.h>
#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "output/cairo_file.hpp"
#include "support/atomic_file.hpp"
#include "support/error.hpp"

namespace sliceform {
namespace {

constexpr double kGap = 6;     // mm between cells
constexpr double kLabel = 4;   // mm of label band under each cell
constexpr double kFont = 2.5;  // mm

Box2 boundsOf(const SliceSet& set) {
  Box2 all;
  for (const Slice& s : set.slices) {
    const Box2 b = s.region.bounds();
    if (b.empty) continue;
    if (all.empty) {
      all = b;
      continue;
    }
    all.min = {std::min(all.min.x, b.min.x), std::min(all.min.y, b.min.y)};
    all.max = {std::max(all.max.x, b.max.x), std::max(all.max.y, b.max.y)};
  }
  return all;
}

void drawRegion(cairo_t* cr, const Region2d& region, double ox, double oy, const Box2& box) {
  // SVG's y runs down; flip so that W points up on the sheet.
  for (const Region2d::Loop& loop : region.loops()) {
    for (size_t i = 0; i < loop.size(); ++i) {
      const double x = ox + loop[i].x - box.min.x, y = oy + box.max.y - loop[i].y;
      i == 0 ? cairo_move_to(cr, x, y) : cairo_line_to(cr, x, y);
    }
    cairo_close_path(cr);
  }
  cairo_set_fill_rule(cr, CAIRO_FILL_RULE_EVEN_ODD);
  cairo_set_source_rgb(cr, 0.85, 0.88, 0.95);
  cairo_fill_preserve(cr);
  cairo_set_source_rgb(cr, 0.8, 0, 0);
  cairo_set_line_width(cr, 0.2);
  cairo_stroke(cr);
}

std::string labelOf(const Slice& slice, int index) {
  char label[96];
  std::snprintf(label, sizeof label, "#%d  at %.2f mm  %.1f mm2", index, slice.position, slice.region.area());
  return label;
}

// Width of the widest label in mm, so that labels of small models do not overlap.
double widestLabel(const SliceSet& set) {
  cairo_surface_t* scratch = cairo_image_surface_create(CAIRO_FORMAT_A8, 1, 1);
  cairo_t* cr = cairo_create(scratch);
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, kFont);
  double widest = 0;
  for (size_t i = 0; i < set.slices.size(); ++i) {
    cairo_text_extents_t extents;
    cairo_text_extents(cr, labelOf(set.slices[i], static_cast<int>(i)).c_str(), &extents);
    widest = std::max(widest, extents.x_advance);
  }
  cairo_destroy(cr);
  cairo_surface_destroy(scratch);
  return widest;
}

}  // namespace

void writeSliceSetSvg(const SliceSet& set, const std::string& title, const std::string& path) {
  const Box2 box = boundsOf(set);
  const double shapeW = box.empty ? 10 : box.max.x - box.min.x;
  const double cellW = std::max(shapeW, widestLabel(set));
  const double cellH = (box.empty ? 10 : box.max.y - box.min.y) + kLabel;
  const int n = static_cast<int>(set.slices.size());
  const int columns = std::max(1, static_cast<int>(std::ceil(std::sqrt(n * cellH / std::max(cellW, 1e-6)))));
  const int rows = (n + columns - 1) / columns;
  const double width = kGap + columns * (cellW + kGap);
  const double height = 2 * kGap + rows * (cellH + kGap);

  writeAtomically(path, [&](const std::string& temporary) {
    cairo_surface_t* surface = cairo_svg_surface_create(temporary.c_str(), width, height);
    // Document unit mm: width="…mm" and a viewBox in mm, so 1 user unit is 1 mm.
    cairo_svg_surface_set_document_unit(surface, CAIRO_SVG_UNIT_MM);
    drawAndFinish(surface, path, [&](cairo_t* cr) {
      cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
      cairo_set_font_size(cr, kFont * 1.4);
      cairo_set_source_rgb(cr, 0, 0, 0);
      cairo_move_to(cr, kGap, kGap * 0.8);
      cairo_show_text(cr, title.c_str());
      cairo_set_font_size(cr, kFont);
      for (int i = 0; i < n; ++i) {
        const double ox = kGap + (i % columns) * (cellW + kGap);
        const double oy = 2 * kGap + (i / columns) * (cellH + kGap);
        const Slice& slice = set.slices[i];
        if (!box.empty) drawRegion(cr, slice.region, ox + (cellW - shapeW) / 2, oy, box);
        cairo_set_source_rgb(cr, 0, 0, 0.7);
        cairo_move_to(cr, ox, oy + cellH - kLabel + kFont + 0.5);
        cairo_show_text(cr, labelOf(slice, i).c_str());
      }
    });
  });
}

}  // namespace sliceform
