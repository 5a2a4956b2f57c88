// SPDX-License-Identifier: LGPL-2.1-or-later
#include "output/instructions.hpp"

#include <cairo-pdf.h>
#include <cairo.h>

#include <algorithm>
#include <memory>

#include "output/cairo_file.hpp"
#include "support/atomic_file.hpp"
#include "support/error.hpp"

namespace sliceform {
namespace {

constexpr double kPointsPerMm = 72 / 25.4;
constexpr double kPageW = 210, kPageH = 297, kMargin = 15;  // A4 portrait, mm
constexpr int kColumns = 2;
constexpr int kPictureWidth = 280;  // pixels of a step picture: 80 mm at about 90 dpi

using Surface = std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)>;

std::string joined(const std::vector<std::string>& ids) {
  std::string out;
  for (const std::string& id : ids) out += (out.empty() ? "" : ", ") + id;
  return out;
}

// A picture on the page, fitted into w x h mm with its top-left at (x, y).
void drawPicture(cairo_t* cr, const Picture& p, double x, double y, double w, double h) {
  const Surface image(cairo_image_surface_create(CAIRO_FORMAT_RGB24, p.width, p.height),
                      cairo_surface_destroy);
  cairo_surface_flush(image.get());
  unsigned char* data = cairo_image_surface_get_data(image.get());
  const int stride = cairo_image_surface_get_stride(image.get());
  for (int row = 0; row < p.height; ++row)
    std::copy_n(p.pixels.begin() + size_t(row) * p.width, p.width,
                reinterpret_cast<uint32_t*>(data + size_t(row) * stride));
  cairo_surface_mark_dirty(image.get());
  const double scale = std::min(w / p.width, h / p.height);
  cairo_save(cr);
  cairo_translate(cr, x + (w - p.width * scale) / 2, y);
  cairo_scale(cr, scale, scale);
  cairo_set_source_surface(cr, image.get(), 0, 0);
  cairo_paint(cr);
  cairo_restore(cr);
}

// Text at (x, y) mm (baseline), `size` mm high; returns the next line's baseline. Lines
// longer than `width` mm are broken at spaces.
double text(cairo_t* cr, const std::string& s, double x, double y, double size, double width,
            bool bold = false) {
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL,
                         bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, size);
  cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
  std::string line;
  const auto flush = [&] {
    cairo_move_to(cr, x, y);
    cairo_show_text(cr, line.c_str());
    y += size * 1.35;
    line.clear();
  };
  size_t at = 0;
  while (at < s.size()) {
    size_t next = s.find(' ', at);
    if (next == std::string::npos) next = s.size();
    const std::string word = s.substr(at, next - at);
    const std::string tried = line.empty() ? word : line + " " + word;
    cairo_text_extents_t e;
    cairo_text_extents(cr, tried.c_str(), &e);
    if (e.x_advance > width && !line.empty()) {
      flush();
      line = word;
    } else {
      line = tried;
    }
    at = next + 1;
  }
  if (!line.empty()) flush();
  return y;
}

void cover(cairo_t* cr, const Design& d, const std::vector<Panel3>& panels, const std::string& title) {
  const double width = kPageW - 2 * kMargin;
  double y = text(cr, "Sliceform: " + title, kMargin, kMargin + 8, 8, width, true);
  const Picture whole = drawAssembly(panels, 900);
  const double h = std::min(130.0, width * whole.height / whole.width);
  drawPicture(cr, whole, kMargin, y, width, h);
  y += h + 8;
  const Scaffold& s = d.arrangement.scaffold;
  int u = 0;
  for (const ScaffoldPatch& p : s.patches) u += p.family == Family::U ? 1 : 0;
  const SheetLayout& l = d.layout;
  y = text(cr,
           std::to_string(s.patches.size()) + " patches (" + std::to_string(u) + " U, " +
               std::to_string(s.patches.size() - u) + " V) on " + std::to_string(l.packing.sheets) + " " +
               l.sheet.name + " sheet(s), in " + std::to_string(assemblySteps(d).size()) + " steps.",
           kMargin, y, 4, width);
  y = text(cr, "Parts by sheet", kMargin, y + 3, 4.5, width, true);
  for (int sheet = 0; sheet < l.packing.sheets; ++sheet) {
    std::vector<std::string> ids;
    for (size_t k = 0; k < l.patches.size(); ++k)
      if (l.packing.placements[k].sheet == sheet) ids.push_back(l.patches[k].id);
    y = text(cr, "Sheet " + std::to_string(sheet + 1) + ": " + joined(ids), kMargin, y, 3.5, width);
  }
  y = text(cr, "Tools", kMargin, y + 3, 4.5, width, true);
  y = text(cr,
           "A laser cutter, or a sharp knife, a steel ruler and a cutting mat. No glue: the slots hold it. "
           "Cut along the red lines; the blue ids are engraved or drawn, not cut.",
           kMargin, y, 3.5, width);
  y = text(cr, "How", kMargin, y + 3, 4.5, width, true);
  text(
      cr,
      "Cut every patch first and keep the ids readable; the number engraved beside each id (#5) is its "
      "step. Then follow the steps: each adds one patch, orange "
      "in its picture. Its slots open at the top or at the bottom; slide it on so each slot meets the named "
      "partner's slot, until the slots' ends touch. Check the ids at each slot (the partner's id is engraved "
      "beside it) before you push.",
      kMargin, y, 3.5, width);
}

}  // namespace

