// SPDX-License-Identifier: LGPL-2.1-or-later
#include "output/sheets_cairo.hpp"

#include "output/cairo_file.hpp"

#include <cairo-pdf.h>
#include <cairo-svg.h>
#include <cairo.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <map>
#include <memory>
#include <string>

#include "layout/labels.hpp"
#include "output/png_file.hpp"
#include "support/atomic_file.hpp"
#include "support/error.hpp"

namespace sliceform {
namespace {

constexpr double kPointsPerMm = 72 / 25.4;
constexpr double kLineWidth = 0.1;  // mm: thin enough for laser software to read as a path

void path(cairo_t* cr, const CutLoop& loop) {
  for (size_t i = 0; i < loop.size(); ++i) {
    const CutElement& e = loop[i];
    if (i == 0 && e.kind != CutElement::Kind::Circle) cairo_move_to(cr, e.a.x, e.a.y);
    switch (e.kind) {
      case CutElement::Kind::Line:
        cairo_line_to(cr, e.b.x, e.b.y);
        break;
      case CutElement::Kind::Arc:
        (e.ccw ? cairo_arc : cairo_arc_negative)(cr, e.centre.x, e.centre.y, e.radius, e.start, e.end);
        break;
      case CutElement::Kind::Circle:
        cairo_new_sub_path(cr);
        cairo_arc(cr, e.centre.x, e.centre.y, e.radius, 0, 2 * M_PI);
        break;
    }
  }
  cairo_close_path(cr);
}

void strokes(cairo_t* cr, const std::vector<Stroke>& lines) {
  for (const Stroke& s : lines) {
    if (s.empty()) continue;
    cairo_move_to(cr, s.front().x, s.front().y);
    for (size_t i = 1; i < s.size(); ++i) cairo_line_to(cr, s[i].x, s[i].y);
  }
}

// Draws a sheet in mm with y up; the caller has set the scale of the device.
void drawSheet(cairo_t* cr, const SheetDrawing& sheet, const SheetSpec& spec, double scale) {
  cairo_save(cr);
  cairo_scale(cr, scale, -scale);
  cairo_translate(cr, 0, -spec.height);
  cairo_set_line_width(cr, kLineWidth);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  // Each loop its own path, so an SVG reader sees one closed path per outline, hole or slot.
  cairo_set_source_rgb(cr, 1, 0, 0);
  for (const CutLoop& loop : sheet.cut) {
    path(cr, loop);
    cairo_stroke(cr);
  }
  cairo_set_source_rgb(cr, 0, 0, 1);
  strokes(cr, sheet.engrave);
  cairo_stroke(cr);
  cairo_restore(cr);
}

// A 50 mm bar with end ticks and its length, in the bottom margin, plus the page number:
// printed only (the PDF), so a maker can check the printer kept 100 %.
void drawScaleMark(cairo_t* cr, const SheetSpec& spec, int page, int pages) {
  if (spec.margin < 6) return;  // no room below the patches
  const double y = spec.margin / 2, x = spec.margin, h = std::min(2.5, spec.margin / 3);
  Label length = setLabel("50 mm", {x + 25, y + h}, h, false);
  Label number = setLabel(std::to_string(page) + "/" + std::to_string(pages),
                          {spec.width - spec.margin - labelWidth("99/99", h) / 2, y}, h, false);
  std::vector<Stroke> marks = {
      {{x, y}, {x + 50, y}}, {{x, y - 1.5}, {x, y + 1.5}}, {{x + 50, y - 1.5}, {x + 50, y + 1.5}}};
  marks.insert(marks.end(), length.strokes.begin(), length.strokes.end());
  marks.insert(marks.end(), number.strokes.begin(), number.strokes.end());
  cairo_save(cr);
  cairo_scale(cr, kPointsPerMm, -kPointsPerMm);
  cairo_translate(cr, 0, -spec.height);
  cairo_set_line_width(cr, 0.2);
  cairo_set_source_rgb(cr, 0.3, 0.3, 0.3);
  strokes(cr, marks);
  cairo_stroke(cr);
  cairo_restore(cr);
}

}  // namespace

void writeSheetsPdf(const std::vector<SheetDrawing>& sheets, const SheetSpec& spec, const std::string& path) {
  writeAtomically(path, [&](const std::string& temporary) {
    cairo_surface_t* surface =
        cairo_pdf_surface_create(temporary.c_str(), spec.width * kPointsPerMm, spec.height * kPointsPerMm);
    checkSurface(surface, path);
    cairo_pdf_surface_set_metadata(surface, CAIRO_PDF_METADATA_CREATOR, "Sliceform");
    drawAndFinish(surface, path, [&](cairo_t* cr) {
      for (size_t i = 0; i < sheets.size(); ++i) {
        drawSheet(cr, sheets[i], spec, kPointsPerMm);
        drawScaleMark(cr, spec, static_cast<int>(i) + 1, static_cast<int>(sheets.size()));
        cairo_show_page(cr);
      }
    });
  });
}

namespace {

// cairo's surface ids in an SVG ("surface21"), renumbered from 1 in order of appearance.
std::string numberedSurfacesFromOne(const std::string& svg) {
  std::string out;
  out.reserve(svg.size());
  std::map<std::string, std::string> renamed;
  const std::string word = "surface";
  size_t from = 0;
  for (size_t at = svg.find(word); at != std::string::npos; at = svg.find(word, from)) {
    size_t end = at + word.size();
    while (end < svg.size() && std::isdigit(static_cast<unsigned char>(svg[end]))) ++end;
    out.append(svg, from, end - from);
    if (end > at + word.size()) {
      const std::string number = svg.substr(at + word.size(), end - at - word.size());
      const auto [it, added] = renamed.emplace(number, std::to_string(renamed.size() + 1));
      out.resize(out.size() - number.size());
      out += it->second;
    }
    from = end;
  }
  out.append(svg, from, std::string::npos);
  return out;
}

}  // namespace

void writeSheetSvg(const SheetDrawing& sheet, const SheetSpec& spec, const std::string& path) {
  // cairo names an SVG's surfaces by a counter shared by every surface the process makes,
  // so the bytes of a sheet would depend on what else was drawn, and in which order; the
  // files are drawn beside others (the booklet, the PDF): drawn into memory, the surfaces
  // renumbered from 1, then written.
  std::string svg;
  const auto append = [](void* into, const unsigned char* data, unsigned int length) {
    static_cast<std::string*>(into)->append(reinterpret_cast<const char*>(data), length);
    return CAIRO_STATUS_SUCCESS;
  };
  // With the document unit set to mm, cairo writes width="…mm" and a viewBox in the
  // surface's own units, which we make millimetres: one user unit is one mm.
  cairo_surface_t* surface = cairo_svg_surface_create_for_stream(append, &svg, spec.width, spec.height);
  checkSurface(surface, path);
  cairo_svg_surface_set_document_unit(surface, CAIRO_SVG_UNIT_MM);
  drawAndFinish(surface, path, [&](cairo_t* cr) { drawSheet(cr, sheet, spec, 1); });
  svg = numberedSurfacesFromOne(svg);
  writeAtomically(path, [&](const std::string& temporary) {
    std::ofstream file(temporary, std::ios::binary);
    file.write(svg.data(), static_cast<std::streamsize>(svg.size()));
    if (!file.flush()) throw Error(ErrorKind::Io, "cannot write " + path);
  });
}

void writeSheetsPng(const std::vector<SheetDrawing>& sheets, const SheetSpec& spec, const std::string& path,
                    double pixelsPerMm) {
  // Up to four sheets a row on a grey ground, each white with its margin shown faintly.
  const int perRow = std::max(1, std::min(4, static_cast<int>(sheets.size())));
  const int rows = (static_cast<int>(sheets.size()) + perRow - 1) / perRow;
  const double gap = 10;
  const int width = static_cast<int>(std::ceil((perRow * (spec.width + gap) + gap) * pixelsPerMm));
  const int height =
      static_cast<int>(std::ceil((std::max(rows, 1) * (spec.height + gap) + gap) * pixelsPerMm));
  writeAtomically(path, [&](const std::string& temporary) {
    // Memory of our own, not cairo's: cairo zeroes a surface it makes (a pass over 22 MB on
    // occ/Top.brep's 17 sheets), and the grey ground below covers every pixel anyway.
    const int stride = cairo_format_stride_for_width(CAIRO_FORMAT_RGB24, width);
    const std::unique_ptr<unsigned char[]> pixels(new unsigned char[static_cast<size_t>(stride) * height]);
    const std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)> surface(
        cairo_image_surface_create_for_data(pixels.get(), CAIRO_FORMAT_RGB24, width, height, stride),
        cairo_surface_destroy);
    checkSurface(surface.get(), path);
    cairo_t* cr = cairo_create(surface.get());
    cairo_set_source_rgb(cr, 0.85, 0.85, 0.85);
    cairo_paint(cr);
    for (size_t i = 0; i < sheets.size(); ++i) {
      const double x = gap + (i % perRow) * (spec.width + gap), y = gap + (i / perRow) * (spec.height + gap);
      cairo_save(cr);
      cairo_scale(cr, pixelsPerMm, pixelsPerMm);
      cairo_translate(cr, x, y);
      cairo_rectangle(cr, 0, 0, spec.width, spec.height);
      cairo_set_source_rgb(cr, 1, 1, 1);
      cairo_fill(cr);
      cairo_rectangle(cr, spec.margin, spec.margin, spec.width - 2 * spec.margin,
                      spec.height - 2 * spec.margin);
      cairo_set_source_rgb(cr, 0.9, 0.9, 0.95);
      cairo_set_line_width(cr, 0.3);
      cairo_stroke(cr);
      cairo_scale(cr, 1 / pixelsPerMm, 1 / pixelsPerMm);
      drawSheet(cr, sheets[i], spec, pixelsPerMm);
      cairo_restore(cr);
    }
    cairo_destroy(cr);
    cairo_surface_flush(surface.get());
    // RGB24: a pixel is a native uint32, 0x00RRGGBB.
    writeRgbPng(temporary, reinterpret_cast<const uint32_t*>(pixels.get()), width, height,
                static_cast<size_t>(stride) / 4);
  });
}

}  // namespace sliceform