std::vector<AssemblyStep> assemblySteps(const Design& d) {
  const Scaffold& s = d.arrangement.scaffold;
  const std::vector<int>& order = d.realization.assemblyOrder;
  std::vector<bool> placed(s.patches.size(), false);
  std::vector<AssemblyStep> steps;
  for (const int k : order) {
    AssemblyStep step;
    step.patch = k;
    step.id = patchId(s, k);
    for (size_t h = 0; h < s.hinges.size(); ++h) {
      const ScaffoldHinge& hinge = s.hinges[h];
      if (!d.emitted.meets[h] || (hinge.u != k && hinge.v != k)) continue;
      const int partner = hinge.u == k ? hinge.v : hinge.u;
      if (!placed[partner]) continue;
      const Slot mine = hinge.u == k ? uSlot(d.realization.slots[h]) : vSlot(d.realization.slots[h]);
      const std::string id = patchId(s, partner);
      auto& into = mine == Slot::Up        ? step.fromTop
                   : mine == Slot::Down    ? step.fromBottom
                   : mine == Slot::Through ? step.through
                                           : step.partnerCuts;
      if (std::find(into.begin(), into.end(), id) == into.end()) into.push_back(id);
    }
    placed[k] = true;
    steps.push_back(std::move(step));
  }
  return steps;
}

void writeInstructionsPdf(const Design& d, const std::vector<Panel3>& panels, const std::string& title,
                          const std::string& path) {
  const std::vector<AssemblyStep> steps = assemblySteps(d);
  std::vector<int> panelOf(d.patches.size(), -1);
  for (size_t i = 0; i < panels.size(); ++i)
    if (panels[i].patch >= 0) panelOf[panels[i].patch] = static_cast<int>(i);
  writeAtomically(path, [&](const std::string& temporary) {
    cairo_surface_t* surface =
        cairo_pdf_surface_create(temporary.c_str(), kPageW * kPointsPerMm, kPageH * kPointsPerMm);
    cairo_pdf_surface_set_metadata(surface, CAIRO_PDF_METADATA_CREATOR, "Sliceform");
    cairo_pdf_surface_set_metadata(surface, CAIRO_PDF_METADATA_TITLE, ("Assembling " + title).c_str());
    drawAndFinish(surface, path, [&](cairo_t* cr) {
      cairo_scale(cr, kPointsPerMm, kPointsPerMm);  // millimetres, y down
      cover(cr, d, panels, title);
      cairo_show_page(cr);
      const double cellW = (kPageW - 2 * kMargin) / kColumns;
      const double cellH = (kPageH - 2 * kMargin) / (kStepsPerPage / kColumns);
      GrowingAssembly pictures(panels, kPictureWidth);
      for (size_t i = 0; i < steps.size(); ++i) {
        const AssemblyStep& step = steps[i];
        const int slot = static_cast<int>(i % kStepsPerPage);
        const double x = kMargin + (slot % kColumns) * cellW, y = kMargin + (slot / kColumns) * cellH;
        double line =
            text(cr, "Step " + std::to_string(i + 1) + ": " + step.id, x, y + 5, 4.5, cellW - 4, true);
        std::string how;
        if (i == 0) how = "Hold it upright; the next patches slide onto it.";
        if (!step.fromTop.empty()) how += "Slots opening at the top onto " + joined(step.fromTop) + ". ";
        if (!step.fromBottom.empty())
          how += "Slots opening at the bottom onto " + joined(step.fromBottom) + ". ";
        if (!step.through.empty()) how += "Slots through, onto " + joined(step.through) + ". ";
        if (!step.partnerCuts.empty()) how += "Uncut where " + joined(step.partnerCuts) + " is cut through. ";
        line = text(cr, how, x, line, 3, cellW - 4);
        const int p = step.patch >= 0 ? panelOf[step.patch] : -1;
        if (p >= 0) drawPicture(cr, pictures.add(p), x, line, cellW - 4, y + cellH - line - 3);
        if (slot == kStepsPerPage - 1 || i + 1 == steps.size()) cairo_show_page(cr);
      }
    });
  });
}

}  // namespace sliceform
